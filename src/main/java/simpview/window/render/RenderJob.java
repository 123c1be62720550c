package simpview.window.render;

import simpview.scene.simp.SceneDrawer;
import simpview.scene.FileVersion;
import simpview.scene.simp.SceneLibrary;
import simpview.scene.simp.ScenePipeline;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import simpview.geometry.Matrix4;
import simpview.pages.PageContext;
import simpview.stage.PrimitiveLog;
import simpview.stage.PrimitiveTrace;
import simpview.pages.PageRenderer;
import simpview.pages.Assignment1;
import simpview.pages.Assignment2;
import simpview.pages.ScenePage;
import simpview.scene.SceneException;
import simpview.surface.Provenance;
import simpview.scene.simp.SceneCancelledException;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.Setting;
import simpview.surface.PageCanvas;

/**
 * One picture to draw on the render thread. It is also the scene's monitor:
 * the window reads its progress and cancels it from the EDT, so its shared
 * state is volatile or thread-safe.
 */
public final class RenderJob implements SceneMonitor {

    private final View view;
    private final PageContext context;
    private final DrawSettings settings;
    private final long createdNanos = System.nanoTime();
    private final List<String> warnings = new CopyOnWriteArrayList<>();
    private volatile long linesRead;
    private volatile boolean cancelled;
    private volatile double topFileShare = -1;
    /** Whether the scene is drawn by the lit rules, told by its pipeline on the render thread as it draws. */
    private volatile boolean lit;
    /** Set on the render thread when the job starts; read there, and by the EDT only after the job is done. */
    private PrimitiveLog trace;
    /** A lit scene's centre of what was shown, in camera space, when told; the render thread's, like trace. */
    private double[] shownCentre;
    /** The files the scene read or looked for, as its pipeline told them; the render thread's, like trace. */
    private List<Path> reached = List.of();
    /** How the scene read them (stamps, checksums); set on the render thread, read on the EDT once the job is done. */
    private volatile List<FileVersion> versionsAsRead = List.of();

    public RenderJob(View view, PageContext context) {
        this(view, context, DrawSettings.PLAIN);
    }

    public RenderJob(View view, PageContext context, DrawSettings settings) {
        this.view = view;
        this.context = context.withMonitor(this).withOwnColours(settings.ownColours());
        this.settings = settings;
    }

    public DrawSettings settings() {
        return settings;
    }

    public View view() {
        return view;
    }

    long seed() {
        return context.seed();
    }

    public long millisSinceCreated() {
        return (System.nanoTime() - createdNanos) / 1_000_000;
    }

    public long linesSoFar() {
        return linesRead;
    }

    /** The share of the scene's top file read so far, 0 to 1, or -1 before the scene tells (for the progress bar). */
    public double topFileShare() {
        return topFileShare;
    }

    public void cancel() {
        cancelled = true;
    }

    @Override
    public boolean cancelled() {
        return cancelled;
    }

    @Override
    public void turnedLit() {
        lit = true;
    }

    /**
     * Whether the scene being drawn is lit, as far as it has been read: its camera, lights and fog colour it (SPEC
     * Part 2), own colours or not; false until its pipeline tells, and for a depth-cued scene or a page.
     */
    public boolean lit() {
        return lit;
    }

    @Override
    public void linesRead(long lines) {
        linesRead = lines;
    }

    @Override
    public void topFileRead(double share) {
        topFileShare = share;
    }

    @Override
    public void warning(String message) {
        warnings.add(message);
    }

    /** A setting as the command line that opened the window names it (its key, where the window has one). */
    @Override
    public String nameOf(Setting setting) {
        return setting.option();
    }

    @Override
    public PrimitiveTrace trace() {
        return trace;
    }

    @Override
    public Matrix4 viewTurn() {
        return settings.viewTurn();
    }

    @Override
    public void versionsAsRead(List<FileVersion> versions) {
        versionsAsRead = List.copyOf(versions);
    }

