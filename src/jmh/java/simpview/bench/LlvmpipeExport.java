package simpview.bench;

import java.io.BufferedReader;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import simpview.geometry.Camera;
import simpview.geometry.Vertex;
import simpview.raster.FragmentLayout;
import simpview.pages.Assignment2;
import simpview.pages.MeshPage;
import simpview.pages.Page;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;
import simpview.pages.PerturbedMesh;
import simpview.pages.ScenePage;
import simpview.pages.ZBufferPage;
import simpview.scene.obj.ObjLibrary;
import simpview.scene.simp.SceneLibrary;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.SimpClient;
import simpview.scene.simp.SimpInterpreter;
import simpview.shading.Fog;
import simpview.shading.FragmentStage;
import simpview.shading.LitState;
import simpview.stage.Painter;
import simpview.stage.PrimitiveTrace;
import simpview.surface.DrawingThreads;
import simpview.surface.PageCanvas;
import simpview.surface.Rgb;

/**
 * The simpview side of the llvmpipe benchmark (bench/llvmpipe/): for each
 * course page, writes the primitives simpview hands its rasterizers: for a
 * lit page (A3, A4) what its geometry stage gives them (clipped and
 * projected, as clip-space positions and the attributes simpview
 * interpolates), for one of A2's eight pages the panel-space triangles and
 * lines its renderers draw (pages 1 to 3 from the page's own mesh or
 * triangles, 4 to 8 from the depth-cued scene's geometry stage). Filled
 * polygons go as triangles, lines and wire outlines as line segments (an
 * outline's every edge), grouped in drawing order by how they are lit and
 * by which of the two they are, so that OpenGL draws the same primitives
 * with the same lighting, fog or depth cue in GLSL (its lines by its own
 * rule, the diamond exit, where simpview's follow the course's DDA: about
 * the same pixels, not the same to the pixel); then times simpview's warm
 * redraws of the page on 1 thread (the median and best of 61), and on 2
 * threads taking turns with llvmpipe's (draw.py, started here):
 * {@value #TURNS} turns each, one after the other, of one untimed redraw and
 * {@value #TIMED_IN_A_TURN} timed. simpview is warmed at each thread count
 * by {@value #WARM_SECONDS} s of redraws (at least 20) first, as long as
 * {@link LitPages}' JMH warm-up, so that C2 has compiled the drawing before
 * it is timed, as llvmpipe's shaders are compiled before its redraws are
 * (draw.py warms llvmpipe 3 s: it compiles its shaders at the first draw).
 * With 3 s here too, as until session 45, simpview's one-thread redraws of
 * A4 page-f1 came out at 20-28 ms (best 13-25) where JMH and this with 8 s
 * give 10-13 (best 8.5-8.9): C2 was still compiling.
 *
 * <p>A2's depth cue is the fog of draw.py's shader: the cue's near colour as
 * every vertex's colour, fogged from z = 0 (near) to z = -200 (far) towards
 * the cue's far colour (black), which is SPEC Part 1's
 * {@code far + (near - far) (z + 200) / 200} per fragment. Pages 1 and 2
 * draw with no depth test (simpview draws them on the panel itself), so
 * their groups ask draw.py for none.
 *
 * <p>Why turns: on this machine a two-thread picture takes 20-25 % longer
 * for a second or so at a time (docs/performance-log.md, session 17), one
 * thread's much less; 61 redraws of each side one after the other fell in
 * one such spell or not, and the ratio of the two moved by as much between
 * runs. Taking turns, both sides see the same spells.
 *
 * <p>Prints one line per page: {@code page ms1 best1 ms2 best2 llvmpipeMs
 * llvmpipeBest triangles lines skipped} (medians and bests, in ms).
 *
 * <p>Args: the folder holding course-simp (A2's pages 6 to 8),
 * course-simp-a3 and course-simp-a4, the folder to write NAME.bin into, the
 * Python that has PyOpenGL, draw.py, then pages as "a3/pageF" or "a2/page7".
 * A2's pages 4 and 5 are the project's own scenes, read from simp/ of the
 * working folder (the repository's, as run.sh runs it). A primitive of
 * another kind (none so far) is not exported, only counted as skipped.
 *
 * <p>File (little-endian): int groups; per group 80 floats of uniforms (see
 * {@link #uniforms}), int mode (0 triangles, 1 line segments), int
 * vertices, then 13 floats per vertex: clip x, y, z, w, camera z, r, g, b
 * (kd under phong, else the lit colour), P x, P y, N x, N y, N z.
 */
