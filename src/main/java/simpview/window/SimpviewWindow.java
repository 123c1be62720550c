package simpview.window;

import simpview.pages.A1Page;
import simpview.pages.A1Pixel;
import simpview.scene.SceneException;
import simpview.scene.simp.SceneDrawer;
import simpview.window.instruments.ComparisonLayer;
import simpview.window.instruments.FolderCheck;
import simpview.window.instruments.Inspector;
import simpview.window.instruments.InspectorPanel;
import simpview.window.render.BackgroundRenderer;
import simpview.window.render.DrawSettings;
import simpview.window.render.Primitives;
import simpview.window.render.RenderJob;
import simpview.window.render.RenderedView;
import simpview.window.render.SceneWatcher;
import simpview.window.render.View;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.Rectangle;
import java.awt.event.ComponentAdapter;
import java.awt.event.ComponentEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.ThreadLocalRandom;
import java.util.stream.Collectors;
import javax.swing.JDialog;
import javax.swing.JFrame;
import simpview.pages.A1Rule;
import simpview.pages.PageContext;
import simpview.pages.Assignment1;
import simpview.pages.Assignment2;
import simpview.pages.ScenePage;
import java.util.function.Consumer;
import simpview.inspect.InspectedScene;
import simpview.inspect.SkippedPrimitives;

/**
 * The window: one page at a time, stepped by clicks and keys, pictures drawn
 * on the render thread. Its parts are the page view, the status and legend
 * strips, the inspector panel and the comparison, with PageCycle (where it is
 * among the pages), InspectedPixel (the pixel the inspector looks at),
 * OverlayToggles, MenusAndKeys and WindowPlacement; every key and menu entry
 * comes to {@link #perform}, which hands it to the part it belongs to. The
 * window itself steps through a drawing and turns it (both change the
 * settings it draws with), and asks for a picture and shows it finished.
 * All methods run on the EDT.
 */
public final class SimpviewWindow {

    private final JFrame frame = new JFrame("simpview");
    private final PageView pageView = new PageView();
    private final LegendStrip legendStrip = new LegendStrip();
    /** The key help (F1), over the whole window. */
    private final HelpOverlay help = new HelpOverlay();
    private final SceneWatcher watcher = new SceneWatcher(this::reload);
    private DrawSettings settings = DrawSettings.WINDOW;
    private final Orbit orbit = new Orbit();
    private final StatusStrip status = new StatusStrip(this::cancel);
    private static final String STEPPING_WORKS_ON =
            "Stepping through the drawing works on scenes (pages 4–8, opened scenes) and the first assignment's pages.";
    /** Where the window is among the pages its keys step through. */
    private final PageCycle pages;
    private final BackgroundRenderer renderer;
    private final FileDialogs dialogs;
    private WindowOptions options;
    /** The check of a folder dropped on the window. */
    private final DroppedFolderCheck folders;
    private RenderedView shown;
    /**
     * Whether {@link #shown} is a frame of a turning drag (drawn untraced): nothing but this window's
     * {@code shown} and its page view hold its image, which goes back to the renderer once another picture is
     * shown ({@link BackgroundRenderer#giveBack}).
     */
    private boolean shownIsDragFrame;
    private RenderJob pending;
    /** The orbit moved while a turned frame was being drawn: draw again when it is done. */
    private boolean turnWaiting;
    /**
     * J while stepping: the picture being drawn for it, first the whole one (who drew a pixel in the picture
     * drawn so far is not who draws it in the end), then, when no primitive draws the pixel, the step it was
     * pressed at again, with {@link #ownerWords} to say once that is shown.
     */
    private RenderJob ownerJob;
    private int stepBeforeOwner;
    private String ownerWords;
    /** What to say once {@link #wordsFor} is shown (what a drop opened and left out), or "". */
    private String wordsWhenShown = "";
    private View wordsFor;
    // compare (issue 15): a picture dropped or opened, compared with the view on screen
    private final ComparisonLayer comparison;
    // the pixel's history, explanation and vertices (issue 20)
    private final InspectorPanel inspectorPanel;
    /** The pixel the inspector looks at, and what is said of it. */
    private final InspectedPixel inspected;
    /** The overlays over the finished picture, and the picture again without them. */
    private final OverlayToggles overlays;
    /** The frame's place on the screen, widened for the inspector panel. */
    private final WindowPlacement placement;