    /**
     * {@link PageFacts#files}' files as the scene read them: stamps, and checksums of the bytes read (empty for a
     * page that reads none).
     */
    public List<FileVersion> versionsAsRead() {
        return versionsAsRead;
    }

    @Override
    public void reached(List<Path> files) {
        reached = List.copyOf(files);
    }

    @Override
    public void shownCentre(double[] xyz) {
        shownCentre = xyz.clone();
    }

    /**
     * Draws on the render thread's canvas and returns the result, or null
     * when the job was cancelled; the scene files come from, and are kept in,
     * the render thread's {@code library}. The picture's image is the
     * canvas's own, handed off ({@link PageCanvas#handOff}); the canvas goes
     * on on an image of {@code spares}, or a new one.
     */
    public RenderedView run(PageRenderer renderer, SceneDrawer drawer, SceneLibrary library,
            Provenance provenance, SpareImages spares) {
        if (cancelled) {
            return null;
        }
        PageCanvas canvas = renderer.canvas();
        canvas.recordProvenance(settings.record() ? provenance : null);
        trace = settings.record() || settings.stepLimit() >= 0
                ? new PrimitiveLog(settings.record() ? provenance : null, settings.stepLimit()) : null;
        String error = null;
        boolean drewSomething = true;
        try {
            if (view instanceof View.OfPage page) {
                renderer.render(page.number(), context.withLibrary(library));
            } else if (view instanceof View.OfAssignment1Page page) {
                canvas.clear();
                // Stepping: every panel's first stepLimit lines or triangles.
                Assignment1.page(page.number()).drawSteps(canvas, context,
                        settings.stepLimit() >= 0 ? settings.stepLimit() : Integer.MAX_VALUE);
            } else {
                canvas.clear();
                drawer.draw(((View.OfScene) view).file(), canvas,
                        ScenePipeline.Options.byCommands(library).withOwnColours(settings.ownColours()), this);
            }
        } catch (SceneException e) {
            error = e.getMessage();
            drewSomething = e.line() > 0;
        } catch (SceneCancelledException e) {
            return null;
        } catch (RuntimeException e) {
            // A bug, not bad input: say so on the page and keep the window going.
            e.printStackTrace();
            error = "internal error while drawing: " + e;
        }
        if (cancelled) {
            return null;
        }
        boolean keepsOwners = !(view instanceof View.OfPage page) || Assignment2.page(page.number()).keepsOwners();
        PageFacts facts = new PageFacts(settings.keepsDepths() ? canvas.zbuffer().copyDepths() : null,
                canvas.zbuffer().farthest(),
                canvas.provenance() == null || !keepsOwners ? null : canvas.provenance().copyOwners(),
                primitives(), filesRead(), drewSomething, shownCentre);
        canvas.recordProvenance(null);
        return new RenderedView(view, seed(), context.a1Rule(), canvas.handOff(spares.take()), error,
                List.copyOf(warnings), facts);
    }

    /** What each primitive drawn was, in drawing order. */
    private Primitives primitives() {
        if (view instanceof View.OfPage page) {
            List<String> names = Assignment2.page(page.number()).primitiveNames(context);
            if (!names.isEmpty()) {
                return Primitives.named(names);
            }
        }
        return trace == null ? Primitives.NONE : Primitives.logged(trace);
    }

    /** The scene file the view reads, or null for a page that is not a scene. */
    private Path topFile() {
        if (view instanceof View.OfScene scene) {
            return scene.file();
        }
        if (view instanceof View.OfAssignment1Page) {
            return null;
        }
        return Assignment2.page(((View.OfPage) view).number()) instanceof ScenePage page ? page.file(context) : null;
    }

    /** The scene files this picture read or looked for: what to watch for a save. */
    private List<Path> filesRead() {
        Path top = topFile();
        if (top == null) {
            return List.of();
        }
        return reached.isEmpty() ? List.of(top) : reached; // not read at all: watch for it to appear
    }
}
