package simpview.inspect;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Random;

/**
 * Random depth-cued scenes for the inspector's tests: a top file that
 * includes a middle one that includes a leaf (three deep), with lines,
 * filled and wire triangles, vertex colours, transforms, and primitives
 * through the near plane, beyond the far one, and wholly outside the view
 * (culled). Every scene is valid by SPEC.
 */
final class RandomCuedScenes {

    private final Random random;
    /** Whether the primitive being written gives its vertices colours (all or none). */
    private boolean coloured;

    private RandomCuedScenes(long seed) {
        random = new Random(seed);
    }

    /** Writes cuedN.simp, cuedmidN.simp and cuedleafN.simp into dir; returns the top file. */
    static Path write(Path dir, long seed) throws IOException {
        RandomCuedScenes r = new RandomCuedScenes(seed);
        Files.writeString(dir.resolve("cuedleaf" + seed + ".simp"), r.primitives(25));
        Files.writeString(dir.resolve("cuedmid" + seed + ".simp"),
                "{\nrotate Z " + r.f(r.uniform(-40, 40)) + "\nfile \"cuedleaf" + seed + "\"\n}\n" + r.primitives(10)
                        + "file cuedleaf" + seed + "\n");
        Path top = dir.resolve("cued" + seed + ".simp");
        Files.writeString(top, "# random depth-cued scene " + seed + "\n" + r.primitives(15)
                + "{\ntranslate " + r.f(r.uniform(-20, 20)) + " " + r.f(r.uniform(-20, 20)) + " 0\nfile \"cuedmid"
                + seed + "\"\n}\n" + r.primitives(10));
        return top;
    }

    private String primitives(int count) {
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < count; i++) {
            double pick = random.nextDouble();
            if (pick < 0.1) {
                sb.append(random.nextBoolean() ? "wire\n" : "filled\n");
            }
            coloured = random.nextDouble() < 0.4;
            if (pick < 0.25) {
                sb.append("line ").append(point()).append(' ').append(point()).append('\n');
            } else if (pick < 0.3) {
                // wholly beyond the near plane: culled
                sb.append("polygon (0, 0, 10) (50, 0, 20) (0, 50, 30)\n");
            } else {
                sb.append("polygon ").append(point()).append(' ').append(point()).append(' ').append(point())
                        .append('\n');
            }
        }
        return sb.toString();
    }

    private String point() {
        double z = uniform(-240, 30);
        String xyz = f(uniform(-110, 110)) + ", " + f(uniform(-110, 110)) + ", " + f(z);
        if (coloured) {
            return "(" + xyz + ", " + f(random.nextDouble()) + ", " + f(random.nextDouble()) + ", "
                    + f(random.nextDouble()) + ")";
        }
        return "(" + xyz + ")";
    }

    private double uniform(double lo, double hi) {
        return lo + (hi - lo) * random.nextDouble();
    }

    private String f(double v) {
        return String.format(Locale.ROOT, "%.3f", v);
    }
}