    private SimpviewWindow(WindowOptions options, SceneDrawer drawer) {
        this.options = options;
        this.pages = new PageCycle(options.sceneList(), options.simpDir(), status, this::leaveFor);
        this.renderer = new BackgroundRenderer(drawer, options.threads());
        this.comparison = new ComparisonLayer(frame, pageView::show, status::say,
                legend -> legendStrip.show("compare", legend), () -> this.options.pageContext(),
                renderer::runAfterDrawing); // compared on the render thread, after the picture compared with
        this.inspectorPanel = new InspectorPanel(renderer.library()); // one library: the files each has read
        this.dialogs = new FileDialogs(frame, options.simpDir());
        this.placement = new WindowPlacement(frame, InspectorPanel.WIDTH);
        this.folders = new DroppedFolderCheck(frame, status, () -> this.options.pageContext());
        OnScreen onScreen = new Screen();
        this.overlays = new OverlayToggles(pageView, legendStrip, status, inspectorPanel, onScreen);
        this.inspected = new InspectedPixel(frame, pageView, status, inspectorPanel, comparison, orbit, onScreen);
    }

    /**
     * Opens the window on the scene given, or else on page 1. Call on the EDT.
     * A scene is an extra view: stepping from it goes to the pages, from page 1.
     */
    public static SimpviewWindow open(WindowOptions options) {
        return open(options, SceneDrawer.SIMP);
    }

    public static SimpviewWindow open(WindowOptions options, SceneDrawer drawer) {
        WindowClass.apply();
        SimpviewWindow window = new SimpviewWindow(options, drawer);
        window.build();
        window.show(options.scene().<View>map(View.OfScene::new).orElse(window.pages.current()));
        return window;
    }

