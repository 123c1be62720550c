"""Joins simpview's and llvmpipe's timings of one run into a markdown table."""
import sys

ours = {}
for line in open(sys.argv[1]):
    page, m1, b1, m2, b2, triangles, lines, skipped = line.split()
    ours[page.replace("/", "-")] = (page, float(m1), float(b1), float(m2), float(b2), int(triangles), int(lines),
                                    int(skipped))
print("| page | triangles | lines | simpview, 1 thread | simpview, 2 threads | llvmpipe | llvmpipe / simpview (2 threads) |")
print("|---|---:|---:|---:|---:|---:|---:|")
for line in open(sys.argv[2]):
    name, median, best = line.split()
    page, m1, b1, m2, b2, triangles, lines, skipped = ours[name]
    note = "" if skipped == 0 else " (+%d primitives drawn by simpview only)" % skipped
    print("| %s | %d%s | %d | %.2f ms (best %.2f) | %.2f ms (best %.2f) | %.2f ms (best %.2f) | %.2f |" % (
        page, triangles, note, lines, m1, b1, m2, b2, float(median), float(best), float(median) / m2))
