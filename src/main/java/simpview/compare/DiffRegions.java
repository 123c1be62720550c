package simpview.compare;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

/**
 * The patches of pixels that differ beyond a tolerance even with slack,
 * found as 8-connected components by a flood fill over one explicit stack.
 */
public final class DiffRegions {

    private DiffRegions() {
    }

    /** All patches counted, and the largest few. */
    public record Found(int count, int pixels, List<DiffRegion> largest) {
    }

    public static Found of(Comparison comparison, int tolerance, int keep) {
        int n = comparison.size();
        boolean[] seen = new boolean[n * n];
        int[] stack = new int[n * n];
        List<DiffRegion> largest = new ArrayList<>();
        int count = 0;
        int pixels = 0;
        for (int i = 0; i < n * n; i++) {
            if (!seen[i] && comparison.fails(i, tolerance)) {
                DiffRegion region = fill(comparison, tolerance, i, seen, stack);
                count++;
                pixels += region.pixels();
                keepLargest(largest, region, keep);
            }
        }
        return new Found(count, pixels, List.copyOf(largest));
    }

    private static void keepLargest(List<DiffRegion> largest, DiffRegion region, int keep) {
        largest.add(region);
        largest.sort(Comparator.comparingInt(DiffRegion::pixels).reversed());
        if (largest.size() > keep) {
            largest.remove(largest.size() - 1);
        }
    }

    /** Floods the patch holding pixel {@code start}; returns its bounds in panel coordinates (y up). */
    private static DiffRegion fill(Comparison comparison, int tolerance, int start, boolean[] seen, int[] stack) {
        int n = comparison.size();
        int size = 0;
        int pixels = 0;
        int minX = n;
        int maxX = -1;
        int minRow = n;
        int maxRow = -1;
        stack[size++] = start;
        seen[start] = true;
        while (size > 0) {
            int i = stack[--size];
            int x = i % n;
            int row = i / n;
            pixels++;
            minX = Math.min(minX, x);
            maxX = Math.max(maxX, x);
            minRow = Math.min(minRow, row);
            maxRow = Math.max(maxRow, row);
            for (int r = Math.max(0, row - 1); r <= Math.min(n - 1, row + 1); r++) {
                for (int c = Math.max(0, x - 1); c <= Math.min(n - 1, x + 1); c++) {
                    int j = r * n + c;
                    if (!seen[j] && comparison.fails(j, tolerance)) {
                        seen[j] = true;
                        stack[size++] = j;
                    }
                }
            }
        }
        return new DiffRegion(minX, n - 1 - maxRow, maxX, n - 1 - minRow, pixels);
    }
}
