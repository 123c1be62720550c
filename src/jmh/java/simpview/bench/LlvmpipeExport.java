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
import simpview.raster.FragmentLayout;
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

/**
 * The simpview side of the llvmpipe benchmark (bench/llvmpipe/): for each
 * lit course page, writes the primitives its geometry stage hands the
 * rasterizers (clipped and projected, as clip-space positions and the
 * attributes simpview interpolates): filled polygons as triangles, lines and
 * wire outlines as line segments (an outline's every edge), grouped in
 * drawing order by how they are lit and by which of the two they are, so
 * that OpenGL draws the same primitives with the same lighting in GLSL (its
 * lines by its own rule, the diamond exit, where simpview's follow the
 * course's DDA: about the same pixels, not the same to the pixel); then
 * times simpview's warm redraws of the page on 1 thread (the median and best
 * of 61), and on 2 threads taking turns with llvmpipe's (draw.py, started
 * here): {@value #TURNS} turns each, one after the other, of one untimed
 * redraw and {@value #TIMED_IN_A_TURN} timed. Each side is warmed by
 * {@value #WARM_SECONDS} s of redraws (at least 20) first. That is as long
 * as JMH's warm-up, so that the JIT has compiled the drawing before it is
 * timed, as llvmpipe's shaders are compiled before its redraws are.
 *
 * <p>Why turns: on this machine a two-thread picture takes 20-25 % longer
 * for a second or so at a time (docs/performance.md, session 17), one
 * thread's much less; 61 redraws of each side one after the other fell in
 * one such spell or not, and the ratio of the two moved by as much between
 * runs. Taking turns, both sides see the same spells.
 *
 * <p>Prints one line per page: {@code page ms1 best1 ms2 best2 llvmpipeMs
 * llvmpipeBest triangles lines skipped} (medians and bests, in ms).
 *
 * <p>Args: the folder holding course-simp-a3 and course-simp-a4, the folder
 * to write NAME.bin into, the Python that has PyOpenGL, draw.py, then pages
 * as "a3/pageF". A primitive of another kind (none so far) is not exported,
 * only counted as skipped.
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
            Path file = LitPages.sceneFile(folder, args[i]);
            Export export = export(file);
            String name = args[i].replace('/', '-');
            export.write(out.resolve(name + ".bin"));
            double[] one = timeOneThread(file);
            double[][] two = inTurns(file, new ProcessBuilder(python, drawPy, out.toString(), name));
            System.out.println(String.format(Locale.ROOT, "%s %.3f %.3f %.3f %.3f %.3f %.3f %d %d %d", args[i],
                    one[0], one[1], two[0][0], two[0][1], two[1][0], two[1][1], export.triangles, export.lines,
                    export.skipped));
        }
    }

    /** How long each thread count is warmed by redraws before it is timed. */
    private static final int WARM_SECONDS = 3;
    /** Turns each side takes, two threads against llvmpipe. */
    private static final int TURNS = 20;
    /** Redraws timed in a turn, after one untimed (draw.py's TIMED_IN_A_TURN). */
    private static final int TIMED_IN_A_TURN = 20;

    /**
     * simpview's warm redraws on two threads and llvmpipe's ({@code llvmpipe}
     * starts draw.py on the page), taking turns: the median and best of each,
     * simpview's first.
     */
    private static double[][] inTurns(Path file, ProcessBuilder llvmpipe) throws Exception {
        Process drawer = llvmpipe.redirectError(ProcessBuilder.Redirect.INHERIT).start();
        SceneLibrary library = new SceneLibrary();
        Writer to = new OutputStreamWriter(drawer.getOutputStream(), StandardCharsets.US_ASCII);
        try (DrawingThreads drawing = DrawingThreads.of(2);
                BufferedReader from = new BufferedReader(
                        new InputStreamReader(drawer.getInputStream(), StandardCharsets.US_ASCII))) {
            if (!"ready".equals(from.readLine())) {
                throw new IllegalStateException("draw.py did not get ready: " + llvmpipe.command());
            }
            PageCanvas canvas = warmed(file, drawing, library);
            double[] ours = new double[TURNS * TIMED_IN_A_TURN];
            double[] theirs = new double[TURNS * TIMED_IN_A_TURN];
            for (int turn = 0; turn < TURNS; turn++) {
                LitPages.redraw(canvas, file, library); // untimed: the cores may still be llvmpipe's for a moment
                for (int r = 0; r < TIMED_IN_A_TURN; r++) {
                    ours[turn * TIMED_IN_A_TURN + r] = timedRedraw(canvas, file, library);
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

    /** Median and best of 61 warm redraws on one thread, in ms. */
    private static double[] timeOneThread(Path file) throws Exception {
        SceneLibrary library = new SceneLibrary();
        try (DrawingThreads drawing = DrawingThreads.of(1)) {
            PageCanvas canvas = warmed(file, drawing, library);
            double[] t = new double[61];
            for (int r = 0; r < t.length; r++) {
                t[r] = timedRedraw(canvas, file, library);
            }
            return medianAndBest(t);
        }
    }

    /**
     * A canvas drawn on by {@code drawing}, after {@value #WARM_SECONDS} s of
     * redraws of the page (at least 20), as draw.py warms llvmpipe.
     */
    private static PageCanvas warmed(Path file, DrawingThreads drawing, SceneLibrary library) throws Exception {
        PageCanvas canvas = new PageCanvas();
        canvas.drawWith(drawing);
        long warmUntil = System.nanoTime() + WARM_SECONDS * 1_000_000_000L;
        for (int r = 0; r < 20 || System.nanoTime() < warmUntil; r++) {
            LitPages.redraw(canvas, file, library);
        }
        return canvas;
    }

    /** One redraw of the page, in ms. */
    private static double timedRedraw(PageCanvas canvas, Path file, SceneLibrary library) throws Exception {
        long start = System.nanoTime();
        LitPages.redraw(canvas, file, library);
        return (System.nanoTime() - start) / 1e6;
    }

    private static Export export(Path file) throws Exception {
        PageCanvas canvas = new PageCanvas();
        canvas.zbuffer().reset(Double.NEGATIVE_INFINITY);
        Export export = new Export();
        SimpClient client = SimpClient.lit(new FragmentStage(canvas.zbuffer(), canvas.litPanel()), new ObjLibrary(),
                export);
        export.client = client;
        new SimpInterpreter(client, SceneMonitor.NONE).run(file);
        return export;
    }

    /** Follows the primitives as they reach the rasterizers, in drawing order. */
    private static final class Export implements PrimitiveTrace {
        /** The client whose primitives are followed: its lit state is the one in force for each. */
        SimpClient client;
        private final List<float[]> groupUniforms = new ArrayList<>();
        private final List<Integer> groupModes = new ArrayList<>();
        private final List<FloatList> groupVertices = new ArrayList<>();
        private Fog lastFog;
        private int lastVersion = -1;
        private boolean lastPhong;
        private int lastMode;
        int triangles;
        int lines;
        int skipped;


        @Override
        public void read(int index, Path file, int line, int kind, double[] p, int at, int stride, int vertices) {
            if (kind != Painter.FILLED && kind != Painter.LINE && kind != Painter.WIRE) {
                skipped++;
                return;
            }
            int mode = kind == Painter.FILLED ? TRIANGLES : SEGMENTS;
            LitState state = client.litState();
            int channels = stride - FragmentLayout.CHANNEL;
            boolean phong = channels == FragmentLayout.PHONG_CHANNELS;
            if (groupVertices.isEmpty() || state.fog() != lastFog || state.lightingVersion() != lastVersion
                    || phong != lastPhong || mode != lastMode) {
                lastFog = state.fog();
                lastVersion = state.lightingVersion();
                lastPhong = phong;
                lastMode = mode;
                groupUniforms.add(uniforms(state, phong));
                groupModes.add(mode);
                groupVertices.add(new FloatList());
            }
            FloatList v = groupVertices.get(groupVertices.size() - 1);
            Camera camera = state.camera();
            if (kind == Painter.FILLED) {
                for (int k = 1; k + 1 < vertices; k++) {
                    vertex(v, camera, p, at, stride, channels);
                    vertex(v, camera, p, at + k * stride, stride, channels);
                    vertex(v, camera, p, at + (k + 1) * stride, stride, channels);
                    triangles++;
                }
            } else {
                // A line's one segment, or each edge of an outline, as simpview draws them.
                int segments = kind == Painter.LINE ? 1 : vertices;
                for (int k = 0; k < segments; k++) {
                    vertex(v, camera, p, at + k * stride, stride, channels);
                    vertex(v, camera, p, at + ((k + 1) % vertices) * stride, stride, channels);
                    lines++;
                }
            }
        }

        private static void vertex(FloatList out, Camera camera, double[] p, int at, int stride, int channels) {
            double q = p[at + FragmentLayout.Q];
            double w = 1 / q;
            double x = p[at + FragmentLayout.X] / PageCanvas.PANEL * 2 - 1;
            double y = p[at + FragmentLayout.Y] / PageCanvas.PANEL * 2 - 1;
            int c = at + FragmentLayout.CHANNEL;
            double z = p[c + FragmentLayout.Z] * w;
            double ndc;
            if (camera.isPerspective()) {
                double near = 1 / -camera.hither();
                double far = 1 / -camera.yon();
                ndc = 1 - 2 * (q - far) / (near - far);
            } else {
                ndc = 1 - 2 * (z - camera.yon()) / (camera.hither() - camera.yon());
            }
            out.add(x * w, y * w, ndc * w, w);
            out.add(z, p[c + FragmentLayout.R] * w, p[c + FragmentLayout.G] * w, p[c + FragmentLayout.B] * w);
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

    /**
     * The uniforms of a group: phong (1 or 0), fog on (1 or 0), fog near,
     * far, r, g, b, ambient r, g, b, ks, p, perspective, lights; then from 16,
     * 8 floats per light (camera-space x, y, z, intensity r, g, b, A, B).
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
