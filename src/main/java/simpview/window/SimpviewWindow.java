package simpview.window;

import simpview.scene.simp.SceneDrawer;
import simpview.window.instruments.ComparisonLayer;
import simpview.window.instruments.DepthPicture;
import simpview.window.instruments.FolderCheck;
import simpview.window.instruments.Inspector;
import simpview.window.instruments.InspectorPanel;
import simpview.window.render.BackgroundRenderer;
import simpview.window.render.DrawSettings;
import simpview.window.render.PageFacts;
import simpview.window.render.Primitives;
import simpview.window.render.RenderJob;
import simpview.window.render.RenderedView;
import simpview.window.render.SceneWatcher;
import simpview.window.render.View;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.Font;
import java.awt.GraphicsConfiguration;
import java.awt.Insets;
import java.awt.Rectangle;
import java.awt.Toolkit;
import java.awt.datatransfer.StringSelection;
import java.awt.event.ActionEvent;
import java.awt.event.ComponentAdapter;
import java.awt.event.ComponentEvent;
import java.awt.event.KeyEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.nio.file.Path;
import java.util.concurrent.ThreadLocalRandom;
import javax.swing.AbstractAction;
import javax.swing.InputMap;
import javax.swing.JComponent;
import javax.swing.JDialog;
import javax.swing.JFrame;
import javax.swing.JScrollPane;
import javax.swing.JTextArea;
import javax.swing.KeyStroke;
import javax.swing.SwingUtilities;
import simpview.pages.PageContext;
import simpview.pages.Assignment1;
import simpview.pages.PageStepper;
import simpview.pages.Assignment2;
import simpview.pages.ScenePage;

/**
 * The window: one page at a time, stepped by clicks and keys, pictures drawn
 * on the render thread. All methods run on the EDT.
 */
public final class SimpviewWindow {

    private final JFrame frame = new JFrame("simpview");
    private final PageView pageView = new PageView();
    private final SceneWatcher watcher = new SceneWatcher(this::reload);
    private DrawSettings settings = DrawSettings.WINDOW;
    private final Orbit orbit = new Orbit();
    private boolean depthView;
    /** The image pixel under the pointer, and the pinned one (x = -1: none). */
    private int hoverX = -1;
    private int hoverY = -1;
    private int pinnedX = -1;
    private int pinnedY = -1;
    private final StatusStrip status = new StatusStrip(this::cancel);
    private static final String STEPPING_WORKS_ON =
            "Stepping through the drawing works on scenes (pages 4–8, opened scenes) and the first assignment's pages.";
    private final PageStepper stepper;
    /** The first assignment's page on show (1 to 5), or 0 while the window steps through the eight pages and scenes. */
    private int assignment1Page;
    private final BackgroundRenderer renderer;
    private final FileDialogs dialogs;
    private WindowOptions options;
    private String lastCheck;
    private FolderCheck folderCheck = FolderCheck.NONE;
    private RenderedView shown;
    private RenderJob pending;
    /** The orbit moved while a turned frame was being drawn: draw again when it is done. */
    private boolean turnWaiting;
    // compare (issue 15): a picture dropped or opened, compared with the view on screen
    private final ComparisonLayer comparison = new ComparisonLayer(frame, pageView::show, status::say);
    // the pixel's history, explanation and vertices (issue 20)
    private final InspectorPanel inspectorPanel = new InspectorPanel();
    private boolean overdrawShown;
    private boolean backFacesShown;
    private int backFaces = -1;
    private int overdrawMax = -1;

    private SimpviewWindow(WindowOptions options, SceneDrawer drawer) {
        this.options = options;
        this.stepper = new PageStepper(options.sceneList().size());
        this.renderer = new BackgroundRenderer(drawer, options.threads());
        this.dialogs = new FileDialogs(frame, options.simpDir());
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
        window.show(options.scene().<View>map(View.OfScene::new).orElse(window.viewAt(window.stepper.current())));
        return window;
    }

