#!/bin/sh
# simpview against Mesa's llvmpipe on the same lit course pages, in one run:
# simpview's warm redraws on 1 and 2 threads (LlvmpipeExport, which also
# writes the pages' triangles), then llvmpipe's warm redraws of those
# triangles (draw.py), then the table of both. Run setup.sh once first.
# Usage: bench/llvmpipe/run.sh [COURSE_DIR] [page ...]   (COURSE_DIR holds course-simp-a3 and -a4)
set -e
here=$(cd "$(dirname "$0")" && pwd)
root="$here/../.."
course=${1:-$root/../shared}
[ $# -gt 0 ] && shift
pages=${*:-"a3/pageA a3/pageC a3/pageE a3/pageF a3/pageG a3/pageH a3/pageI a3/tomsPageJ a4/page-d a4/page-e a4/page-f2 a4/page-h"}
out="$root/build/llvmpipe"
mkdir -p "$out"
(cd "$root" && gradle --no-daemon -q jmhClasses)
cp="$root/build/classes/java/main:$root/build/classes/java/jmh:$root/build/resources/main"
java -cp "$cp" simpview.bench.LlvmpipeExport "$course" "$out" $pages > "$out/simpview.txt"
names=$(for p in $pages; do printf '%s ' "$(echo "$p" | tr / -)"; done)
"$root/build/llvmpipe-venv/bin/python" "$here/draw.py" "$out" $names > "$out/llvmpipe.txt"
python3 "$here/table.py" "$out/simpview.txt" "$out/llvmpipe.txt"
