package simpview.reference;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.regex.Pattern;

/**
 * The .obj subset of SPEC, read the plain way: `v x y z [w] [r g b]`,
 * `vn x y z`, `f` with `v`, `v/vt`, `v//vn`, `v/vt/vn` references (1-based,
 * negative counting back from the last defined); any other line ignored.
 *
 * @param positions the points, already divided by w
 * @param colours   each vertex's own colour, or null
 * @param faces     each face as rows {vertex index, normal index or -1}, 0-based
 */
record RefObj(List<double[]> positions, List<double[]> colours, List<double[]> normals, List<int[][]> faces) {

    /** Blanks, commas and parentheses separate, as in simp lines. */
    static final Pattern SEPARATORS = Pattern.compile("[\\s,()]+");

    static RefObj read(Path file) throws IOException {
        RefObj obj = new RefObj(new ArrayList<>(), new ArrayList<>(), new ArrayList<>(), new ArrayList<>());
        int lineNumber = 0;
        for (String raw : Files.readAllLines(file)) {
            lineNumber++;
            String line = raw.strip();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            String[] tokens = SEPARATORS.split(line);
            String where = file + ":" + lineNumber + ": ";
            switch (tokens[0].toLowerCase(Locale.ROOT)) {
                case "v" -> obj.vertex(numbers(tokens, where), where);
                case "vn" -> obj.normal(numbers(tokens, where), where);
                case "f" -> obj.face(tokens, where);
                default -> { }
            }
        }
        return obj;
    }

    private static double[] numbers(String[] tokens, String where) {
        double[] n = new double[tokens.length - 1];
        for (int i = 1; i < tokens.length; i++) {
            try {
                n[i - 1] = Double.parseDouble(tokens[i]);
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException(where + "not a number: " + tokens[i], e);
            }
        }
        return n;
    }

    private void vertex(double[] n, String where) {
        double w = n.length == 4 || n.length == 7 ? n[3] : 1;
        if (n.length != 3 && n.length != 4 && n.length != 6 && n.length != 7 || w == 0) {
            throw new IllegalArgumentException(where + "a vertex takes x y z [w] [r g b] with w != 0");
        }
        positions.add(new double[] {n[0] / w, n[1] / w, n[2] / w});
        if (n.length >= 6) {
            int c = n.length - 3;
            colours.add(new double[] {clamp(n[c]), clamp(n[c + 1]), clamp(n[c + 2])});
        } else {
            colours.add(null);
        }
    }

    private static double clamp(double c) {
        return Math.max(0, Math.min(1, c));
    }

    private void normal(double[] n, String where) {
        if (n.length != 3) {
            throw new IllegalArgumentException(where + "a normal takes x y z");
        }
        normals.add(n);
    }

    private void face(String[] tokens, String where) {
        if (tokens.length < 4) {
            throw new IllegalArgumentException(where + "a face takes three or more vertices");
        }
        int[][] face = new int[tokens.length - 1][];
        for (int i = 1; i < tokens.length; i++) {
            String[] parts = tokens[i].split("/", -1);
            int v = index(parts[0], positions.size(), where);
            int vn = parts.length == 3 && !parts[2].isEmpty() ? index(parts[2], normals.size(), where) : -1;
            face[i - 1] = new int[] {v, vn};
        }
        faces.add(face);
    }

    /** 1-based or negative (from the end) to 0-based, checked against what is defined so far. */
    private static int index(String text, int defined, String where) {
        int i = Integer.parseInt(text);
        int zeroBased = i < 0 ? defined + i : i - 1;
        if (i == 0 || zeroBased < 0 || zeroBased >= defined) {
            throw new IllegalArgumentException(where + "index " + i + " with " + defined + " defined");
        }
        return zeroBased;
    }
}
