package simpview.shading;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import org.junit.jupiter.api.Test;
import simpview.geometry.Camera;
import simpview.geometry.Matrix4;
import simpview.raster.FragmentLayout;
import simpview.surface.Drawable;
import simpview.surface.DrawingThreads;
import simpview.surface.ImageDrawable;
import simpview.surface.WaitingPixels;
import simpview.surface.ZBuffer;

/**
 * The fragment stages a picture's drawing threads keep for the next: handed
 * out again in the order they were, to one picture at a time, only for
 * panels of their size, and each as a new one, whatever the last picture
 * left in it.
 */
class FragmentStagesTest {

    private static final int SIZE = 120;

    @Test
    void keptStagesAreHandedOutAgainInOrderToOnePictureAtATime() {
        try (DrawingThreads threads = DrawingThreads.of(2)) {
            ZBuffer zbuffer = new ZBuffer(SIZE, SIZE);
            Drawable panel = panel(new BufferedImage(SIZE, SIZE, BufferedImage.TYPE_INT_RGB));
            FragmentStages first = FragmentStages.keptBy(threads, zbuffer);
            FragmentStage a = first.next(panel);
            FragmentStage b = first.next(panel);
            first.keep();
            first.keep(); // gives nothing back a second time, and keeps what the first gave

            FragmentStages second = FragmentStages.keptBy(threads, new ZBuffer(SIZE, SIZE));
            FragmentStages meanwhile = FragmentStages.keptBy(threads, zbuffer);
            assertSame(a, second.next(panel), "the first kept, first");
            assertNotSame(a, meanwhile.next(panel), "taken by the second picture: this one makes its own");
            assertSame(b, second.next(panel));
            FragmentStage c = second.next(panel);
            assertNotSame(a, c);
            assertNotSame(b, c);
            second.keep();

            FragmentStages larger = FragmentStages.keptBy(threads, new ZBuffer(SIZE + 1, SIZE + 1));
            FragmentStage made = larger.next(panel(new BufferedImage(SIZE + 1, SIZE + 1, BufferedImage.TYPE_INT_RGB)));
            assertNotSame(a, made, "kept for panels of another size");
            assertNotSame(b, made);
            assertNotSame(c, made);
        }
    }

    /**
     * A stage whose last picture ended with its rows narrowed, a look set and
     * phong pixels still waiting (as when a scene stops at an error) draws the
     * next picture as a new stage does: every row, shaded at once.
     */
    @Test
    void aKeptStageDrawsWhatANewOneDraws() {
        LitState state = new LitState();
        state.setCamera(Camera.perspective(-1, -1, 1, 1, -0.1, -200), Matrix4.identity());
        state.setAmbient(0.2, 0.1, 0.3);
        state.setSurface(0.8, 0.6, 0.4, 0.5, 16);
        state.addLight(3, 4, -2, 0.9, 0.8, 0.7, 1, 0);
        state.addLight(-5, 2, -1, 0.3, 0.6, 0.2, 1, 0.01);
        state.setFog(new Fog(-4, -8, 0.1, 0.2, 0.3));
        PointShader shader = state.frozenShader().get();
        double[] v0 = new double[FragmentLayout.PHONG_CHANNELS];
        double[] dv = new double[FragmentLayout.PHONG_CHANNELS];
        v0[FragmentLayout.Z] = -5;
        v0[FragmentLayout.NZ] = 1;
        v0[FragmentLayout.R] = 1;
        v0[FragmentLayout.G] = 0.5;
        dv[FragmentLayout.NX] = 0.01;
        dv[FragmentLayout.PX] = 0.05;

        try (DrawingThreads threads = DrawingThreads.one()) {
            ZBuffer before = new ZBuffer(SIZE, SIZE);
            before.reset(Double.NEGATIVE_INFINITY);
            FragmentStages last = FragmentStages.keptBy(threads, before);
            FragmentStage used = last.next(panel(new BufferedImage(SIZE, SIZE, BufferedImage.TYPE_INT_RGB)));
            used.rows(0, 5);
            used.shadeLater(new WaitingPixels(SIZE, SIZE), null);
            used.phong(shader, Fog.NONE);
            used.span(2, 0, 100, 1, 0, v0, dv); // waits, never shaded
            last.keep();

            BufferedImage kept = new BufferedImage(SIZE, SIZE, BufferedImage.TYPE_INT_RGB);
            BufferedImage fresh = new BufferedImage(SIZE, SIZE, BufferedImage.TYPE_INT_RGB);
            ZBuffer keptDepths = new ZBuffer(SIZE, SIZE);
            ZBuffer freshDepths = new ZBuffer(SIZE, SIZE);
            keptDepths.reset(Double.NEGATIVE_INFINITY);
            freshDepths.reset(Double.NEGATIVE_INFINITY);
            FragmentStage again = FragmentStages.keptBy(threads, keptDepths).next(panel(kept));
            assertSame(used, again);
            FragmentStage made = new FragmentStage(freshDepths, panel(fresh));
            for (FragmentStage stage : new FragmentStage[] {again, made}) {
                stage.phong(shader, state.fog());
                stage.span(2, 0, 100, 1, 0, v0, dv);
                stage.span(60, 10, 110, 1, 0, v0, dv);
                stage.colours(Fog.NONE);
                stage.span(61, 0, 50, 1, 0, v0, dv);
            }
            assertArrayEquals(pixels(fresh), pixels(kept), "the picture");
            assertArrayEquals(freshDepths.copyDepths(), keptDepths.copyDepths(), "the depths");
        }
    }

    private static Drawable panel(BufferedImage image) {
        return new ImageDrawable(image);
    }

    private static int[] pixels(BufferedImage image) {
        return ((DataBufferInt) image.getRaster().getDataBuffer()).getData();
    }
}
