package simpview.scene.obj;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.statistics.Statistics;
import simpview.scene.SceneException;
import simpview.scene.obj.CollectedFaces.Corner;
import simpview.scene.obj.CollectedFaces.Face;

/**
 * Random models written every way the subset allows (any case, any
 * separators, w, colours, every reference form, negative indices, ignored
 * lines between), against what their making says the faces are; and random
 * damage, which must give a SceneException at a place on the damaged text,
 * never anything else.
 */
class ObjFuzzTest {

    private static final String[] SEPARATORS = {" ", "  ", "\t", ", ", ",", " (", ") ", "(", ")"};
    private static final String[] IGNORED = {"# comment", "g part", "o thing", "s 1", "usemtl m", "mtllib m.mtl",
        "", "   ", "vp 1 2", "vt 0.5 0.5 0"};

    /** A model as it is made: the text, and the faces it must read as. */
    private static final class Maker {
        final Random random;
        final StringBuilder text = new StringBuilder();
        final List<double[]> positions = new ArrayList<>();
        final List<double[]> colours = new ArrayList<>();
        /** The line of the first vertex with a colour channel outside [0, 1], or 0. */
        int firstClampedColour;
        double firstClampedChannel = Double.NaN;
        final List<double[]> normals = new ArrayList<>();
        final List<Face> faces = new ArrayList<>();
        int textures;
        int line;

        Maker(long seed) {
            random = new Random(seed);
        }

        String number(double[] into, int k) {
            String s = switch (random.nextInt(5)) {
                case 0 -> Integer.toString(random.nextInt(2001) - 1000);
                case 1 -> String.format("%.6f", random.nextGaussian() * 50);
                case 2 -> Double.toString(random.nextGaussian());
                case 3 -> (random.nextBoolean() ? "-" : "") + "." + random.nextInt(1000);
                default -> random.nextInt(100) + "e" + (random.nextInt(7) - 3);
            };
            into[k] = Double.parseDouble(s);
            return s;
        }

        String separator() {
            return SEPARATORS[random.nextInt(SEPARATORS.length)];
        }

        String keyword(String k) {
            return random.nextInt(4) == 0 ? k.toUpperCase() : k;
        }

        void emit(String s) {
            text.append(random.nextInt(8) == 0 ? "\t" : "").append(s).append(random.nextInt(6) == 0 ? "\r\n" : "\n");
            line++;
        }

        void vertex() {
            int form = random.nextInt(4); // 3, 4, 6, 7 numbers
            boolean w = form == 1 || form == 3;
            boolean colour = form >= 2;
            double[] n = new double[7];
            StringBuilder s = new StringBuilder(keyword("v"));
            int count = 3 + (w ? 1 : 0) + (colour ? 3 : 0);
            for (int k = 0; k < count; k++) {
                String number = number(n, k);
                while (w && k == 3 && n[3] == 0) {
                    number = number(n, k); // w = 0 is an error, tested elsewhere
                }
                s.append(separator()).append(number);
            }
            double wv = w ? n[3] : 1;
            positions.add(wv == 1 ? new double[] {n[0], n[1], n[2]} : new double[] {n[0] / wv, n[1] / wv, n[2] / wv});
            int c = w ? 4 : 3;
            colours.add(colour ? new double[] {n[c], n[c + 1], n[c + 2]} : null);
            for (int k = c; colour && firstClampedColour == 0 && k < c + 3; k++) {
                if (n[k] < 0 || n[k] > 1) {
                    firstClampedColour = line + 1; // emit counts this line
                    firstClampedChannel = Math.max(n[c], Math.max(n[c + 1], n[c + 2]));
                }
            }
            emit(s.toString());
        }

        void normal() {
            double[] n = new double[3];
            StringBuilder s = new StringBuilder(keyword("vn"));
            for (int k = 0; k < 3; k++) {
                s.append(separator()).append(number(n, k));
            }
            normals.add(n);
            emit(s.toString());
        }

        String index(int zeroBased, int count) {
            return random.nextBoolean() ? Integer.toString(zeroBased + 1) : Integer.toString(zeroBased - count);
        }

        void face() {
            int size = 3 + (random.nextInt(4) == 0 ? random.nextInt(20) : random.nextInt(2));
            StringBuilder s = new StringBuilder(keyword("f"));
            List<Corner> corners = new ArrayList<>();
            for (int k = 0; k < size; k++) {
                int v = random.nextInt(positions.size());
                int form = random.nextInt(4);
                boolean vt = (form == 1 || form == 3) && textures > 0;
                boolean vn = form >= 2 && !normals.isEmpty();
                int n = vn ? random.nextInt(normals.size()) : -1;
                s.append(separator()).append(index(v, positions.size()));
                if (vt) {
                    s.append('/').append(index(random.nextInt(textures), textures));
                }
                if (vn) {
                    s.append(vt ? "/" : "//").append(index(n, normals.size()));
                }
                corners.add(corner(v, n));
            }
            emit(s.toString());
            faces.add(new Face(line, corners));
        }

