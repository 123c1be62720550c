"""Joins simpview's and llvmpipe's timings of one run into a markdown table."""
import sys

ours = {}
for line in open(sys.argv[1]):
    page, m1, b1, m2, b2, triangles, skipped = line.split()
    ours[page.replace("/", "-")] = (page, float(m1), float(b1), float(m2), float(b2), int(triangles), int(skipped))
print("| page | triangles | simpview, 1 thread | simpview, 2 threads | llvmpipe | llvmpipe / simpview (2 threads) |")
print("|---|---:|---:|---:|---:|---:|")
for line in open(sys.argv[2]):
    name, median, best = line.split()
    page, m1, b1, m2, b2, triangles, skipped = ours[name]
    note = "" if skipped == 0 else " (+%d lines or outlines, drawn by simpview only)" % skipped
    print("| %s | %d%s | %.2f ms (best %.2f) | %.2f ms (best %.2f) | %.2f ms (best %.2f) | %.2f |" % (
        page, triangles, note, m1, b1, m2, b2, float(median), float(best), float(median) / m2))
