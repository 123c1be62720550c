package simpview.build;

import java.util.Arrays;

/** A Gradle version such as 4.4.1 or 6.4, compared number by number. */
record GradleVersionNumber(int[] parts) implements Comparable<GradleVersionNumber> {

    static GradleVersionNumber of(String text) {
        return new GradleVersionNumber(Arrays.stream(text.split("\\.")).mapToInt(Integer::parseInt).toArray());
    }

    @Override
    public int compareTo(GradleVersionNumber other) {
        for (int i = 0; i < Math.max(parts.length, other.parts.length); i++) {
            int a = i < parts.length ? parts[i] : 0;
            int b = i < other.parts.length ? other.parts[i] : 0;
            if (a != b) {
                return Integer.compare(a, b);
            }
        }
        return 0;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof GradleVersionNumber v && compareTo(v) == 0;
    }

    @Override
    public int hashCode() {
        return Arrays.hashCode(parts);
    }

    @Override
    public String toString() {
        return String.join(".", Arrays.stream(parts).mapToObj(Integer::toString).toList());
    }
}