    private void build() {
        frame.setName("simpview");
        frame.setIconImages(AppIcon.images());
        frame.setDefaultCloseOperation(JFrame.DISPOSE_ON_CLOSE);
        frame.getContentPane().add(pageView, BorderLayout.CENTER);
        frame.getContentPane().add(status.component(), BorderLayout.SOUTH);
        frame.getContentPane().add(inspectorPanel.component(), BorderLayout.EAST);
        frame.setResizable(true);
        // compare (issue 15): a picture dropped; check (issue 21): a folder dropped
        frame.setTransferHandler(new SceneDrop(this::openScene, comparison::compareWith, this::checkFolder, status::say));
        new PointerGestures(pageView.zoomPan(), new Gestures()).attach(pageView);
        pageView.addComponentListener(new ComponentAdapter() {
            @Override
            public void componentResized(ComponentEvent e) {
                inspect();
            }
        });
        bindKeys();
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
        frame.setBounds(WindowPlacement.within(frame.getSize(), usableScreen()));
        frame.setVisible(true);
    }

    /** The screen's area for windows: without taskbars and docks. */
    private Rectangle usableScreen() {
        GraphicsConfiguration screen = frame.getGraphicsConfiguration();
        Rectangle bounds = screen.getBounds();
        Insets taken = Toolkit.getDefaultToolkit().getScreenInsets(screen);
        return new Rectangle(bounds.x + taken.left, bounds.y + taken.top,
                bounds.width - taken.left - taken.right, bounds.height - taken.top - taken.bottom);
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
            inspect();
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
            ZoomPan zoomPan = pageView.zoomPan();
            hoverX = x < 0 ? -1 : zoomPan.imageX(x);
            hoverY = y < 0 ? -1 : zoomPan.imageY(y);
            inspect();
        }
    }

    private void bindKeys() {
        bind("next", this::next, "RIGHT", "SPACE", "PAGE_DOWN", "KP_RIGHT");
        bind("previous", this::previous, "LEFT", "PAGE_UP", "KP_LEFT");
        bind("first", () -> end(true), "HOME");
        bind("last", () -> end(false), "END");
        for (int n = 1; n <= Assignment2.COUNT; n++) {
            int page = n;
            bind("page" + n, () -> jump(page), String.valueOf(n), "NUMPAD" + n);
        }
        bind("assignment", this::switchAssignment, "A");
        bind("seed", this::newSeed, "R");
        bind("cancel", this::cancel, "ESCAPE");
        bind("fit", () -> zoom(ZoomPan::fit), "F");
        bind("actual size", () -> zoom(ZoomPan::actualSize), "Z");
        bind("zoom in", () -> zoom(z -> z.wheel(pageView.getWidth() / 2.0, pageView.getHeight() / 2.0, -1)),
                "typed +", "typed =");
        bind("zoom out", () -> zoom(z -> z.wheel(pageView.getWidth() / 2.0, pageView.getHeight() / 2.0, 1)),
                "typed -");
        bind("depth view", this::toggleDepthView, "D");
        bind("pin", this::togglePin, "P");
        bind("own colours", this::toggleOwnColours, "C");
        bind("hide error", () -> pageView.toggleErrorHidden(), "H");
        bind("help", () -> pageView.toggleHelp(), "F1");
        bind("redraw", this::reload, "F5");
        bind("step on", () -> step(1), "CLOSE_BRACKET");
        bind("step back", () -> step(-1), "OPEN_BRACKET");
        bind("step on ten", () -> step(10), "shift CLOSE_BRACKET");
        bind("step back ten", () -> step(-10), "shift OPEN_BRACKET");
        bind("step off", this::stepOff, "BACK_SLASH");
        bind("step on hundred", () -> step(100), "ctrl CLOSE_BRACKET");
        bind("step back hundred", () -> step(-100), "ctrl OPEN_BRACKET");
        bind("step on thousand", () -> step(1000), "ctrl shift CLOSE_BRACKET");
        bind("step back thousand", () -> step(-1000), "ctrl shift OPEN_BRACKET");
        bind("step to the pixel's primitive", this::stepToOwner, "J");
        bind("go to primitive", this::goToPrimitive, "G");
        bind("inspector panel", this::toggleInspectorPanel, "I");
        bind("overdraw", () -> toggleOverdraw(false), "V");
        bind("depth-test failures", () -> toggleOverdraw(true), "shift V");
        bind("back faces", this::toggleBackFaces, "K");
        bind("unturn", this::unturn, "O");
        int menu = Toolkit.getDefaultToolkit().getMenuShortcutKeyMaskEx();
        bindStroke("save", this::save, KeyStroke.getKeyStroke(KeyEvent.VK_S, menu));
        bindStroke("open", this::chooseScene, KeyStroke.getKeyStroke(KeyEvent.VK_O, menu));
        comparison.bindKeys((name, action, stroke) -> bindStroke(name, action, KeyStroke.getKeyStroke(stroke))); // compare (issue 15)
        bindStroke("copy", this::copyInspected, KeyStroke.getKeyStroke(KeyEvent.VK_C, menu));
        bindStroke("quit", this::close, KeyStroke.getKeyStroke(KeyEvent.VK_Q, menu));
        bindStroke("close", this::close, KeyStroke.getKeyStroke(KeyEvent.VK_W, menu));
    }

    private void zoom(java.util.function.Consumer<ZoomPan> change) {
        change.accept(pageView.zoomPan());
        pageView.repaint();
        inspect();
    }

    /** The status line's inspector: the pinned pixel, else the one under the pointer, and the zoom. */
    private void inspect() {
        int x = pinnedX >= 0 ? pinnedX : hoverX;
        int y = pinnedX >= 0 ? pinnedY : hoverY;
        String pixel = x < 0 || y < 0 ? null : Inspector.describe(shown, x, y);
        String zoom = pageView.zoomPan().describe() + (depthView ? " · depth view" : "")
                + (settings.ownColours() ? " · own colours" : "");
        status.inspect(pixel == null ? zoom : (pinnedX >= 0 ? "pinned · " : "") + pixel + " · " + zoom);
        if (settings.stepLimit() < 0) {
            boolean magnified = PixelGrid.shows(pageView.zoomPan());
            pageView.outline(magnified ? Inspector.outlineAt(shown, x, y) : null);
            pageView.marks(magnified ? Inspector.marksAt(shown, x, y) : null);
        }
    }

    private void togglePin() {
        if (pinnedX >= 0) {
            pinnedX = pinnedY = -1;
        } else if (hoverX >= 0 && hoverY >= 0) {
            pinnedX = hoverX;
            pinnedY = hoverY;
        } else {
            status.say("Move the pointer over a pixel, then press P to pin it.");
        }
        pageView.pin(pinnedX, pinnedY);
        inspect();
        refreshPanel();
    }

    /** Shows or hides the side panel of the pinned pixel's history (I). */
    private void toggleInspectorPanel() {
        boolean shownNow = inspectorPanel.toggle();
        frame.getContentPane().validate();
        if (shownNow) {
            refreshPanel();
        }
    }

    /** The side panel, when shown: the pinned pixel's history in the view on screen, replayed. */
    private void refreshPanel() {
        if (!inspectorPanel.isShown()) {
            return;
        }
        if (pinnedX < 0 || shown == null) {
            inspectorPanel.say("Pin a pixel (P) to see every write it received, how its colour was made, and its "
                    + "primitive's vertices.");
            return;
        }
        int x = pinnedX - simpview.surface.PageCanvas.MARGIN;
        int y = simpview.surface.PageCanvas.MARGIN + simpview.surface.PageCanvas.PANEL - 1 - pinnedY;
        if (x < 0 || y < 0 || x >= simpview.surface.PageCanvas.PANEL || y >= simpview.surface.PageCanvas.PANEL) {
            inspectorPanel.say("The pinned pixel is in the margin: nothing is drawn there.");
            return;
        }
        simpview.inspect.InspectedScene scene = inspectedScene(inspectorPanel::say);
        if (scene == null) {
            return;
        }
        String note = orbit.turned() || settings.stepLimit() >= 0
                ? "The history is of the whole drawing in the unturned view (stepping and turning are left out)."
                : null;
        inspectorPanel.inspect(scene, x, y, note);
    }

    /** The view on screen as the inspector replays it, or null (told to {@code why}) when it is not a scene. */
    private simpview.inspect.InspectedScene inspectedScene(java.util.function.Consumer<String> why) {
        try {
            View view = shown.view();
            if (view instanceof View.OfScene s) {
                return simpview.inspect.InspectedScene.of(s.file()).withOwnColours(settings.ownColours());
            }
            int number = ((View.OfPage) view).number();
            return simpview.inspect.InspectedScene.page(number, options.pageContext())
                    .withOwnColours(settings.ownColours());
        } catch (IllegalArgumentException | simpview.scene.SceneException e) {
            why.accept(e.getMessage());
            return null;
        }
    }

    /**
     * The overdraw overlay (V): each pixel by how many writes reached its
     * depth test, with its scale; or (Shift+V) by how many of them lost it.
     * Again: the page.
     */
    private void toggleOverdraw(boolean failures) {
        if (overdrawShown) {
            overdrawShown = false;
            showPicture();
            return;
        }
        if (shown == null) {
            return;
        }
        simpview.inspect.InspectedScene scene = inspectedScene(status::say);
        if (scene == null) {
            return;
        }
        RenderedView of = shown;
        status.say("Counting the writes of every pixel ...");
        inspectorPanel.overdraw(scene, counts -> {
            if (shown != of || counts == null) {
                status.say(counts == null ? "The overdraw could not be counted: the scene has an error." : "");
                return;
            }
            int[] shownCounts = failures ? counts.failed() : counts.reached();
            overdrawShown = true;
            overdrawMax = simpview.inspect.Overdraw.max(shownCounts);
            pageView.show(failures
                    ? simpview.window.instruments.OverdrawPicture.of(shownCounts,
                            "depth-test failures: writes that lost each pixel's depth test")
                    : simpview.window.instruments.OverdrawPicture.of(shownCounts), null, true);
            status.say((failures ? "Depth-test failures: up to " + overdrawMax + " lost writes at a pixel"
                    : "Overdraw: up to " + overdrawMax + " writes at a pixel")
                    + " (the scale is above the panel) · " + (failures ? "Shift+V" : "V") + ": the page again");
        });
    }

    /** The back-face overlay (K): pixels of clockwise polygons tinted magenta; again: the page. */
    private void toggleBackFaces() {
        if (backFacesShown) {
            showPicture();
            return;
        }
        if (shown == null) {
            return;
        }
        simpview.window.instruments.BackFacePicture.Tinted tinted =
                simpview.window.instruments.BackFacePicture.of(shown.image(), shown.facts());
        if (tinted == null) {
            status.say("Who drew each pixel was not recorded for this picture: no back faces to show.");
            return;
        }
        showPicture();
        backFacesShown = true;
        backFaces = tinted.backFacing();
        pageView.show(tinted.image(), null, true);
        status.say("Back faces tinted magenta: " + tinted.backFacing() + " of " + tinted.polygons()
                + " polygons are clockwise on the panel · K: the page again");
    }

    /** Steps the drawing up to the primitive that drew the pixel under the pointer (or the pinned one). */
    private void stepToOwner() {
        int x = pinnedX >= 0 ? pinnedX : hoverX;
        int y = pinnedX >= 0 ? pinnedY : hoverY;
        int owner = Inspector.ownerAt(shown, x, y);
        if (shown != null && shown.view() instanceof View.OfAssignment1Page page) {
            int[] last = x < 0 || y < 0 ? null : simpview.pages.A1Pixel.lastAt(page.number(), shown.seed(), x, y);
            owner = last == null ? -1 : last[1];
        }
        if (owner < 0) {
            status.say("No primitive drew the pixel under the pointer: nothing to step to.");
            return;
        }
        settings = settings.withStepLimit(owner + 1);
        reload();
    }

    /** Asks for a primitive number and steps the drawing to it (G). */
    private void goToPrimitive() {
        if (!steps(requested()) || shown == null) {
            status.say(STEPPING_WORKS_ON);
            return;
        }
        int total = stepsInAll();
        String answer = javax.swing.JOptionPane.showInputDialog(frame, "Go to primitive (1 to " + total + "):",
                "simpview", javax.swing.JOptionPane.QUESTION_MESSAGE);
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

    /** Puts the inspector's line on the clipboard. */
    private void copyInspected() {
        String line = status.inspectorText();
        Toolkit.getDefaultToolkit().getSystemClipboard().setContents(new StringSelection(line), null);
        status.say("Copied: " + line);
    }

    private void toggleDepthView() {
        depthView = !depthView;
        showPicture();
        inspect();
    }

    private void toggleOwnColours() {
        settings = settings.withOwnColours(!settings.ownColours());
        status.say(settings.ownColours()
                ? "Own colours: scenes show their vertices' colours (white where none), without the depth cue."
                : "Depth cue: scenes are coloured by depth again.");
        reload();
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

    /** Leaving a view leaves its stepping and its turn. */
    private void forgetViewState() {
        orbit.reset();
        settings = settings.withStepLimit(-1).withViewTurn(null).withRecord(true);
        pinnedX = pinnedY = -1;
        pageView.pin(-1, -1);
    }

    /** The line under the page while stepping: which primitive, from where; and its outline on the page. */
    private void showStep(RenderedView result) {
        int limit = settings.stepLimit();
        if (result.view() instanceof View.OfAssignment1Page page) {
            simpview.pages.A1Page a1 = Assignment1.page(page.number());
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
        if (limit < 0 || limit > primitives.size() || limit == 0) {
            pageView.outline(null);
            return;
        }
        status.say("primitive " + limit + " of " + primitives.size() + ", " + primitives.describe(limit - 1)
                + "   (] next · [ back · Shift: ten · \\ all)");
        pageView.outline(Inspector.toImage(primitives.outline(limit - 1)));
    }

    /** Shows the picture, or its depths, of the finished view. */
    private void showPicture() {
        overdrawShown = false;
        backFacesShown = false;
        if (shown != null) {
            PageFacts facts = shown.facts();
            pageView.show(depthView && facts.depths() != null ? DepthPicture.of(facts.depths(), facts.depthStart())
                    : shown.image(), shown.error(), facts.drewSomething());
        }
    }

    /** Draws what is on screen again (F5, a save of one of its files), keeping zoom and pan. */
    void reload() {
        show(requested());
    }

    private void bind(String name, Runnable action, String... keys) {
        for (String key : keys) {
            bindStroke(name, action, KeyStroke.getKeyStroke(key));
        }
    }

    private void bindStroke(String name, Runnable action, KeyStroke stroke) {
        JComponent root = frame.getRootPane();
        InputMap keys = root.getInputMap(JComponent.WHEN_IN_FOCUSED_WINDOW);
        keys.put(stroke, name);
        root.getActionMap().put(name, new AbstractAction() {
            private static final long serialVersionUID = 1L;

            @Override
            public void actionPerformed(ActionEvent e) {
                action.run();
            }
        });
    }

    /** The next page of the assignment on show (after its last comes its first). */
    void next() {
        if (assignment1Page > 0) {
            showAssignment1(assignment1Page % Assignment1.COUNT + 1);
        } else {
            stepTo(stepper.next());
        }
    }

    void previous() {
        if (assignment1Page > 0) {
            showAssignment1((assignment1Page + Assignment1.COUNT - 2) % Assignment1.COUNT + 1);
        } else {
            stepTo(stepper.previous());
        }
    }

    /** The first or the last place of the assignment on show. */
    private void end(boolean first) {
        if (assignment1Page > 0) {
            showAssignment1(first ? 1 : Assignment1.COUNT);
        } else {
            stepTo(first ? stepper.first() : stepper.last());
        }
    }

    /** Page n of the assignment on show. */
    private void jump(int n) {
        if (assignment1Page == 0) {
            stepTo(stepper.jump(n));
        } else if (n <= Assignment1.COUNT) {
            showAssignment1(n);
        } else {
            status.say("The first assignment has pages 1 to " + Assignment1.COUNT + "; A switches to the eight pages.");
        }
    }

    /** A: from the eight pages (and scenes) to the first assignment's five pages and back, each where it was left. */
    void switchAssignment() {
        if (assignment1Page > 0) {
            stepTo(stepper.current());
        } else {
            showAssignment1(1);
        }
    }

    private void showAssignment1(int page) {
        forgetViewState();
        assignment1Page = page;
        show(new View.OfAssignment1Page(page));
    }

    private void stepTo(int position) {
        assignment1Page = 0;
        forgetViewState();
        show(viewAt(position));
    }

    /** What stands at a place among the pages: one of the scenes named at start, or one of the eight pages. */
    private View viewAt(int position) {
        int scene = stepper.sceneAt(position);
        return scene >= 0 ? new View.OfScene(options.sceneList().get(scene)) : new View.OfPage(stepper.pageAt(position));
    }

    /** Shows a scene file as an extra view; stepping keys go back to the pages. */
    /** What a dropped folder does from now on: the command line gives {@code simpview check}. Call on the EDT. */
    public SimpviewWindow checkFoldersWith(FolderCheck check) {
        this.folderCheck = check;
        return this;
    }

    /**
     * A folder dropped (issue 21): {@code simpview check FOLDER} (its pages, the first assignment's,
     * its own scenes with their pictures, its own compare.json), on its own thread (drawn with this
     * window's seed and scene folder); the table in a window of its own.
     */
    void checkFolder(Path folder) {
        status.say("Checking the pictures in " + folder + " against the pages ...");
        PageContext context = options.pageContext();
        FolderCheck check = folderCheck;
        Runnable work = () -> {
            String table = check.text(folder, context);
            SwingUtilities.invokeLater(() -> showCheck(folder, table));
        };
        Thread thread = new Thread(work, "simpview-folder-check");
        thread.setDaemon(true);
        thread.start();
    }

    private void showCheck(Path folder, String table) {
        JTextArea text = new JTextArea(table);
        text.setEditable(false);
        text.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 13));
        JDialog dialog = new JDialog(frame, "check: " + folder.getFileName(), false);
        dialog.getContentPane().add(new JScrollPane(text));
        dialog.pack();
        dialog.setLocationRelativeTo(frame);
        dialog.setVisible(true);
        lastCheck = table;
        String[] lines = table.split("\n");
        status.say(folder.getFileName() + ": " + lines[lines.length - 1]);
    }

    /** The table of the last folder checked, or null: for the tests. */
    String lastCheck() {
        return lastCheck;
    }

    void openScene(Path file) {
        assignment1Page = 0;
        forgetViewState();
        show(new View.OfScene(file));
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
        return pending != null ? pending.view() : shown == null ? viewAt(stepper.current()) : shown.view();
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

    private void finished(RenderJob job, RenderedView result) {
        if (job != pending) {
            return; // cancelled or overtaken by a newer request
        }
        pending = null;
        if (result == null) {
            status.say(StatusStrip.HINTS);
            return;
        }
        shown = result;
        overdrawShown = false;
        showPicture();
        frame.setTitle(result.title());
        watcher.watch(result.facts().files(), job.stampsAsRead());
        inspect();
        status.say(result.warnings().isEmpty() ? StatusStrip.HINTS : "Warning: " + String.join("; ", result.warnings()));
        if (orbit.turned()) {
            status.say(orbit.describe());
        }
        showStep(result);
        refreshPanel();
        comparison.viewShown(result); // compare (issue 15)
        if (turnWaiting) {
            reload();
        }
    }

    /** Stops the picture being drawn; the one on screen stays, and so does its place among the pages. */
    void cancel() {
        if (pending == null) {
            return;
        }
        pending.cancel();
        pending = null;
        if (shown != null && shown.view() instanceof View.OfPage page) {
            stepper.jump(page.number());
        } else if (shown != null && shown.view() instanceof View.OfScene scene
                && options.sceneList().contains(scene.file())) {
            stepper.moveTo(options.sceneList().indexOf(scene.file()) + 1);
        }
        status.say("Cancelled: the page on screen is unchanged.");
    }

    private void chooseScene() {
        dialogs.chooseScene().ifPresent(this::openScene);
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

    InspectorPanel inspectorPanel() {
        return inspectorPanel;
    }

    /** How many polygons the back-face overlay tints while it is shown, else -1. */
    int backFacesShownCount() {
        return backFacesShown ? backFaces : -1;
    }

    /** The overdraw overlay's largest count while it is shown, else -1. */
    int overdrawShownMax() {
        return overdrawShown ? overdrawMax : -1;
    }

    // compare (issue 15)
    ComparisonLayer comparison() {
        return comparison;
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