        Corner corner(int v, int n) {
            double[] p = positions.get(v);
            double[] c = colours.get(v);
            double[] nn = n >= 0 ? normals.get(n) : new double[] {Double.NaN, Double.NaN, Double.NaN};
            return new Corner(p[0], p[1], p[2], c != null, c == null ? Double.NaN : c[0],
                    c == null ? Double.NaN : c[1], c == null ? Double.NaN : c[2], n >= 0, nn[0], nn[1], nn[2], v, n);
        }

        Maker make() {
            int lines = 5 + random.nextInt(200);
            for (int i = 0; i < lines; i++) {
                int kind = random.nextInt(10);
                if (kind < 3 || positions.isEmpty()) {
                    vertex();
                } else if (kind < 5) {
                    normal();
                } else if (kind < 8) {
                    face();
                } else if (kind == 8) {
                    textures++;
                    emit(keyword("vt") + " 0.5 0.5");
                } else {
                    emit(IGNORED[random.nextInt(IGNORED.length - 1)]);
                }
            }
            return this;
        }
    }

    @Property(tries = 200, seed = "1202007")
    void randomModelsReadAsTheyWereMade(@ForAll long seed) throws SceneException {
        Maker m = new Maker(seed).make();
        byte[] bytes = m.text.toString().getBytes(StandardCharsets.UTF_8);
        CollectedFaces streamed = new CollectedFaces();
        ObjCounts counts = ObjReader.stream(ObjReaderTest.NAME, bytes, streamed);
        assertEquals(m.faces, streamed.faces, m.text::toString);
        // warnings are ObjWarningsTest's: numbers such as "-912,523" are two, as SPEC reads them, with a warning
        assertEquals(new ObjCounts(m.positions.size(), m.normals.size(), m.faces.size(), m.firstClampedColour,
                m.firstClampedChannel, counts.warnings()), counts);
        CollectedFaces replayed = new CollectedFaces();
        ObjModel.of(ObjReaderTest.NAME, bytes).replay(replayed);
        assertEquals(m.faces, replayed.faces);
    }

    @Property(tries = 300, seed = "1202008")
    void damagedModelsFailAtAPlaceOnTheirText(@ForAll long seed) {
        Maker m = new Maker(seed).make();
        Random random = new Random(~seed);
        StringBuilder text = new StringBuilder(m.text);
        String junk = "0123456789/-+.,()e xvnfVNF#\t\u00e9\u0000";
        for (int d = 1 + random.nextInt(4); d > 0; d--) {
            int at = random.nextInt(text.length() + 1);
            switch (random.nextInt(3)) {
                case 0 -> text.insert(at, junk.charAt(random.nextInt(junk.length())));
                case 1 -> text.delete(at, Math.min(text.length(), at + 1 + random.nextInt(3)));
                default -> text.insert(at, "\nf " + (random.nextInt(400) - 200) + " 1 2\n");
            }
        }
        byte[] bytes = text.toString().getBytes(StandardCharsets.UTF_8);
        String[] lines = text.toString().split("\r?\n", -1);
        try {
            ObjReader.stream(ObjReaderTest.NAME, bytes, face -> assertTrue(face.size() >= 3));
            Statistics.collect("read");
        } catch (SceneException e) {
            Statistics.collect("error");
            assertTrue(e.line() >= 1 && e.line() <= lines.length, e.getMessage());
            Matcher notText = Pattern
                    .compile("^not a text file: byte 0x([0-9A-F]{2}) at offset (\\d+) \\(line (\\d+)\\)")
                    .matcher(e.problem());
            if (notText.find()) { // the junk's NUL: that byte, on that line, and none of the file's bytes shown
                int offset = Integer.parseInt(notText.group(2));
                assertEquals(0, bytes[offset], e.getMessage());
                int line = 1;
                for (int i = 0; i < offset; i++) {
                    line += bytes[i] == '\n' ? 1 : 0;
                }
                assertEquals(line, e.line(), e.getMessage());
                assertEquals("", e.lineText());
                return;
            }
            String line = lines[e.line() - 1].replaceAll("\r+$", "");
            assertEquals(line, e.lineText());
            assertTrue(e.column() >= 1 && e.column() <= line.length() + 1, e.getMessage());
        }
        Statistics.coverage(c -> c.check("error").percentage(p -> p > 30));
    }
}
