package simpview.surface;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.TreeSet;
import java.util.function.Function;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import simpview.testing.RecordingDrawable;

/**
 * {@link DrawableDecorator}'s rule, held by a test: a decorator that passes
 * {@code setRun} on whole (instead of the default, {@code setPixel} pixel by
 * pixel through itself) must mean by it exactly what its {@code setPixel}
 * means. Every decorator of the main sources that does is listed here, or
 * this test fails; each is checked on random runs against the same pixels
 * written one by one.
 */
class RunMeansPixelsTest {

    private static final int SIZE = 64;

    /** A decorator's writes on a fresh recorder, and what else it changes (the owners it records). */
    private record Chain(Drawable drawable, RecordingDrawable under, Provenance owners) {
    }

    /** Every decorator that passes runs on, made over a fresh recorder. */
    private static final Map<String, Function<RecordingDrawable, Chain>> PASSING_RUNS_ON = Map.of(
            "PanelDrawable", under -> new Chain(new PanelDrawable(under, 3, 5, SIZE - 10), under, null),
            "ProvenanceDrawable", under -> {
                Provenance owners = new Provenance(SIZE, SIZE);
                owners.begin(7);
                return new Chain(new ProvenanceDrawable(owners, under), under, owners);
            },
            "RowBandDrawable", under -> new Chain(new RowBandDrawable(10, 40, under), under, null));

    @Test
    void everyDecoratorThatPassesRunsOnIsCheckedHere() throws IOException {
        TreeSet<String> found = new TreeSet<>();
        try (Stream<Path> files = Files.walk(Path.of("src/main/java"))) {
            for (Path file : files.filter(f -> f.toString().endsWith(".java")).toList()) {
                String text = Files.readString(file);
                if (text.contains("extends DrawableDecorator") && text.contains("public void setRun(")) {
                    found.add(file.getFileName().toString().replace(".java", ""));
                }
            }
        }
        assertEquals(new TreeSet<>(PASSING_RUNS_ON.keySet()), found,
                "a decorator that passes setRun on must mean what its setPixel means: list it here to be checked");
    }

    @Test
    void aRunIsItsPixelsOneByOne() {
        Random random = new Random(19);
        for (var entry : PASSING_RUNS_ON.entrySet()) {
            for (int trial = 0; trial < 200; trial++) {
                int count = 1 + random.nextInt(80);
                int at = random.nextInt(5);
                int x = random.nextInt(SIZE + 20) - 10;
                int y = random.nextInt(SIZE + 20) - 10;
                double[] depths = new double[at + count];
                int[] colours = new int[at + count];
                for (int i = 0; i < at + count; i++) {
                    depths[i] = -200 * random.nextDouble();
                    colours[i] = 0xFF000000 | random.nextInt(1 << 24);
                }
                Chain run = entry.getValue().apply(new RecordingDrawable(SIZE, SIZE));
                Chain pixels = entry.getValue().apply(new RecordingDrawable(SIZE, SIZE));
                run.drawable().setRun(x, y, count, depths, colours, at);
                for (int i = 0; i < count; i++) {
                    pixels.drawable().setPixel(x + i, y, depths[at + i], colours[at + i]);
                }
                String what = entry.getKey() + ", trial " + trial;
                assertEquals(writes(pixels.under()), writes(run.under()), what);
                if (run.owners() != null) {
                    assertArrayEquals(pixels.owners().copyOwners(), run.owners().copyOwners(), what);
                }
            }
        }
    }

    private static List<RecordingDrawable.Write> writes(RecordingDrawable d) {
        return new ArrayList<>(d.writes());
    }
}
