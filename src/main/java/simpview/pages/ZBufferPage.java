package simpview.pages;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import simpview.geometry.Vertex;
import simpview.surface.Drawable;
import simpview.surface.PageCanvas;
import simpview.surface.Provenance;
import simpview.raster.FilledPolygonRenderer;

/**
 * Page 3: six grey regular triangles, v = 1, .85, .7, .55, .4, .25 in that
 * drawing order, vertices on the circle of radius 275 px around the panel
 * centre, each turned by a random angle in [0, 120) degrees and put at a
 * random world depth in [-199, -1]. Drawn through the z-buffer, without depth
 * cueing, so the greys show which triangle is in front.
 */
public final class ZBufferPage implements Page {

    /**
     * Which triangle a pixel shows where several cover it: SPEC's, the nearest; or a student's z-buffer that is
     * left out (each triangle drawn over the last, in drawing order) or whose test is turned round (the farthest).
     * Drawn so, the page is what such a renderer draws, for compare to tell a picture that is one.
     */
    public enum DepthTest {
        NEAREST,
        NONE,
        FARTHEST
    }

    private final DepthTest test;

    /** The page as SPEC draws it, the nearest triangle in front. */
    public ZBufferPage() {
        this(DepthTest.NEAREST);
    }

    /** The page with its triangles in front of each other as {@code test} has them. */
    public ZBufferPage(DepthTest test) {
        this.test = test;
    }

    /** Triangle t's grey, in drawing order; read through {@link #grey}, so nobody can change a page's colours. */
    private static final double[] GREYS = {1, .85, .7, .55, .4, .25};
    public static final double RADIUS = 275;
    public static final double NEAREST_Z = -1;
    public static final double FARTHEST_Z = -199;

    /** The grey of triangle t (0 first drawn, 1 white). */
    public static double grey(int t) {
        return GREYS[t];
    }

    @Override
    public String title() {
        return "Z-buffer";
    }

    @Override
    public boolean usesSeed() {
        return true;
    }

    @Override
    public void draw(PageCanvas canvas, PageContext context) {
        Drawable target = canvas.depthTested();
        target.settle(); // what the clear owes, made before the z-test loop rather than by its first write
        FilledPolygonRenderer renderer = new FilledPolygonRenderer();
        Provenance provenance = canvas.provenance();
        Vertex[][] triangles = triangles(context.seed());
        for (int t = 0; t < triangles.length; t++) {
            triangles[t] = inFront(triangles[t], t);
            if (provenance != null) {
                provenance.begin(t);
            }
            renderer.drawPolygon(triangles[t][0], triangles[t][1], triangles[t][2], target);
        }
    }

    /**
     * Triangle t (in drawing order) with its depth moved so that SPEC's z-buffer puts it in front as {@link #test}
     * would: without a test each later triangle is nearer than the one before; with the test turned round, a depth
     * z is mirrored to -200 - z, so the farthest is the nearest. Its shape and grey are kept.
     */
    private Vertex[] inFront(Vertex[] triangle, int t) {
        if (test == DepthTest.NEAREST) {
            return triangle;
        }
        double z = test == DepthTest.NONE ? FARTHEST_Z + (NEAREST_Z - FARTHEST_Z) * t / (GREYS.length - 1)
                : FARTHEST_Z + NEAREST_Z - triangle[0].z();
        Vertex[] moved = new Vertex[triangle.length];
        for (int k = 0; k < triangle.length; k++) {
            Vertex v = triangle[k];
            moved[k] = new Vertex(v.x(), v.y(), z, v.r(), v.g(), v.b());
        }
        return moved;
    }

    /** "triangle 3 of 6, grey 0.70, z -57.1234", in drawing order. */
    @Override
    public List<String> primitiveNames(PageContext context) {
        List<String> names = new ArrayList<>();
        Vertex[][] triangles = triangles(context.seed());
        for (int t = 0; t < triangles.length; t++) {
            names.add(String.format(Locale.ROOT, "triangle %d of %d, grey %.2f, z %.4f",
                    t + 1, triangles.length, GREYS[t], triangles[t][0].z()));
        }
        return names;
    }

    @Override
    public List<ListedPrimitive> primitives(PageContext context) {
        List<ListedPrimitive> out = new ArrayList<>();
        for (Vertex[] triangle : triangles(context.seed())) {
            out.add(new ListedPrimitive(1, List.of(triangle)));
        }
        return out;
    }

    /** The six triangles in drawing order, in panel coordinates; random draws: angle, then depth. */
    public static Vertex[][] triangles(long seed) {
        Random random = new Random(seed);
        double centre = PageCanvas.PANEL / 2.0;
        Vertex[][] result = new Vertex[GREYS.length][];
        for (int t = 0; t < GREYS.length; t++) {
            double turn = random.nextDouble() * 120;
            double z = FARTHEST_Z + random.nextDouble() * (NEAREST_Z - FARTHEST_Z);
            double v = GREYS[t];
            Vertex[] triangle = new Vertex[3];
            for (int k = 0; k < 3; k++) {
                double angle = StrictMath.toRadians(turn + 120 * k + 90);
                triangle[k] = new Vertex(centre + RADIUS * StrictMath.cos(angle), centre + RADIUS * StrictMath.sin(angle), z,
                        v, v, v);
            }
            result[t] = triangle;
        }
        return result;
    }
}
