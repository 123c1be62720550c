package simpview.window.instruments;

import java.awt.Dimension;
import java.awt.Font;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import javax.swing.BorderFactory;
import javax.swing.JComponent;
import javax.swing.JScrollPane;
import javax.swing.JTextArea;
import javax.swing.ScrollPaneConstants;
import javax.swing.SwingUtilities;
import simpview.inspect.HistoryEntry;
import simpview.inspect.InspectedScene;
import simpview.inspect.PixelInspector;
import simpview.inspect.PixelReport;
import simpview.scene.SceneException;
import simpview.scene.simp.SceneMonitor;

/**
 * The inspector's side panel: for the pinned pixel, its whole history, how
 * its colour was made and the vertices of the primitive that drew it, as
 * {@code simpview inspect} prints them. The text wraps and scrolls; nothing
 * is cut off. The replay behind it runs on the panel's own thread
 * ("simpview-pixel-history"), one at a time; a newer request overtakes an
 * older one, whose answer is then dropped. Methods other than the worker's
 * run on the EDT.
 */
public final class InspectorPanel {

    private static final int WIDTH = 420;

    private final JTextArea text = new JTextArea();
    private final JScrollPane scroll;
    private final ExecutorService worker = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "simpview-inspector");
        t.setDaemon(true);
        return t;
    });
    /** The replay's inspector, with its own models: used on the worker thread only. */
    private final simpview.scene.obj.ObjLibrary models = new simpview.scene.obj.ObjLibrary();
    private final PixelInspector inspector = new PixelInspector(models, SceneMonitor.NONE);
    /** Counts requests; an answer for an older one is not shown. */
    private int request;
    private boolean answered = true;

    public InspectorPanel() {
        text.setEditable(false);
        text.setLineWrap(true);
        text.setWrapStyleWord(true);
        text.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 12));
        text.setBorder(BorderFactory.createEmptyBorder(6, 6, 6, 6));
        text.setName("inspector text");
        scroll = new JScrollPane(text, ScrollPaneConstants.VERTICAL_SCROLLBAR_AS_NEEDED,
                ScrollPaneConstants.HORIZONTAL_SCROLLBAR_NEVER);
        scroll.setPreferredSize(new Dimension(WIDTH, 400));
        scroll.setName("inspector panel");
        scroll.setVisible(false);
        say("Pin a pixel (P) to see every write it received, how its colour was made, and its primitive's vertices.");
    }

    public JComponent component() {
        return scroll;
    }

    public boolean isShown() {
        return scroll.isVisible();
    }

    /** Shows or hides the panel; returns whether it is shown now. */
    public boolean toggle() {
        scroll.setVisible(!scroll.isVisible());
        scroll.revalidate();
        return scroll.isVisible();
    }

    /** A message in place of a report (nothing pinned, a page that is not a scene, ...). */
    public void say(String message) {
        request++;
        answered = true;
        text.setText(message);
        text.setCaretPosition(0);
    }

    /** Replays {@code scene} for panel pixel (x, y) and shows the report when it is ready. */
    public void inspect(InspectedScene scene, int x, int y, String note) {
        int mine = ++request;
        answered = false;
        text.setText("Replaying the scene for pixel (" + x + ", " + y + ") ...");
        worker.submit(() -> {
            String report;
            try {
                PixelReport r = inspector.inspect(scene, x, y);
                HistoryEntry owner = r.lastWritten();
                report = (note == null ? "" : note + "\n\n")
                        + r.text(true, true, owner == null ? HistoryEntry.NO_NUMBER : owner.primitive());
            } catch (SceneException e) {
                report = "The scene stops with an error, so the history ends there:\n" + e.getMessage();
            } catch (RuntimeException e) {
                report = "Could not replay the scene: " + e;
            }
            String shown = report;
            SwingUtilities.invokeLater(() -> {
                if (mine == request) {
                    answered = true;
                    text.setText(shown);
                    text.setCaretPosition(0);
                }
            });
        });
    }

    /**
     * The overdraw of {@code scene}, counted on the inspector's thread, then
     * given to {@code show} on the EDT (null when the scene has an error).
     */
    public void overdraw(InspectedScene scene, java.util.function.Consumer<simpview.inspect.Overdraw.Counts> show) {
        worker.submit(() -> {
            simpview.inspect.Overdraw.Counts counts;
            try {
                counts = simpview.inspect.Overdraw.counts(scene, models);
            } catch (SceneException | RuntimeException e) {
                counts = null;
            }
            simpview.inspect.Overdraw.Counts shown = counts;
            SwingUtilities.invokeLater(() -> show.accept(shown));
        });
    }

    /** The panel's text, whole (for copying and for tests). */
    public String text() {
        return text.getText();
    }

    /** True when the last request has its answer on screen. */
    public boolean answered() {
        return answered;
    }

    public void shutdown() {
        worker.shutdownNow();
    }
}