public final class LlvmpipeExport {

    static final int UNIFORMS = 80;
    /** A group's mode in the file: triangles, three vertices each, or line segments, two each. */
    static final int TRIANGLES = 0;
    static final int SEGMENTS = 1;
    static final int MOST_LIGHTS = 8;
    private static final int FLOATS = 13;

    private LlvmpipeExport() {
    }

    public static void main(String[] args) throws Exception {
        Path folder = Path.of(args[0]);
        Path out = Path.of(args[1]);
        String python = args[2];
        String drawPy = args[3];
        Files.createDirectories(out);
        for (int i = 4; i < args.length; i++) {
            ComparedPage page = ComparedPage.of(folder, args[i]);
            Export export = page.export();
            String name = args[i].replace('/', '-');
            export.write(out.resolve(name + ".bin"));
            double[] one = timeOneThread(page);
            double[][] two = inTurns(page, new ProcessBuilder(python, drawPy, out.toString(), name));
            System.out.println(String.format(Locale.ROOT, "%s %.3f %.3f %.3f %.3f %.3f %.3f %d %d %d", args[i],
                    one[0], one[1], two[0][0], two[0][1], two[1][0], two[1][1], export.triangles, export.lines,
                    export.skipped));
        }
    }

    /** How long each thread count is warmed by redraws before it is timed. */
    private static final int WARM_SECONDS = 8;
    /** Turns each side takes, two threads against llvmpipe. */
    private static final int TURNS = 20;
    /** Redraws timed in a turn, after one untimed (draw.py's TIMED_IN_A_TURN). */
    private static final int TIMED_IN_A_TURN = 20;

    /**
     * simpview's warm redraws of the page on two threads and llvmpipe's
     * ({@code llvmpipe} starts draw.py on it), taking turns: the median and
     * best of each, simpview's first.
     */
    private static double[][] inTurns(ComparedPage page, ProcessBuilder llvmpipe) throws Exception {
        Process drawer = llvmpipe.redirectError(ProcessBuilder.Redirect.INHERIT).start();
        Writer to = new OutputStreamWriter(drawer.getOutputStream(), StandardCharsets.US_ASCII);
        try (DrawingThreads drawing = DrawingThreads.of(2);
                BufferedReader from = new BufferedReader(
                        new InputStreamReader(drawer.getInputStream(), StandardCharsets.US_ASCII))) {
            if (!"ready".equals(from.readLine())) {
                throw new IllegalStateException("draw.py did not get ready: " + llvmpipe.command());
            }
            Redraw redraw = warmed(page, drawing);
            double[] ours = new double[TURNS * TIMED_IN_A_TURN];
            double[] theirs = new double[TURNS * TIMED_IN_A_TURN];
            for (int turn = 0; turn < TURNS; turn++) {
                redraw.redraw(); // untimed: the cores may still be llvmpipe's for a moment
                for (int r = 0; r < TIMED_IN_A_TURN; r++) {
                    ours[turn * TIMED_IN_A_TURN + r] = timed(redraw);
                }
                to.write("turn\n");
                to.flush();
                String line = from.readLine();
                String[] times = line == null ? new String[0] : line.trim().split(" ");
                if (times.length != TIMED_IN_A_TURN) {
                    throw new IllegalStateException("draw.py answered a turn with " + line);
                }
                for (int r = 0; r < TIMED_IN_A_TURN; r++) {
                    theirs[turn * TIMED_IN_A_TURN + r] = Double.parseDouble(times[r]);
                }
            }
            to.close(); // the end of draw.py's stdin: it returns
            if (drawer.waitFor() != 0) {
                throw new IllegalStateException("draw.py failed: " + llvmpipe.command());
            }
            return new double[][] {medianAndBest(ours), medianAndBest(theirs)};
        } finally {
            drawer.destroy();
        }
    }

