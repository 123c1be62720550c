#!/bin/sh
# simpview against Mesa's llvmpipe on the same course pages, page by page:
# LlvmpipeExport writes the page's triangles, times simpview's warm redraws
# on 1 thread, then on 2 threads taking turns with llvmpipe's redraws of
# those triangles (draw.py, which it starts), so that both see the host's
# cores as they are then; then the table of both, with the load average
# before and after. Run setup.sh once first.
# Usage: bench/llvmpipe/run.sh [COURSE_DIR] [page ...]   (COURSE_DIR holds course-simp, course-simp-a3 and -a4;
# pages as a2/page7, a3/pageF, a4/page-d)
set -e
here=$(cd "$(dirname "$0")" && pwd)
root="$here/../.."
course=$(cd "${1:-$root/../shared}" && pwd) # absolute: the JVMs below run in $root
[ $# -gt 0 ] && shift
# By default every course page: A2's eight, A3's ten and A4's fifteen.
pages=${*:-"a2/page1 a2/page2 a2/page3 a2/page4 a2/page5 a2/page6 a2/page7 a2/page8
 a3/pageA a3/pageB a3/pageC a3/pageD a3/pageE a3/pageF a3/pageG a3/pageH a3/pageI a3/tomsPageJ
 a4/page-a1 a4/page-a2 a4/page-a3 a4/page-b1 a4/page-b2 a4/page-b3 a4/page-c1 a4/page-c2 a4/page-c3
 a4/page-d a4/page-e a4/page-f1 a4/page-f2 a4/page-g a4/page-h"}
python="$root/build/llvmpipe-venv/bin/python"
if [ ! -x "$python" ]; then
    echo "run.sh: no $python: run bench/llvmpipe/setup.sh first" >&2
    exit 2
fi
out="$root/build/llvmpipe"
mkdir -p "$out"
(cd "$root" && gradle --no-daemon -q jmhClasses drawingJvmOptions)
cp="$root/build/classes/java/main:$root/build/classes/java/jmh:$root/build/resources/main"
: > "$out/times.txt"
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
# The JVM options simpview's start scripts give it (build.gradle's drawingJvmArgs,
# written out by its drawingJvmOptions task).
jvm=$(cat "$root/build/drawing-jvm-options.txt")
cd "$root" # A2's pages 4 and 5 are the project's own scenes, in simp/
for p in $pages; do
    java $jvm -cp "$cp" simpview.bench.LlvmpipeExport "$course" "$out" "$python" \
        "$here/draw.py" "$p" >> "$out/times.txt"
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
python3 "$here/table.py" "$out/times.txt"
