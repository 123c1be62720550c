package simpview.window;

import simpview.testing.Images;
import simpview.scene.simp.SceneDrawer;
import simpview.window.render.RenderedView;
import simpview.window.render.View;

import static org.junit.jupiter.api.Assertions.fail;

import java.awt.AWTEvent;
import java.awt.Component;
import java.awt.MouseInfo;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.Toolkit;
import java.awt.Window;
import java.awt.event.AWTEventListener;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.event.MouseEvent;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.BooleanSupplier;
import java.util.function.Predicate;
import javax.imageio.ImageIO;
import javax.swing.JComponent;
import javax.swing.SwingUtilities;
import simpview.surface.PageCanvas;
import java.awt.Dimension;
import java.util.function.ToLongFunction;

/** Drives the real window the way a person would: java.awt.Robot clicks, keys and screen captures. */
public final class WindowDriver {

    static final long WAIT_MS = 10_000;
    /** Where pinWindow puts the frame: well inside Xvfb's 1280x1024 screen. */
    private static final int PIN_X = 40;
    private static final int PIN_Y = 40;

    private final SimpviewWindow window;
    private final Robot robot;
    private final InputSeen input = new InputSeen();

    private WindowDriver(SimpviewWindow window, Robot robot) {
        this.window = window;
        this.robot = robot;
        Toolkit.getDefaultToolkit().addAWTEventListener(input,
                AWTEvent.KEY_EVENT_MASK | AWTEvent.MOUSE_EVENT_MASK | AWTEvent.MOUSE_MOTION_EVENT_MASK);
    }

    /**
     * The robot's keys and buttons as this JVM's event queue dispatched them.
     * A wait for the window to have handled an input waits for that input
     * here, rather than in Robot.waitForIdle: its sync with the X server can
     * run into its own timeout, up to 3 s a call, on an idle machine as
     * much as on a busy one (a whole run's window tests took 122 s with it,
     * 20 s without).
     */
    private static final class InputSeen implements AWTEventListener {
        private final Map<Integer, AtomicLong> keyPresses = new ConcurrentHashMap<>();
        private final Map<Integer, AtomicLong> keyReleases = new ConcurrentHashMap<>();
        private final AtomicLong buttonReleases = new AtomicLong();
        private volatile Point pointer;

        @Override
        public void eventDispatched(AWTEvent event) {
            if (event.getID() == KeyEvent.KEY_PRESSED) {
                presses(((KeyEvent) event).getKeyCode()).incrementAndGet();
            } else if (event.getID() == KeyEvent.KEY_RELEASED) {
                releases(((KeyEvent) event).getKeyCode()).incrementAndGet();
            } else if (event instanceof MouseEvent mouse) {
                if (mouse.getID() == MouseEvent.MOUSE_RELEASED) {
                    buttonReleases.incrementAndGet();
                }
                pointer = mouse.getLocationOnScreen();
            }
        }

        AtomicLong presses(int keyCode) {
            return keyPresses.computeIfAbsent(keyCode, k -> new AtomicLong());
        }

        AtomicLong releases(int keyCode) {
            return keyReleases.computeIfAbsent(keyCode, k -> new AtomicLong());
        }
    }

    /**
     * Until the event queue has run dry (what the robot's input set off,
     * the repaints it asked for) and the X server has drawn what was painted.
     */
    void settle() {
        try {
            for (int round = 0; round < 50; round++) {
                if (onEdt(() -> Toolkit.getDefaultToolkit().getSystemEventQueue().peekEvent() == null)) {
                    break;
                }
            }
            Toolkit.getDefaultToolkit().sync();
        } catch (Exception e) {
            throw new AssertionError("the event queue did not run dry", e);
        }
    }

    /** Until the release of {@code keyCode} after the {@code before}-th has been dispatched, then settled. */
    private void awaitKeyRelease(int keyCode, long before) {
        AtomicLong count = input.releases(keyCode);
        try {
            await(() -> count.get() > before, "the window to receive " + KeyEvent.getKeyText(keyCode));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new AssertionError(e);
        }
        settle();
    }

    /** Moves the pointer and, where it lands on one of this JVM's windows, waits for the window to see it there. */
    void movePointer(int x, int y) throws Exception {
        Point to = new Point(x, y);
        boolean moves = !to.equals(MouseInfo.getPointerInfo().getLocation());
        robot.mouseMove(x, y);
        boolean overOurs = onEdt(() -> {
            for (Window w : Window.getWindows()) {
                if (w.isShowing() && w.getBounds().contains(to)) {
                    return true;
                }
            }
            return false;
        });
        if (moves && overOurs) {
            await(() -> to.equals(input.pointer), "the window to see the pointer at " + x + ", " + y);
        }
        settle();
    }

