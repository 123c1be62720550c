"""The markdown table of one run's timings (LlvmpipeExport's lines: simpview's and llvmpipe's)."""
import sys

print("| page | triangles | lines | simpview, 1 thread | simpview, 2 threads | llvmpipe | llvmpipe / simpview (2 threads) |")
print("|---|---:|---:|---:|---:|---:|---:|")
for line in open(sys.argv[1]):
    page, m1, b1, m2, b2, theirs, their_best, triangles, lines, skipped = line.split()
    note = "" if int(skipped) == 0 else " (+%s primitives drawn by simpview only)" % skipped
    print("| %s | %s%s | %s | %.2f ms (best %.2f) | %.2f ms (best %.2f) | %.2f ms (best %.2f) | %.2f |" % (
        page, triangles, note, lines, float(m1), float(b1), float(m2), float(b2), float(theirs),
        float(their_best), float(theirs) / float(m2)))