    /** The median and the least of {@code t}, which it sorts. */
    private static double[] medianAndBest(double[] t) {
        Arrays.sort(t);
        return new double[] {t[t.length / 2], t[0]};
    }

    /** Median and best of 61 warm redraws of the page on one thread, in ms. */
    private static double[] timeOneThread(ComparedPage page) throws Exception {
        try (DrawingThreads drawing = DrawingThreads.of(1)) {
            Redraw redraw = warmed(page, drawing);
            double[] t = new double[61];
            for (int r = 0; r < t.length; r++) {
                t[r] = timed(redraw);
            }
            return medianAndBest(t);
        }
    }

    /**
     * The page's redraw with {@code drawing}, after {@value #WARM_SECONDS} s
     * of redraws (at least 20), as draw.py warms llvmpipe.
     */
    private static Redraw warmed(ComparedPage page, DrawingThreads drawing) throws Exception {
        Redraw redraw = page.redraw(drawing);
        long warmUntil = System.nanoTime() + WARM_SECONDS * 1_000_000_000L;
        for (int r = 0; r < 20 || System.nanoTime() < warmUntil; r++) {
            redraw.redraw();
        }
        return redraw;
    }

    /** One redraw, in ms. */
    private static double timed(Redraw redraw) throws Exception {
        long start = System.nanoTime();
        redraw.redraw();
        return (System.nanoTime() - start) / 1e6;
    }

    /** One warm redraw of a page, as the window makes it: its canvas cleared, then the page drawn. */
    @FunctionalInterface
    private interface Redraw {
        void redraw() throws Exception;
    }

    /** A course page as the benchmark draws it on both sides. */
    private interface ComparedPage {

        /** The page named as "a3/pageF", "a4/page-d" or "a2/page7", its files in or under {@code folder}. */
        static ComparedPage of(Path folder, String name) {
            if (name.startsWith("a2/page")) {
                int number = Integer.parseInt(name.substring("a2/page".length()));
                Assignment2.page(number); // fails at once for a page that does not exist
                return new A2Page(number, folder.resolve("course-simp"));
            }
            return new LitPage(LitPages.sceneFile(folder, name));
        }

        /** Its primitives, as simpview's rasterizers get them, for draw.py. */
        Export export() throws Exception;

        /** Its redraw on a canvas of its own, drawn with {@code drawing}. */
        Redraw redraw(DrawingThreads drawing);
    }

    /** A lit course page (A3, A4): its scene file, redrawn as {@link LitPages} does. */
    private record LitPage(Path file) implements ComparedPage {

        @Override
        public Export export() throws Exception {
            PageCanvas canvas = new PageCanvas();
            canvas.zbuffer().reset(Double.NEGATIVE_INFINITY);
            Export export = new Export();
            LitTrace trace = new LitTrace(export);
            SimpClient client = SimpClient.lit(new FragmentStage(canvas.zbuffer(), canvas.litPanel()),
                    new ObjLibrary(), trace);
            trace.client = client;
            new SimpInterpreter(client, SceneMonitor.NONE).run(file);
            return export;
        }

        @Override
        public Redraw redraw(DrawingThreads drawing) {
            PageCanvas canvas = new PageCanvas();
            canvas.drawWith(drawing);
            SceneLibrary library = new SceneLibrary();
            return () -> LitPages.redraw(canvas, file, library);
        }
    }

    /**
     * One of A2's eight pages, as {@link Assignment2Pages} draws it (the default seed;
     * the project's scenes from simp/, the course's from {@code courseScenes}).
     */
    private record A2Page(int number, Path courseScenes) implements ComparedPage {

        private PageContext context(SceneMonitor monitor) {
            return new PageContext(PageContext.DEFAULT_SEED, courseScenes, PageContext.PROJECT_SCENES, monitor);
        }

