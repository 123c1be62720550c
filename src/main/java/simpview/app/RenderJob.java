package simpview.app;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;
import simpview.scene.SceneException;
import simpview.scene.simp.SceneCancelledException;
import simpview.scene.simp.SceneMonitor;
import simpview.surface.PageCanvas;

/**
 * One picture to draw on the render thread. It is also the scene's monitor:
 * the window reads its progress and cancels it from the EDT, so its shared
 * state is volatile or thread-safe.
 */
final class RenderJob implements SceneMonitor {

    private final View view;
    private final PageContext context;
    private final long createdNanos = System.nanoTime();
    private final List<String> warnings = new CopyOnWriteArrayList<>();
    private volatile long linesRead;
    private volatile boolean cancelled;

    RenderJob(View view, PageContext context) {
        this.view = view;
        this.context = context.withMonitor(this);
    }

    View view() {
        return view;
    }

    long seed() {
        return context.seed();
    }

    long millisSinceCreated() {
        return (System.nanoTime() - createdNanos) / 1_000_000;
    }

    long linesSoFar() {
        return linesRead;
    }

    void cancel() {
        cancelled = true;
    }

    @Override
    public boolean cancelled() {
        return cancelled;
    }

    @Override
    public void linesRead(long lines) {
        linesRead = lines;
    }

    @Override
    public void warning(String message) {
        warnings.add(message);
    }

    /**
     * Draws on the render thread's canvas and returns a copy of the result,
     * or null when the job was cancelled.
     */
    RenderedView run(PageRenderer renderer, SceneDrawer drawer) {
        if (cancelled) {
            return null;
        }
        PageCanvas canvas = renderer.canvas();
        String error = null;
        try {
            if (view instanceof View.OfPage page) {
                renderer.render(page.number(), context);
            } else {
                SceneSheet.of(((View.OfScene) view).file()).drawOn(canvas, this, drawer);
            }
        } catch (SceneException e) {
            error = e.getMessage();
        } catch (SceneCancelledException e) {
            return null;
        } catch (RuntimeException e) {
            // A bug, not bad input: say so on the page and keep the window going.
            e.printStackTrace();
            error = "internal error while drawing: " + e;
        }
        return cancelled ? null : new RenderedView(view, seed(), canvas.snapshot(), error, List.copyOf(warnings));
    }
}
