package simpview.bench;

import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import simpview.surface.PageCanvas;

/**
 * The two surfaces a raster benchmark compares: our page canvas and a Java2D
 * graphics on the same kind of 750x750 image. The z-buffer is reset before
 * each invocation, outside the timing, so every run starts from an empty
 * depth buffer whatever the one before drew.
 */
@State(Scope.Thread)
public abstract class AgainstJava2D {

    protected PageCanvas canvas;
    protected Java2DPage java2d;

    @Setup(Level.Trial)
    public final void openSurfaces() {
        canvas = new PageCanvas();
        java2d = new Java2DPage();
        prepare();
    }

    /** Builds the benchmark's geometry and drawable chain; the surfaces are open by then. */
    protected abstract void prepare();

    @Setup(Level.Invocation)
    public final void resetDepth() {
        canvas.zbuffer().reset(-200);
    }

    @TearDown(Level.Trial)
    public final void closeSurfaces() {
        java2d.dispose();
    }
}