        @Override
        public Export export() throws Exception {
            Export export = new Export();
            Page page = Assignment2.page(number);
            if (page instanceof MeshPage) {
                // Page 1 each triangle's outline (WireframePolygonRenderer's three
                // lerped DDA lines), page 2 the triangles blerped; on the panel, no depth test.
                boolean filled = ((MeshPage) page).isFilled();
                export.group(cued(false, false), filled ? TRIANGLES : SEGMENTS);
                new PerturbedMesh(PageContext.DEFAULT_SEED).forEachTriangle((a, b, c) -> {
                    if (filled) {
                        export.triangle(a, b, c);
                    } else {
                        export.segment(a, b);
                        export.segment(b, c);
                        export.segment(c, a);
                    }
                });
            } else if (page instanceof ZBufferPage) {
                export.group(cued(false, true), TRIANGLES);
                for (Vertex[] t : ZBufferPage.triangles(PageContext.DEFAULT_SEED)) {
                    export.triangle(t[0], t[1], t[2]);
                }
            } else {
                // A scene: its primitives as its geometry stage hands them to the painter, cued.
                ScenePage scene = (ScenePage) page;
                export.colour(scene.near());
                CuedTrace trace = new CuedTrace(export, cued(true, true));
                PageCanvas canvas = new PageCanvas();
                page.draw(canvas, context(new SceneMonitor() {
                    @Override
                    public PrimitiveTrace trace() {
                        return trace;
                    }
                }));
            }
            return export;
        }

        @Override
        public Redraw redraw(DrawingThreads drawing) {
            PageRenderer renderer = new PageRenderer(drawing);
            PageContext context = context(SceneMonitor.NONE);
            return () -> renderer.render(number, context);
        }
    }

    /**
     * The uniforms of an A2 group: not lit; cued or not, from near (z = 0,
     * the cue's near colour, which is every vertex's: {@link Export#colour})
     * towards black at far (z = -200); with or without the depth test (u[14]
     * 1: without).
     */
    private static float[] cued(boolean cue, boolean depthTest) {
        float[] u = new float[UNIFORMS];
        Camera view = Camera.PARALLEL;
        if (cue) {
            u[1] = 1;
            u[2] = (float) view.hither();
            u[3] = (float) view.yon();
            u[4] = (float) Rgb.BLACK.r();
            u[5] = (float) Rgb.BLACK.g();
            u[6] = (float) Rgb.BLACK.b();
        }
        u[14] = depthTest ? 0 : 1;
        return u;
    }

    /** The groups of primitives written for draw.py, in drawing order. */
    private static final class Export {
        private final List<float[]> groupUniforms = new ArrayList<>();
        private final List<Integer> groupModes = new ArrayList<>();
        private final List<FloatList> groupVertices = new ArrayList<>();
        /** The colour every A2 vertex is given from now on (a cued scene's near colour), or null: its own. */
        private Rgb colour;
        int triangles;
        int lines;
        int skipped;

        /**
         * How a primitive of this kind is drawn: filled polygons as
         * triangles, lines and wire outlines as segments; -1, counted as
         * skipped, for any other kind.
         */
        int modeOf(int kind) {
            if (kind == Painter.FILLED) {
                return TRIANGLES;
            }
            if (kind == Painter.LINE || kind == Painter.WIRE) {
                return SEGMENTS;
            }
            skipped++;
            return -1;
        }

        /** From now on the primitives go to a new group: these uniforms, triangles or segments. */
        void group(float[] uniforms, int mode) {
            groupUniforms.add(uniforms);
            groupModes.add(mode);
            groupVertices.add(new FloatList());
        }

        boolean isEmpty() {
            return groupVertices.isEmpty();
        }

        FloatList vertices() {
            return groupVertices.get(groupVertices.size() - 1);
        }

        /** Every later A2 vertex is given this colour (null: its own). */
        void colour(Rgb every) {
            colour = every;
        }

        void triangle(Vertex a, Vertex b, Vertex c) {
            panelVertex(a);
            panelVertex(b);
            panelVertex(c);
            triangles++;
        }

        void segment(Vertex a, Vertex b) {
            panelVertex(a);
            panelVertex(b);
            lines++;
        }

        /** An A2 vertex: panel x and y, world z (the parallel view's depth), its colour. */
        private void panelVertex(Vertex v) {
            double x = v.x() / PageCanvas.PANEL * 2 - 1;
            double y = v.y() / PageCanvas.PANEL * 2 - 1;
            FloatList out = vertices();
            out.add(x, y, depth(Camera.PARALLEL, 1, v.z()), 1);
            if (colour == null) {
                out.add(v.z(), v.r(), v.g(), v.b());
            } else {
                out.add(v.z(), colour.r(), colour.g(), colour.b());
            }
            out.add(0, 0, 0, 0);
            out.add(0);
        }