    /** Opens the window and waits for its first page, or for the scene it was given. */
    static WindowDriver open(WindowOptions options, SceneDrawer drawer) throws Exception {
        WindowDriver driver = openWhileDrawing(options, drawer);
        View first = options.sceneList().isEmpty() ? new View.OfPage(1) : new View.OfScene(options.sceneList().get(0));
        driver.awaitShown(options.scene().<View>map(View.OfScene::new).orElse(first));
        return driver;
    }

    /** Opens the window and returns at once, its first view perhaps still being drawn. */
    static WindowDriver openWhileDrawing(WindowOptions options, SceneDrawer drawer) throws Exception {
        AtomicReference<SimpviewWindow> opened = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> opened.set(SimpviewWindow.open(options, drawer)));
        Robot robot = new Robot();
        robot.setAutoDelay(20);
        WindowDriver driver = new WindowDriver(opened.get(), robot);
        driver.pinWindow();
        return driver;
    }

    /**
     * Puts the frame at a place of our choosing and checks on the screen that
     * it is really there. Under Xvfb there is no window manager, and the AWT
     * toolkit sometimes keeps a stale location for a newly shown frame (it
     * says (0, 0) while the X server shows it centred): every click and
     * capture would then miss. An explicit move makes the two agree.
     */
    private void pinWindow() throws Exception {
        // Near the top-left corner, but wholly on a screen that has little room (1366x768).
        Rectangle screen = onEdt(() -> window.frame().getGraphicsConfiguration().getBounds());
        Dimension size = onEdt(() -> window.frame().getSize());
        int left = Math.max(0, Math.min(PIN_X, screen.width - size.width - 10));
        int top = Math.max(0, Math.min(PIN_Y, screen.height - size.height));
        for (int attempt = 0; attempt < 10; attempt++) {
            int x = left + attempt;
            onEdt(() -> window.frame().setLocation(x, top));
            settle();
            if (pageIsWhereTheToolkitSaysItIs()) {
                return;
            }
            Thread.sleep(100);
        }
        keepEvidence("misplaced", capturePage());
        fail("the window is not where the AWT toolkit says it is, even after moving it");
    }

    /** The capture at the page's reported place shows the page's white top and left margins (as zoomed). */
    private boolean pageIsWhereTheToolkitSaysItIs() throws Exception {
        BufferedImage screen = capturePage();
        double zoom = onEdt(() -> window.pageView().zoomPan().zoom());
        Point origin = onEdt(() -> window.pageView().imageOrigin());
        int shown = Math.min(screen.getWidth(), screen.getHeight());
        // With the margins cropped (a small screen), only what is left of them shows.
        int margin = (int) Math.floor(PageCanvas.MARGIN * Math.min(1, zoom) + Math.min(0, Math.min(origin.x, origin.y)));
        for (int i = 0; i < shown; i++) {
            for (int m = 0; m < margin; m++) {
                if ((screen.getRGB(i, m) & 0xFFFFFF) != 0xFFFFFF || (screen.getRGB(m, i) & 0xFFFFFF) != 0xFFFFFF) {
                    return false;
                }
            }
        }
        return true;
    }

    SimpviewWindow window() {
        return window;
    }

    <T> T onEdt(Callable<T> question) throws Exception {
        AtomicReference<T> answer = new AtomicReference<>();
        AtomicReference<Exception> failure = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> {
            try {
                answer.set(question.call());
            } catch (Exception e) {
                failure.set(e);
            }
        });
        if (failure.get() != null) {
            throw failure.get();
        }
        return answer.get();
    }

    void onEdt(Runnable action) throws Exception {
        SwingUtilities.invokeAndWait(action);
    }

    /** Waits until nothing is being drawn and {@code view} is on screen. */
    RenderedView awaitShown(View view) throws Exception {
        awaitEdt(() -> !window.busy() && window.shown() != null && window.shown().view().equals(view),
                "showing " + view);
        settle();
        return onEdt(window::shown);
    }

    /** Polls a condition on the EDT until it holds; fails with what the window shows if it never does. */
    void awaitEdt(Callable<Boolean> condition, String what) throws Exception {
        long deadline = System.currentTimeMillis() + WAIT_MS;
        while (!onEdt(condition)) {
            if (System.currentTimeMillis() > deadline) {
                RenderedView shown = onEdt(window::shown);
                fail("timed out waiting for " + what + "; showing " + (shown == null ? "nothing" : shown.view())
                        + ", busy " + onEdt(window::busy));
            }
            Thread.sleep(20);
        }
    }

    static void await(BooleanSupplier condition, String what) throws InterruptedException {
        long deadline = System.currentTimeMillis() + WAIT_MS;
        while (!condition.getAsBoolean()) {
            if (System.currentTimeMillis() > deadline) {
                fail("timed out waiting for " + what);
            }
            Thread.sleep(20);
        }
    }

    /** A left click in the middle of the page, then the pointer moves off the window. */
    void clickPage() throws Exception {
        click(window.pageView());
    }

    /**
     * Clicks the middle of {@code component}, once it is laid out and really is
     * what lies under that point: a button just made visible can still have no
     * size, and a click at its "middle" would land on whatever is next to it.
     */
    void click(JComponent component) throws Exception {
        awaitEdt(() -> component.isShowing() && component.getWidth() > 0 && component.getHeight() > 0
                && hits(component), "the component to click to be laid out and on top");
        Point p = onEdt(() -> middleOnScreen(component));
        long before = input.buttonReleases.get();
        robot.mouseMove(p.x, p.y);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        await(() -> input.buttonReleases.get() > before, "the window to receive the click");
        robot.mouseMove(1, 1);
        settle();
    }

    private static Point middleOnScreen(JComponent component) {
        Point corner = component.getLocationOnScreen();
        return new Point(corner.x + component.getWidth() / 2, corner.y + component.getHeight() / 2);
    }

    /** Whether the middle of the component is the component itself (or a child of it) in its window. */
    private static boolean hits(JComponent component) {
        Window frame = SwingUtilities.getWindowAncestor(component);
        Point p = middleOnScreen(component);
        SwingUtilities.convertPointFromScreen(p, frame);
        Component under = SwingUtilities.getDeepestComponentAt(frame, p.x, p.y);
        return under != null && (under == component || SwingUtilities.isDescendingFrom(under, component));
    }

    /** Clicks the page once to give the window the keyboard, and waits for the step that click makes. */
    void focusByClicking(View afterClick) throws Exception {
        clickPage();
        awaitShown(afterClick);
        awaitEdt(() -> window.frame().isFocused(), "the window to have the keyboard");
    }

    /** Presses and releases a key, then waits until the window has handled it. */
    void press(int keyCode) {
        long before = input.releases(keyCode).get();
        robot.keyPress(keyCode);
        robot.keyRelease(keyCode);
        awaitKeyRelease(keyCode, before);
    }

    /**
     * Presses and releases a key that closes {@code closing}, the window that has the keys, and waits until
     * the press has been handled and the window is gone. The release is not waited for: the window closed on
     * the press, and the X server hands the release to whichever window has the keys by then, which may be
     * none of this JVM's while the focus moves.
     */
    void pressToClose(int keyCode, Window closing) throws Exception {
        long before = input.presses(keyCode).get();
        robot.keyPress(keyCode);
        robot.keyRelease(keyCode);
        await(() -> input.presses(keyCode).get() > before, "the window to receive " + KeyEvent.getKeyText(keyCode));
        awaitEdt(() -> !closing.isShowing(), KeyEvent.getKeyText(keyCode) + " to close its window");
        settle();
    }

    /** The same with {@code modifier} (a key code such as VK_SHIFT) held down. */
    void pressWith(int modifier, int keyCode) {
        long before = input.releases(modifier).get();
        robot.keyPress(modifier);
        press(keyCode);
        robot.keyRelease(modifier);
        awaitKeyRelease(modifier, before);
    }

    void pressWithControl(int keyCode) {
        pressWith(KeyEvent.VK_CONTROL, keyCode);
    }

    /** The page as the X server shows it: at 1:1 the 750x750 image, else the square it is zoomed into (what shows of it). */
    BufferedImage capturePage() throws Exception {
        settle();
        Rectangle page = onEdt(this::pageOnScreen);
        return robot.createScreenCapture(page);
    }

    /** Where the page image is on screen, cut to the page view. */
    Rectangle pageOnScreen() {
        PageView view = window.pageView();
        Point corner = view.getLocationOnScreen();
        Point origin = view.imageOrigin();
        int size = (int) Math.round(view.zoomPan().shownSize());
        Rectangle image = new Rectangle(corner.x + origin.x, corner.y + origin.y, size, size);
        return image.intersection(new Rectangle(corner, view.getSize()));
    }

    /** The screen point at the centre of image pixel (ix, iy) as now zoomed and panned. */
    Point onScreen(int ix, int iy) throws Exception {
        return onEdt(() -> {
            PageView view = window.pageView();
            Point corner = view.getLocationOnScreen();
            return new Point(corner.x + (int) Math.floor(view.zoomPan().screenX(ix + 0.5)),
                    corner.y + (int) Math.floor(view.zoomPan().screenY(iy + 0.5)));
        });
    }

    Robot robot() {
        return robot;
    }

    /**
     * The page as captured once {@code settled} holds for it, or the last
     * capture after three seconds (a busy machine may be slow to repaint).
     */
    BufferedImage captureWhen(Predicate<BufferedImage> settled) throws Exception {
        BufferedImage screen = capturePage();
        for (int attempt = 0; attempt < 60 && !settled.test(screen); attempt++) {
            Thread.sleep(50);
            screen = capturePage();
        }
        return screen;
    }

    /**
     * How many pixels of the page on screen differ from {@code expected}, once
     * the screen has had up to three seconds to settle (a busy machine may be
     * slow to repaint). When some still differ, the last capture is kept under
     * build/window-failures for a look.
     */
    long screenDiffersFrom(BufferedImage page) throws Exception {
        double zoom = onEdt(() -> window.pageView().zoomPan().zoom());
        if (zoom > 1) {
            return scaledScreenDiffersFrom(page, zoom);
        }
        BufferedImage expected = shownPart(page);
        BufferedImage screen = captureWhen(capture -> Images.differingPixels(expected, capture) == 0);
        long differing = Images.differingPixels(expected, screen);
        if (differing != 0) {
            keepEvidence("differs-" + differing, screen);
        }
        return differing;
    }

    /**
     * What of {@code page} the screen should show at 1:1 or below, as
     * {@link #capturePage} captures it: at 1:1 the page itself, below 1:1 the
     * page as the line-keeping filter makes it smaller (exactly), and of that
     * what is in view (the margins cropped on a small screen).
     */
    BufferedImage shownPart(BufferedImage page) throws Exception {
        double zoom = onEdt(() -> window.pageView().zoomPan().zoom());
        BufferedImage whole = zoom == 1 ? page : LineKeepingDownscale.of(page, zoom);
        Point origin = onEdt(() -> window.pageView().imageOrigin());
        Rectangle seen = onEdt(this::pageOnScreen);
        return whole.getSubimage(Math.max(0, -origin.x), Math.max(0, -origin.y),
                Math.min(seen.width, whole.getWidth()), Math.min(seen.height, whole.getHeight()));
    }

    /**
     * The same for a page zoomed in at a zoom that is not whole: a screen
     * pixel matches when it shows the page pixel it falls on, or, where
     * rounding can pick either, one of that pixel's neighbours.
     */
    private long scaledScreenDiffersFrom(BufferedImage page, double zoom) throws Exception {
        ToLongFunction<BufferedImage> count = screen -> {
            long differing = 0;
            for (int sy = 0; sy < screen.getHeight(); sy++) {
                for (int sx = 0; sx < screen.getWidth(); sx++) {
                    if (!nearMatch(page, screen.getRGB(sx, sy), (int) (sx / zoom), (int) (sy / zoom))) {
                        differing++;
                    }
                }
            }
            return differing;
        };
        BufferedImage screen = captureWhen(capture -> count.applyAsLong(capture) == 0);
        long differing = count.applyAsLong(screen);
        if (differing != 0) {
            keepEvidence("differs-scaled-" + differing, screen);
        }
        return differing;
    }

    private static boolean nearMatch(BufferedImage page, int rgb, int ix, int iy) {
        for (int dy = -1; dy <= 1; dy++) {
            for (int dx = -1; dx <= 1; dx++) {
                int x = ix + dx;
                int y = iy + dy;
                if (x >= 0 && y >= 0 && x < page.getWidth() && y < page.getHeight()
                        && ((page.getRGB(x, y) ^ rgb) & 0xFFFFFF) == 0) {
                    return true;
                }
            }
        }
        return false;
    }

    /**
     * Keeps what the screen showed when a window test saw something
     * unexpected, under build/window-failures: the page capture, the whole
     * screen, and every showing window with its place, for a later look.
     */
    void keepEvidence(String what, BufferedImage pageCapture) throws Exception {
        Path dir = Path.of(System.getProperty("simpview.projectDir", "."), "build", "window-failures");
        Files.createDirectories(dir);
        String stem = what + "-" + System.nanoTime();
        ImageIO.write(pageCapture, "png", dir.resolve(stem + "-page.png").toFile());
        Rectangle screen = new Rectangle(Toolkit.getDefaultToolkit().getScreenSize());
        ImageIO.write(robot.createScreenCapture(screen), "png", dir.resolve(stem + "-screen.png").toFile());
        StringBuilder windows = new StringBuilder();
        onEdt(() -> {
            for (Window w : Window.getWindows()) {
                windows.append(w.getClass().getSimpleName()).append(' ').append(w.getName())
                        .append(" showing=").append(w.isShowing()).append(' ').append(w.getBounds())
                        .append(w == SwingUtilities.getWindowAncestor(window.pageView()) ? " (this test's)" : "")
                        .append('\n');
            }
            windows.append("page view on screen at ").append(window.pageView().getLocationOnScreen()).append('\n');
        });
        Files.writeString(dir.resolve(stem + "-windows.txt"), windows);
        System.err.println("window test evidence kept: " + dir.resolve(stem + "-*"));
    }

    void close() throws Exception {
        onEdt(window::close);
        settle();
        Toolkit.getDefaultToolkit().removeAWTEventListener(input);
    }
}