    private void build() {
        frame.setName("simpview");
        frame.setIconImages(AppIcon.images());
        frame.setDefaultCloseOperation(JFrame.DISPOSE_ON_CLOSE);
        frame.getContentPane().add(pageView, BorderLayout.CENTER);
        frame.getContentPane().add(status.component(), BorderLayout.SOUTH);
        frame.getContentPane().add(inspectorPanel.component(), BorderLayout.EAST);
        frame.setJMenuBar(MenusAndKeys.menuBar(legendStrip, this::isOn, this::perform));
        frame.setGlassPane(help);
        inspectorPanel.onCopy(status::say);
        frame.setResizable(true);
        // compare (issue 15): a picture dropped; check (issue 21): a folder dropped
        frame.setTransferHandler(new SceneDrop(this::openDropped, comparison::compareWith, this::checkFolder, status::say));
        new PointerGestures(pageView, new Gestures()).attach(pageView);
        pageView.addComponentListener(new ComponentAdapter() {
            @Override
            public void componentResized(ComponentEvent e) {
                inspected.inspectUnderPointer();
            }
        });
        MenusAndKeys.bindKeys(frame.getRootPane(), this::perform);
        frame.addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosed(WindowEvent e) {
                watcher.stop();
                renderer.shutdown();
                inspectorPanel.shutdown();
            }
        });
        frame.pack();
        frame.setMinimumSize(new Dimension(320, 240));
        placement.placeAsOpened();
        frame.setVisible(true);
    }

    /** The view on screen as the inspected pixel and the overlays read it. */
    private final class Screen implements OnScreen {
        @Override
        public RenderedView picture() {
            return shown;
        }

        @Override
        public DrawSettings settings() {
            return settings;
        }

        @Override
        public boolean ownColoursShown() {
            return settings.ownColours() && shown != null
                    && withoutDepthCue(shown.view(), shown.facts().depthStart() == Double.NEGATIVE_INFINITY) == null;
        }

        @Override
        public InspectedScene inspectedScene(Consumer<String> why) {
            return SimpviewWindow.this.inspectedScene(why);
        }
    }

    /** What the pointer does over the page. */
    private final class Gestures implements PointerGestures.Actions {
        @Override
        public void click() {
            next();
        }

        @Override
        public void zoomPanChanged() {
            pageView.repaint();
            inspected.inspectUnderPointer();
        }

        @Override
        public void orbit(int dx, int dy) {
            turn(() -> orbit.drag(dx, dy), false);
        }

        @Override
        public void orbitEnded() {
            if (!settings.record()) {
                turn(() -> { }, true);
            }
        }

        @Override
        public void nearer(int notches) {
            turn(() -> orbit.wheel(notches), true);
        }

        @Override
        public void hover(int x, int y) {
            inspected.pointerAt(x, y);
        }
    }

    /**
     * Whether an entry that turns something on and off ({@link WindowAction#toggle}) is on now: its menu
     * entry ticked.
     */
    boolean isOn(WindowAction action) {
        return switch (action) {
            case DEPTH_VIEW -> settings.depthView();
            case OWN_COLOURS -> settings.ownColours();
            case A1_RULE -> options.a1Rule() == A1Rule.COURSE;
            case BACK_FACES -> overlays.backFacesShown();
            case OVERDRAW -> overlays.overdrawShown(false);
            case DEPTH_FAILURES -> overlays.overdrawShown(true);
            case CULLED -> pageView.skippedShown();
            case WIRE -> pageView.wireShown();
            case COMPARE_HEAT -> comparison.showing() == ComparisonLayer.Showing.HEAT;
            case HIDE_ERROR -> pageView.errorHidden();
            case INSPECTOR -> inspectorPanel.isShown();
            case PIN -> inspected.isPinned();
            case HELP -> help.isVisible();
            default -> throw new IllegalArgumentException(action + " is a toggle without its state here, "
                    + "or no toggle: WindowAction says which");
        };
    }

    /** Does what the table's entry says: a key, its menu entry and the tests all come here. */
    void perform(WindowAction action) {
        actionOf(action).run();
    }

    /**
     * What each entry of the table does. A switch expression with no
     * default, so that a new entry does not build until it has its action.
     */
    private Runnable actionOf(WindowAction action) {
        return switch (action) {
            case OPEN -> () -> chooseScene();
            case COMPARE -> () -> comparison.choosePicture(dialogFolder());
            case SAVE -> () -> save();
            case REDRAW -> () -> drawAgainFromDisk();
            case CLOSE, QUIT -> () -> close();
            case ZOOM_IN -> () -> zoom(z -> z.wheel(pageView.deviceX(pageView.getWidth() / 2.0),
                    pageView.deviceY(pageView.getHeight() / 2.0), -1));
            case ZOOM_OUT -> () -> zoom(z -> z.wheel(pageView.deviceX(pageView.getWidth() / 2.0),
                    pageView.deviceY(pageView.getHeight() / 2.0), 1));
            case ACTUAL_SIZE -> () -> zoom(ZoomPan::actualSize);
            case FIT -> () -> zoom(ZoomPan::fit);
            case CROP -> () -> zoom(ZoomPan::fitPanel);
            case DEPTH_VIEW -> () -> toggleDepthView();
            case OWN_COLOURS -> () -> toggleOwnColours();
            case BACK_FACES -> () -> overlays.toggleBackFaces();
            case OVERDRAW -> () -> overlays.toggleOverdraw(false);
            case DEPTH_FAILURES -> () -> overlays.toggleOverdraw(true);
            case CULLED -> () -> overlays.toggleSkipped();
            case WIRE -> () -> overlays.toggleWire();
            case COMPARE_FLIP -> () -> comparison.flip();
            case COMPARE_HEAT -> () -> comparison.heat();
            case COMPARE_STOP -> () -> comparison.stop();
            case HIDE_ERROR -> () -> pageView.toggleErrorHidden();
            case UNTURN -> () -> unturn();
            case NEXT -> () -> next();
            case PREVIOUS -> () -> previous();
            case FIRST -> () -> pages.end(true);
            case LAST -> () -> pages.end(false);
            case PAGE_1 -> () -> pages.jump(1);
            case PAGE_2 -> () -> pages.jump(2);
            case PAGE_3 -> () -> pages.jump(3);
            case PAGE_4 -> () -> pages.jump(4);
            case PAGE_5 -> () -> pages.jump(5);
            case PAGE_6 -> () -> pages.jump(6);
            case PAGE_7 -> () -> pages.jump(7);
            case PAGE_8 -> () -> pages.jump(8);
            case ASSIGNMENT -> () -> pages.switchAssignment();
            case ASSIGNMENT_1 -> () -> pages.firstAssignment();
            case ASSIGNMENT_2 -> () -> pages.secondAssignment();
            case ASSIGNMENT_3 -> () -> pages.showCoursePages(3);
            case ASSIGNMENT_4 -> () -> pages.showCoursePages(4);
            case A1_RULE -> () -> toggleA1Rule();
            case SEED -> () -> newSeed();
            case CANCEL -> () -> {
                if (help.isVisible()) {
                    help.setVisible(false); // Escape closes what is in front first
                } else {
                    cancel();
                }
            };
            case INSPECTOR -> () -> toggleInspectorPanel();
            case PIN -> () -> inspected.togglePin();
            case GO_TO_PIXEL -> () -> inspected.askForPixel();
            case COPY -> () -> inspected.copyInspected();
            case COPY_CHAIN -> () -> inspected.copyChain();
            case STEP_ON -> () -> step(1);
            case STEP_BACK -> () -> step(-1);
            case STEP_ON_10 -> () -> step(10);
            case STEP_BACK_10 -> () -> step(-10);
            case STEP_ON_100 -> () -> step(100);
            case STEP_BACK_100 -> () -> step(-100);
            case STEP_ON_1000 -> () -> step(1000);
            case STEP_BACK_1000 -> () -> step(-1000);
            case STEP_OFF -> () -> stepOff();
            case GO_TO_PRIMITIVE -> () -> goToPrimitive();
            case STEP_TO_OWNER -> () -> stepToOwner(false);
            case HELP -> () -> help.setVisible(!help.isVisible());
        };
    }

    private void zoom(Consumer<ZoomPan> change) {
        change.accept(pageView.zoomPan());
        pageView.repaint();
        inspected.inspectUnderPointer();
    }

    /** Shows or hides the side panel of the pinned pixel's history (I). */
    private void toggleInspectorPanel() {
        boolean shownNow = inspectorPanel.toggle();
        placement.makeRoomForThePanel(shownNow);
        frame.getContentPane().validate();
        if (shownNow) {
            inspected.refreshPanel();
        }
    }

    /** The view on screen as the inspector replays it, or null (told to {@code why}) when it is not a scene. */
    private InspectedScene inspectedScene(Consumer<String> why) {
        try {
            View view = shown.view();
            if (view instanceof View.OfScene s) {
                return InspectedScene.of(s.file()).withOwnColours(settings.ownColours());
            }
            if (view instanceof View.OfAssignment1Page) {
                why.accept("The overlays are drawn for scenes; on the first assignment's pages the inspector "
                        + "panel (I) lists every write a pixel received, with its coverage.");
                return null;
            }
            int number = ((View.OfPage) view).number();
            return InspectedScene.page(number, options.pageContext())
                    .withOwnColours(settings.ownColours());
        } catch (IllegalArgumentException | SceneException e) {
            why.accept(e.getMessage());
            return null;
        }
    }

    /**
     * Steps the drawing up to the primitive that drew the pixel under the
     * pointer (or the pinned one) in the whole picture. While stepping, the
     * picture on screen is drawn only so far, and who drew a pixel there is
     * not who draws it in the end: the whole picture is drawn first, and
     * {@link #finished} calls this again with {@code wholeDrawn}.
     */
    private void stepToOwner(boolean wholeDrawn) {
        int x = inspected.x();
        int y = inspected.y();
        String pixel = inspected.isPinned() ? "the pinned pixel" : "the pixel under the pointer";
        if (x < 0 || y < 0) {
            // The pointer is off the picture (over the side panel, the status strip, beside the page) and none is pinned.
            nothingToStepTo("There is no pixel under the pointer: point at the picture, or pin a pixel (P, or Shift+G "
                    + "for its coordinates), then press J.", wholeDrawn);
            return;
        }
        int owner = Inspector.ownerAt(shown, x, y);
        if (shown != null && shown.view() instanceof View.OfAssignment1Page page) {
            int[] last = A1Pixel.lastAt(page.number(), shown.seed(), shown.a1Rule(), x, y);
            owner = last == null ? -1 : last[1];
        } else if (settings.stepLimit() >= 0) {
            stepBeforeOwner = settings.stepLimit();
            settings = settings.withStepLimit(-1);
            reload();
            ownerJob = pending;
            status.say("Drawing the whole picture to find the primitive that draws " + pixel + " ...");
            return;
        }
        if (owner < 0) {
            nothingToStepTo("No primitive draws " + pixel + " in the whole picture: nothing to step to.", wholeDrawn);
            return;
        }
        settings = settings.withStepLimit(owner + 1);
        reload();
    }

    /**
     * Says why J has nothing to step to; when the whole picture was drawn to
     * find out ({@code wholeDrawn}), once the drawing is back at the step it
     * was at.
     */
    private void nothingToStepTo(String words, boolean wholeDrawn) {
        if (!wholeDrawn) {
            status.say(words);
            return;
        }
        ownerWords = words + " Back at primitive " + stepBeforeOwner + ".";
        settings = settings.withStepLimit(stepBeforeOwner);
        reload();
        ownerJob = pending;
    }

    /** Asks for a primitive number and steps the drawing to it (G). */
    private void goToPrimitive() {
        if (!steps(requested()) || shown == null) {
            status.say(STEPPING_WORKS_ON);
            return;
        }
        int total = stepsInAll();
        if (total == 0) {
            status.say("There is no primitive to go to: this picture has none.");
            return;
        }
        String answer = QuestionAfterKey.ask(frame, "Go to primitive (1 to " + total + "):", 'g');
        if (answer == null) {
            return;
        }
        try {
            int n = Integer.parseInt(answer.strip());
            if (n < 1 || n > total) {
                status.say("There is no primitive " + n + ": this picture has 1 to " + total + ".");
                return;
            }
            settings = settings.withStepLimit(n);
            reload();
        } catch (NumberFormatException e) {
            status.say("'" + answer + "' is not a primitive number.");
        }
    }

    /**
     * Places the frame as it would open on a screen whose usable area is
     * {@code usable} (for tests of a small screen on a larger one).
     */
    void placeWithin(Rectangle usable) {
        placement.placeWithin(usable);
    }

    /**
     * Pins the pixel "x, y" (the panel's coordinates, x right and y up; on
     * the first assignment's pages the page's) and brings it into view; says
     * why not when the text is not a pixel.
     */
    void goToPixel(String answer) {
        inspected.goToPixel(answer);
    }

    /** Where the compare dialog opens: the shown scene's folder, else the course's pages' folder. */
    Path dialogFolder() {
        Path folder = shownSceneFolder();
        return folder != null ? folder : options.simpDir();
    }

    /** The folder of the scene on screen (an opened scene's, a course page's), or null on the pages. */
    private Path shownSceneFolder() {
        if (shown != null && shown.view() instanceof View.OfScene scene) {
            return scene.file().toAbsolutePath().getParent();
        }
        if (shown != null && shown.view() instanceof View.OfPage && !shown.facts().files().isEmpty()) {
            return shown.facts().files().get(0).toAbsolutePath().getParent(); // pages 4 to 8: their scene's folder
        }
        return null;
    }

    private void toggleDepthView() {
        if (!settings.depthView() && shown != null && shown.view() instanceof View.OfAssignment1Page) {
            status.say("The first assignment's pages have no depths to show: their panels are drawn without a "
                    + "z-buffer (SPEC Part 3).");
            return;
        }
        settings = settings.withDepthView(!settings.depthView());
        if (settings.depthView() && !settings.record() && (pending != null ? !pending.settings().keepsDepths()
                : shown != null && shown.facts().depths() == null)) {
            reload(); // a frame of a turning drag, drawn or being drawn without its depths: drawn again with them
        }
        overlays.showPicture();
        inspected.inspect();
    }

    /**
     * C: a depth-cued scene (pages 4 to 8, an opened scene drawn by SPEC Part 1) drawn in its vertices' own
     * colours, without the depth cue, or with it again. The setting stays for the views shown after; on a view
     * without a depth cue the picture stays as it is, and the status line says why.
     */
    private void toggleOwnColours() {
        settings = settings.withOwnColours(!settings.ownColours());
        boolean lit = pending != null ? pending.lit()
                : shown != null && shown.facts().depthStart() == Double.NEGATIVE_INFINITY;
        String noCue = withoutDepthCue(requested(), lit);
        if (noCue != null) {
            // Nothing to draw again, nor a drawing (of a lit scene still being drawn) to start over.
            inspected.inspect();
            status.say((settings.ownColours() ? "Own colours: on for depth-cued scenes. " : "Depth cue: on again for "
                    + "depth-cued scenes. ") + noCue + ", so it looks the same either way.");
            return;
        }
        status.say(settings.ownColours()
                ? "Own colours: scenes show their vertices' colours (white where none), without the depth cue."
                : "Depth cue: scenes are coloured by depth again.");
        reload();
    }

    /**
     * Why own colours (C) leave {@code view} as it is, or null for a depth-cued scene, the one kind of view they
     * change: pages 1 to 3 and the first assignment's pages are drawn in their own colours, without a depth cue,
     * and a lit scene ({@code lit}: its z-buffer starts at -infinity, or its job says so while it is drawn) is
     * coloured by its camera, lights and fog (SPEC Part 2).
     */
    private static String withoutDepthCue(View view, boolean lit) {
        if (view instanceof View.OfAssignment1Page) {
            return "The first assignment's pages have no depth cue";
        }
        if (view instanceof View.OfPage page && !(Assignment2.page(page.number()) instanceof ScenePage)) {
            return "Page " + page.number() + " has no depth cue (its triangles are drawn in their vertices' own "
                    + "colours)";
        }
        if (lit) {
            return "This scene is lit (its camera, lights and fog make its colours, SPEC Part 2)";
        }
        return null;
    }

    /** Whether the view is drawn from a scene file (pages 4 to 8, an opened scene): what stepping and turning work on. */
    private boolean isScene(View view) {
        return view instanceof View.OfScene
                || view instanceof View.OfPage page && Assignment2.page(page.number()) instanceof ScenePage;
    }

    /** Whether the drawing of the view can be stepped: a scene's, or a first-assignment page's (SPEC Part 3). */
    private boolean steps(View view) {
        return isScene(view) || view instanceof View.OfAssignment1Page;
    }

    /**
     * How many steps draw the whole view on screen: a scene's primitives, or
     * a first-assignment page's lines or triangles, every panel stepping
     * together (one more line of each line panel, one more triangle of each
     * scene, a step).
     */
    private int stepsInAll() {
        if (requested() instanceof View.OfAssignment1Page page) {
            return Assignment1.page(page.number()).steps(options.pageContext());
        }
        return shown == null ? 0 : shown.facts().primitives().size();
    }

    /** Steps the drawing by {@code by} primitives (the first step from the whole picture shows primitive 1). */
    private void step(int by) {
        if (!steps(requested())) {
            status.say(STEPPING_WORKS_ON);
            return;
        }
        int total = stepsInAll();
        int from = settings.stepLimit() >= 0 ? settings.stepLimit() : by > 0 ? 0 : total + 1;
        int limit = Math.max(1, Math.min(Math.max(total, 1), from + by));
        settings = settings.withStepLimit(limit);
        reload();
    }

    private void stepOff() {
        if (settings.stepLimit() >= 0) {
            settings = settings.withStepLimit(-1);
            reload();
        }
    }

    /**
     * A turning drag or a move nearer: a depth-cued scene's world turns about
     * the view volume's centre, before the depth cue; a lit scene's camera
     * about the centre of what the unturned view showed. While a turned
     * frame is being drawn, further moves only change what the next frame
     * shows: it is drawn when this one is done, so frames never queue up.
     * The frames of a drag are drawn without the inspector's record (who
     * drew each pixel), which cost 1-2.5 ms of a frame as measured; the
     * frame drawn when the drag ends has it again ({@code record}).
     */
    private void turn(Runnable move, boolean record) {
        if (!isScene(requested())) {
            status.say("Turning works on scenes: pages 4–8 and opened scenes.");
            return;
        }
        if (!orbit.turned() && shown != null && shown.facts().shownCentre() != null) {
            orbit.about(shown.facts().shownCentre());
        }
        move.run();
        settings = settings.withViewTurn(orbit.matrix()).withRecord(record);
        if (pending != null && pending.settings().viewTurn() != null) {
            turnWaiting = true;
        } else {
            reload();
        }
    }

    private void unturn() {
        orbit.reset();
        if (settings.viewTurn() != null || !settings.record()) {
            settings = settings.withViewTurn(null).withRecord(true);
            reload();
        }
    }

    /** Leaving a view for another: its stepping, its turn and its pin are left behind. */
    private void leaveFor(View view) {
        forgetViewState();
        show(view);
    }

    /** Leaving a view leaves its stepping and its turn. */
    private void forgetViewState() {
        orbit.reset();
        settings = settings.withStepLimit(-1).withViewTurn(null).withRecord(true);
        inspected.unpin();
    }

    /** The line under the page while stepping: which primitive, from where; and its outline on the page. */
    private void showStep(RenderedView result) {
        int limit = settings.stepLimit();
        if (result.view() instanceof View.OfAssignment1Page page) {
            A1Page a1 = Assignment1.page(page.number());
            PageContext context = options.pageContext().withSeed(result.seed());
            if (limit < 1) {
                return; // not stepping: the magnifier's marks, if any, are the inspector's
            }
            int step = Math.min(limit, a1.steps(context));
            status.say(a1.describeStep(context, step) + "   (] next · [ back · Shift: ten · \\ all)");
            pageView.outline(null);
            pageView.marks(a1.stepMarks(context, step));
            return;
        }
        Primitives primitives = result.facts().primitives();
        if (limit < 1) {
            pageView.outline(null);
            return;
        }
        // The scene's file may have changed while stepping: what the line says is what was drawn. A save with an
        // error drew what came before it, and the step stays where it was for when the file is mended.
        if (result.error() != null && limit > primitives.size()) {
            pageView.outline(null);
            return;
        }
        if (primitives.size() == 0) {
            settings = settings.withStepLimit(-1);
            pageView.outline(null);
            status.say("Stepping ended: the scene has no primitives now.");
            return;
        }
        String shrank = "";
        if (limit > primitives.size()) {
            shrank = " (the scene has " + primitives.size() + " now: stepping was at " + limit + ")";
            limit = primitives.size();
            settings = settings.withStepLimit(limit);
        }
        status.say("primitive " + limit + " of " + primitives.size() + ", " + primitives.describe(limit - 1) + shrank
                + "   (] next · [ back · Shift: ten · \\ all)");
        pageView.outline(Inspector.toImage(primitives.outline(limit - 1)));
    }

    /** Draws what is on screen again (F5, a save of one of its files), keeping zoom and pan. */
    void reload() {
        show(requested());
    }

    /** The view drawn again with nothing kept from before: every file it reads is read from disk afresh. */
    private void drawAgainFromDisk() {
        renderer.forgetFiles();
        inspectorPanel.forgetFiles();
        reload();
    }

    /** The next page of the assignment on show (after its last comes its first). */
    void next() {
        pages.next();
    }

    void previous() {
        pages.previous();
    }

    /** What a dropped folder does from now on: the command line gives {@code simpview check}. Call on the EDT. */
    public SimpviewWindow checkFoldersWith(FolderCheck check) {
        folders.checkWith(check);
        return this;
    }

    /** A folder dropped (issue 21): checked as {@code simpview check FOLDER}, on its own thread. */
    void checkFolder(Path folder) {
        folders.check(folder);
    }

    /** The table of the last folder checked, or null: for the tests. */
    String lastCheck() {
        return folders.lastCheck();
    }

    /** The window of the dropped folders' tables, or null before the first. */
    JDialog checkTable() {
        return folders.tableWindow();
    }

    /** Shows a scene file as an extra view; stepping keys go back to the pages. */
    void openScene(Path file) {
        pages.openScene(file);
    }

    /**
     * The .simp files of a drop, in the order given: one is opened as {@link #openScene} opens it; several become
     * the first pages, before the eight. Once the first is shown, the status line says so and names what the drop
     * left out ({@code leftOut}, "" for nothing).
     */
    void openDropped(List<Path> scenes, String leftOut) {
        String opened = "";
        if (scenes.size() == 1) {
            pages.openScene(scenes.get(0));
        } else {
            pages.openScenes(scenes);
            opened = "Opened the " + scenes.size() + " scenes dropped as the first pages, before the eight: "
                    + scenes.stream().map(scene -> scene.getFileName().toString()).collect(Collectors.joining(", "))
                    + " (→ steps through them).";
        }
        wordsWhenShown = (opened + " " + leftOut).strip();
        wordsFor = requested();
    }

    /** Switches the first assignment between SPEC's rule and the course's pictures' (A1Rule); A1 pages are drawn again. */
    private void toggleA1Rule() {
        A1Rule rule = options.a1Rule() == A1Rule.SPEC ? A1Rule.COURSE : A1Rule.SPEC;
        options = options.withA1Rule(rule);
        if (requested() instanceof View.OfAssignment1Page page) {
            show(page);
        }
        status.say("The first assignment's Bresenham panels and fills now follow " + rule.label() + ".");
    }

    /** A fresh seed for pages 1 to 3; redraws the page if it is one of them. */
    void newSeed() {
        long seed = options.seed();
        while (seed == options.seed()) {
            seed = ThreadLocalRandom.current().nextInt(1, 100_000);
        }
        options = options.withSeed(seed);
        if (requested() instanceof View.OfPage page && Assignment2.page(page.number()).usesSeed()) {
            show(page);
        } else if (requested() instanceof View.OfAssignment1Page page && Assignment1.page(page.number()).usesSeed()) {
            show(page);
        } else {
            status.say("Seed is now " + seed + ": it changes pages 1–3 only, not this one.");
        }
    }

    private View requested() {
        return pending != null ? pending.view() : shown == null ? pages.current() : shown.view();
    }

    /** Draws the view on the render thread; the page on screen stays until the new one is finished. */
    private void show(View view) {
        if (pending != null) {
            pending.cancel();
        }
        turnWaiting = false;
        pending = new RenderJob(view, options.pageContext(), settings);
        status.watch(pending);
        renderer.submit(pending, this::finished);
    }

    /**
     * Whether two views show the same page or scene: a scene file however its path is written (relative as
     * typed at start, absolute from Ctrl+O or a drop); scenes of one name in two folders are two. Told without
     * asking the file system, on the event thread.
     */
    static boolean sameView(View one, View other) {
        if (one instanceof View.OfScene a && other instanceof View.OfScene b) {
            return a.file().toAbsolutePath().normalize().equals(b.file().toAbsolutePath().normalize());
        }
        return one.equals(other);
    }

    private void finished(RenderJob job, RenderedView result) {
        if (job != pending) {
            if (result != null) {
                renderer.giveBack(result.image()); // overtaken by a newer request: shown to no one
            }
            return; // cancelled or overtaken by a newer request
        }
        pending = null;
        if (result == null) {
            status.sayHints();
            return;
        }
        if (shown != null && !sameView(shown.view(), result.view())) {
            // Another page or scene opens fitted, as in an image viewer; the same one drawn again (a save, F5, a
            // new seed, a turn) keeps zoom and pan, to compare before and after.
            pageView.zoomPan().refit();
        }
        RenderedView before = shown;
        boolean beforeIsDragFrame = shownIsDragFrame;
        shown = result;
        shownIsDragFrame = !job.settings().record();
        overlays.showPicture();
        if (before != null && beforeIsDragFrame) {
            renderer.giveBack(before.image()); // the page view shows the new picture now
        }
        String coursePage = pages.coursePageOf(result.view());
        String shows = coursePage != null ? coursePage + (result.error() == null ? "" : " — error") : result.shows();
        frame.setTitle(RenderedView.TITLE_START + shows);
        pageView.describe(shows);
        watcher.watch(result.facts().files(), job.versionsAsRead());
        status.forgetLastPixel();
        inspected.followPointer();
        inspected.inspect();
        status.say(result.warnings().isEmpty() ? status.hints() : "Warning: " + String.join("; ", result.warnings()));
        if (coursePage != null && result.warnings().isEmpty()) {
            status.say(coursePage + " · → ← Home End 1-8: its pages · Alt+2: the eight pages");
        }
        if (orbit.turned()) {
            status.say(orbit.describe());
        }
        if (!wordsWhenShown.isEmpty()) {
            if (result.view().equals(wordsFor)) {
                status.say(wordsWhenShown);
            }
            wordsWhenShown = "";
        }
        showStep(result);
        if (job.settings().record()) {
            // A turning drag's frames (untraced) leave the panel and the comparison as they are: the panel's
            // history is the unturned view's, which the turn does not change, and a replay a frame (25 ms for A3
            // pageI on this project's 2-core machine) would take a core from the drawing; a comparison (with
            // its search for a mistake of the whole panel, tens of ms) would hold the render thread, and with it
            // the next frame. The traced frame after the drag does both.
            inspected.refreshPanel();
            comparison.viewShown(result); // compare (issue 15)
        }
        if (turnWaiting) {
            reload();
        } else if (job == ownerJob) {
            ownerJob = null;
            if (ownerWords != null) {
                status.say(ownerWords);
                ownerWords = null;
            } else {
                stepToOwner(true);
            }
        }
    }

    /** Stops the picture being drawn; the one on screen stays, and so does its place among the pages. */
    void cancel() {
        if (pending == null) {
            return;
        }
        pending.cancel();
        pending = null;
        if (shown != null) {
            pages.stayAt(shown.view());
        }
        status.say("Cancelled: the page on screen is unchanged.");
    }

    private void chooseScene() {
        dialogs.chooseScene(shownSceneFolder()).ifPresent(this::openScene);
    }

    private void save() {
        if (shown != null) {
            dialogs.save(shown).ifPresent(file -> status.say("Saved " + file));
        }
    }

    void close() {
        watcher.stop();
        frame.dispose();
    }

    // For tests: what is on screen and what is going on.

    JFrame frame() {
        return frame;
    }

    SceneWatcher watcher() {
        return watcher;
    }

    PageView pageView() {
        return pageView;
    }

    StatusStrip status() {
        return status;
    }

    /** What the culled and clipped-away overlay shows, or null while it is off. */
    SkippedPrimitives.Found skippedShown() {
        return overlays.skippedShown();
    }

    LegendStrip legendStrip() {
        return legendStrip;
    }

    InspectorPanel inspectorPanel() {
        return inspectorPanel;
    }

    /** How many polygons the back-face overlay tints while it is shown, else -1. */
    int backFacesShownCount() {
        return overlays.backFacesShownCount();
    }

    /** The step shown: how many primitives are drawn, or -1 for the whole picture. */
    int stepLimit() {
        return settings.stepLimit();
    }

    /** The overdraw overlay's largest count while it is shown, else -1. */
    int overdrawShownMax() {
        return overlays.overdrawShownMax();
    }

    // compare (issue 15)
    ComparisonLayer comparison() {
        return comparison;
    }

    /** Whether the render thread may draw the next picture on {@code image}: given back and not taken yet. */
    boolean mayBeDrawnOn(BufferedImage image) {
        return renderer.holdsSpare(image);
    }

    RenderedView shown() {
        return shown;
    }

    boolean busy() {
        return pending != null;
    }

    /** Lines the picture being drawn has read so far, or -1 when nothing is being drawn. */
    long linesReadSoFar() {
        return pending == null ? -1 : pending.linesSoFar();
    }
}