        void write(Path file) throws IOException {
            try (OutputStream o = Files.newOutputStream(file); DataOutputStream d = new DataOutputStream(o)) {
                d.write(ints(groupVertices.size()));
                for (int g = 0; g < groupVertices.size(); g++) {
                    d.write(floats(groupUniforms.get(g), groupUniforms.get(g).length));
                    d.write(ints(groupModes.get(g)));
                    FloatList v = groupVertices.get(g);
                    d.write(ints(v.size / FLOATS));
                    d.write(floats(v.data, v.size));
                }
            }
        }
    }

    /** Follows a depth-cued scene's primitives as its geometry stage hands them to the painter, in drawing order. */
    private static final class CuedTrace implements PrimitiveTrace {
        private final Export export;
        private final float[] uniforms;
        private final Vertex[] corners = new Vertex[3];
        private int lastMode = -1;

        CuedTrace(Export export, float[] uniforms) {
            this.export = export;
            this.uniforms = uniforms;
        }

        @Override
        public void read(int index, Path file, int line, int kind, double[] p, int at, int stride, int vertices) {
            int mode = export.modeOf(kind);
            if (mode < 0) {
                return;
            }
            if (mode != lastMode) {
                lastMode = mode;
                export.group(uniforms, mode);
            }
            for (int k = 0; k < vertices; k++) {
                corners[k] = Vertex.readFrom(p, at + k * stride);
            }
            if (kind == Painter.FILLED) {
                export.triangle(corners[0], corners[1], corners[2]);
            } else {
                int segments = kind == Painter.LINE ? 1 : vertices;
                for (int k = 0; k < segments; k++) {
                    export.segment(corners[k], corners[(k + 1) % vertices]);
                }
            }
        }

        @Override
        public boolean drawing(int index) {
            return true;
        }
    }

    /** Follows a lit scene's primitives as they reach the rasterizers, in drawing order. */
    private static final class LitTrace implements PrimitiveTrace {
        private final Export export;
        /** The client whose primitives are followed: its lit state is the one in force for each. */
        SimpClient client;
        private Fog lastFog;
        private int lastVersion = -1;
        private boolean lastPhong;
        private int lastMode;
        /** Whether the primitive read next holds its one colour as it is, not times q (PrimitiveTrace.oneColour). */
        private boolean oneColour;

        LitTrace(Export export) {
            this.export = export;
        }

        @Override
        public void oneColour() {
            oneColour = true;
        }

        @Override
        public void read(int index, Path file, int line, int kind, double[] p, int at, int stride, int vertices) {
            boolean asIs = oneColour;
            oneColour = false;
            int mode = export.modeOf(kind);
            if (mode < 0) {
                return;
            }
            LitState state = client.litState();
            int channels = stride - FragmentLayout.CHANNEL;
            boolean phong = channels == FragmentLayout.PHONG_CHANNELS;
            if (export.isEmpty() || state.fog() != lastFog || state.lightingVersion() != lastVersion
                    || phong != lastPhong || mode != lastMode) {
                lastFog = state.fog();
                lastVersion = state.lightingVersion();
                lastPhong = phong;
                lastMode = mode;
                export.group(uniforms(state, phong), mode);
            }
            FloatList v = export.vertices();
            Camera camera = state.camera();
            if (kind == Painter.FILLED) {
                for (int k = 1; k + 1 < vertices; k++) {
                    vertex(v, camera, p, at, stride, channels, asIs);
                    vertex(v, camera, p, at + k * stride, stride, channels, asIs);
                    vertex(v, camera, p, at + (k + 1) * stride, stride, channels, asIs);
                    export.triangles++;
                }
            } else {
                // A line's one segment, or each edge of an outline, as simpview draws them.
                int segments = kind == Painter.LINE ? 1 : vertices;
                for (int k = 0; k < segments; k++) {
                    vertex(v, camera, p, at + k * stride, stride, channels, asIs);
                    vertex(v, camera, p, at + ((k + 1) % vertices) * stride, stride, channels, asIs);
                    export.lines++;
                }
            }
        }

