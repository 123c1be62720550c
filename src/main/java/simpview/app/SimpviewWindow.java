package simpview.app;

import java.awt.BorderLayout;
import java.awt.Toolkit;
import java.awt.event.ActionEvent;
import java.awt.event.KeyEvent;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.nio.file.Path;
import java.util.concurrent.ThreadLocalRandom;
import javax.swing.AbstractAction;
import javax.swing.InputMap;
import javax.swing.JComponent;
import javax.swing.JFrame;
import javax.swing.KeyStroke;
import javax.swing.SwingUtilities;
import simpview.pages.PageStepper;
import simpview.pages.Pages;

/**
 * The window: one page at a time, stepped by clicks and keys, pictures drawn
 * on the render thread. All methods run on the EDT.
 */
final class SimpviewWindow {

    private final JFrame frame = new JFrame("simpview");
    private final PageView pageView = new PageView();
    private final StatusStrip status = new StatusStrip(this::cancel);
    private final PageStepper stepper = new PageStepper();
    private final BackgroundRenderer renderer;
    private final FileDialogs dialogs;
    private WindowOptions options;
    private RenderedView shown;
    private RenderJob pending;
    // compare (issue 15): a picture dropped or opened, compared with the view on screen
    private final ComparisonLayer comparison = new ComparisonLayer(frame, pageView, status::say);

    private SimpviewWindow(WindowOptions options, SceneDrawer drawer) {
        this.options = options;
        this.renderer = new BackgroundRenderer(drawer);
        this.dialogs = new FileDialogs(frame, options.simpDir());
    }

    /**
     * Opens the window on the scene given, or else on page 1. Call on the EDT.
     * A scene is an extra view: stepping from it goes to the pages, from page 1.
     */
    static SimpviewWindow open(WindowOptions options) {
        return open(options, SceneDrawer.SIMP);
    }

    static SimpviewWindow open(WindowOptions options, SceneDrawer drawer) {
        SimpviewWindow window = new SimpviewWindow(options, drawer);
        window.build();
        window.show(options.scene().<View>map(View.OfScene::new).orElse(new View.OfPage(window.stepper.current())));
        return window;
    }

    private void build() {
        frame.setDefaultCloseOperation(JFrame.DISPOSE_ON_CLOSE);
        frame.getContentPane().add(pageView, BorderLayout.CENTER);
        frame.getContentPane().add(status.component(), BorderLayout.SOUTH);
        // The page stays at 1:1; a larger window would only add grey.
        frame.setResizable(false);
        frame.setTransferHandler(new SceneDrop(this::openScene, comparison::compareWith, status::say)); // compare (issue 15)
        pageView.addMouseListener(new MouseAdapter() {
            @Override
            public void mousePressed(MouseEvent e) {
                if (SwingUtilities.isLeftMouseButton(e)) {
                    stepTo(stepper.next());
                }
            }
        });
        bindKeys();
        frame.addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosed(WindowEvent e) {
                renderer.shutdown();
            }
        });
        frame.pack();
        frame.setLocationRelativeTo(null);
        frame.setVisible(true);
    }

    private void bindKeys() {
        bind("next", () -> stepTo(stepper.next()), "RIGHT", "SPACE", "PAGE_DOWN", "KP_RIGHT");
        bind("previous", () -> stepTo(stepper.previous()), "LEFT", "PAGE_UP", "KP_LEFT");
        bind("first", () -> stepTo(stepper.first()), "HOME");
        bind("last", () -> stepTo(stepper.last()), "END");
        for (int n = 1; n <= Pages.COUNT; n++) {
            int page = n;
            bind("page" + n, () -> stepTo(stepper.jump(page)), String.valueOf(n), "NUMPAD" + n);
        }
        bind("seed", this::newSeed, "R");
        bind("cancel", this::cancel, "ESCAPE");
        int menu = Toolkit.getDefaultToolkit().getMenuShortcutKeyMaskEx();
        bindStroke("save", this::save, KeyStroke.getKeyStroke(KeyEvent.VK_S, menu));
        bindStroke("open", this::chooseScene, KeyStroke.getKeyStroke(KeyEvent.VK_O, menu));
        comparison.bindKeys((name, action, stroke) -> bindStroke(name, action, KeyStroke.getKeyStroke(stroke))); // compare (issue 15)
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

    private void stepTo(int page) {
        show(new View.OfPage(page));
    }

    /** Shows a scene file as an extra view; stepping keys go back to the pages. */
    void openScene(Path file) {
        show(new View.OfScene(file));
    }

    /** A fresh seed for pages 1 to 3; redraws the page if it is one of them. */
    void newSeed() {
        long seed = options.seed();
        while (seed == options.seed()) {
            seed = ThreadLocalRandom.current().nextInt(1, 100_000);
        }
        options = new WindowOptions(seed, options.simpDir(), options.scene());
        if (requested() instanceof View.OfPage page && Pages.page(page.number()).usesSeed()) {
            show(page);
        } else {
            status.say("Seed is now " + seed + " (pages 1–3).");
        }
    }

    private View requested() {
        return pending != null ? pending.view() : shown == null ? new View.OfPage(stepper.current()) : shown.view();
    }

    /** Draws the view on the render thread; the page on screen stays until the new one is finished. */
    private void show(View view) {
        if (pending != null) {
            pending.cancel();
        }
        pending = new RenderJob(view, options.pageContext());
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
        pageView.show(result.image(), result.error());
        frame.setTitle(result.title());
        status.say(result.warnings().isEmpty() ? StatusStrip.HINTS : "Warning: " + String.join("; ", result.warnings()));
        comparison.viewShown(result); // compare (issue 15)
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
        frame.dispose();
    }

    // For tests: what is on screen and what is going on.

    JFrame frame() {
        return frame;
    }

    PageView pageView() {
        return pageView;
    }

    StatusStrip status() {
        return status;
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