        /** One vertex for the shaders: its colour as it is ({@code asIs}: one colour) or its channels over q. */
        private static void vertex(FloatList out, Camera camera, double[] p, int at, int stride, int channels,
                boolean asIs) {
            double q = p[at + FragmentLayout.Q];
            double w = 1 / q;
            double x = p[at + FragmentLayout.X] / PageCanvas.PANEL * 2 - 1;
            double y = p[at + FragmentLayout.Y] / PageCanvas.PANEL * 2 - 1;
            int c = at + FragmentLayout.CHANNEL;
            double z = p[c + FragmentLayout.Z] * w;
            double colourTimes = asIs ? 1 : w;
            out.add(x * w, y * w, depth(camera, q, z) * w, w);
            out.add(z, p[c + FragmentLayout.R] * colourTimes, p[c + FragmentLayout.G] * colourTimes,
                    p[c + FragmentLayout.B] * colourTimes);
            if (channels == FragmentLayout.PHONG_CHANNELS) {
                out.add(p[c + FragmentLayout.PX] * w, p[c + FragmentLayout.PY] * w, p[c + FragmentLayout.NX] * w,
                        p[c + FragmentLayout.NY] * w);
                out.add(p[c + FragmentLayout.NZ] * w);
            } else {
                out.add(0, 0, 0, 0);
                out.add(0);
            }
        }

        @Override
        public boolean drawing(int index) {
            return true;
        }
    }

    /**
     * OpenGL's depth of a vertex, -1 on the near plane and 1 on the far one:
     * from q (1 / w) in perspective, as simpview's depth test orders the
     * pixels there, from camera z in the parallel view (A2's, q 1).
     */
    private static double depth(Camera camera, double q, double z) {
        if (camera.isPerspective()) {
            double near = 1 / -camera.hither();
            double far = 1 / -camera.yon();
            return 1 - 2 * (q - far) / (near - far);
        }
        return 1 - 2 * (z - camera.yon()) / (camera.hither() - camera.yon());
    }

    /**
     * The uniforms of a lit group: phong (1 or 0), fog on (1 or 0), fog
     * near, far, r, g, b, ambient r, g, b, ks, p, perspective, lights, then
     * u[14] 0 (depth-tested; 1 draws with no depth test, A2's pages 1 and 2:
     * {@link #cued}); from 16, 8 floats per light (camera-space x, y, z,
     * intensity r, g, b, A, B).
     */
    static float[] uniforms(LitState state, boolean phong) {
        float[] u = new float[UNIFORMS];
        Fog fog = state.fog();
        double[] lighting = state.lightingNumbers();
        u[0] = phong ? 1 : 0;
        u[1] = fog.isNone() ? 0 : 1;
        u[2] = (float) (fog.isNone() ? 0 : fog.near());
        u[3] = (float) (fog.isNone() ? 0 : fog.far());
        u[4] = (float) fog.r();
        u[5] = (float) fog.g();
        u[6] = (float) fog.b();
        for (int i = 0; i < 6; i++) {
            u[7 + i] = (float) lighting[i];
        }
        int lights = Math.min(MOST_LIGHTS, (int) lighting[6]);
        u[13] = lights;
        for (int i = 0; i < 8 * lights; i++) {
            u[16 + i] = (float) lighting[7 + i];
        }
        return u;
    }

    private static byte[] ints(int v) {
        return ByteBuffer.allocate(4).order(ByteOrder.LITTLE_ENDIAN).putInt(v).array();
    }

    private static byte[] floats(float[] v, int n) {
        ByteBuffer b = ByteBuffer.allocate(4 * n).order(ByteOrder.LITTLE_ENDIAN);
        for (int i = 0; i < n; i++) {
            b.putFloat(v[i]);
        }
        return b.array();
    }

    /** A growing array of floats. */
    private static final class FloatList {
        float[] data = new float[1024];
        int size;

        void add(double... values) {
            if (size + values.length > data.length) {
                data = Arrays.copyOf(data, 2 * data.length + values.length);
            }
            for (double v : values) {
                data[size++] = (float) v;
            }
        }
    }
}
