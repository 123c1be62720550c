package simpview.window;

import simpview.window.render.RenderJob;
import simpview.window.render.View;

import java.awt.BorderLayout;
import java.awt.CardLayout;
import java.awt.Dimension;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JProgressBar;
import javax.swing.Timer;
import simpview.surface.PageCanvas;

/**
 * The line under the page: key hints and messages, or, while a picture takes
 * more than a moment, a progress bar (lines read) with a Cancel button.
 * Everything here runs on the EDT.
 */
public final class StatusStrip {

    static final String HINTS = "Click/→ next · ← back · 1–8 · wheel zoom · drag pan · right-drag turn · F fit · Z 1:1 · "
            + "D depth · P pin · C own colours · ] step · F5 redraw · Ctrl+O open · Ctrl+S save · F1 all keys";
    /** Quick pictures never flash a progress bar. */
    static final int PROGRESS_DELAY_MS = 150;
    private static final String TEXT = "text";
    private static final String PROGRESS = "progress";

    private final CardLayout cards = new CardLayout();
    private final JPanel panel = new JPanel(cards);
    private final JLabel text = new JLabel(HINTS);
    private final JLabel inspector = new JLabel(" ");
    private final JLabel working = new JLabel();
    private final JProgressBar bar = new JProgressBar();
    private final JButton cancel = new JButton("Cancel");
    private final Timer ticker = new Timer(100, e -> tick());
    private RenderJob watched;
    /** The inspector's last line of a pixel, or null. */
    private String lastPixelLine;

    StatusStrip(Runnable onCancel) {
        panel.setPreferredSize(new Dimension(PageCanvas.SIZE, 46));
        panel.setBorder(BorderFactory.createEmptyBorder(4, 8, 4, 8));
        bar.setStringPainted(true);
        // Keys belong to the page: a focused button would swallow Space.
        cancel.setFocusable(false);
        cancel.addActionListener(e -> onCancel.run());
        JPanel progress = new JPanel(new BorderLayout(8, 0));
        progress.add(working, BorderLayout.WEST);
        progress.add(bar, BorderLayout.CENTER);
        progress.add(cancel, BorderLayout.EAST);
        JPanel lines = new JPanel(new BorderLayout());
        lines.add(inspector, BorderLayout.NORTH);
        lines.add(text, BorderLayout.SOUTH);
        panel.add(lines, TEXT);
        panel.add(progress, PROGRESS);
        cards.show(panel, TEXT);
    }

    JPanel component() {
        return panel;
    }

    /** Follows a job; its progress shows once it has taken longer than a moment. */
    void watch(RenderJob job) {
        watched = job;
        ticker.restart();
    }

    /** Back to text, e.g. when the job ended or was cancelled. */
    void say(String message) {
        watched = null;
        ticker.stop();
        // An indeterminate bar animates for as long as its window is open,
        // shown or not: only while a job is showing may it move.
        bar.setIndeterminate(false);
        text.setText(message);
        // a line longer than the window is cut with "...": the whole of it shows on hovering
        text.setToolTipText(message);
        cards.show(panel, TEXT);
    }

    /**
     * The inspector's line: the pixel under the pointer (or pinned) and the
     * zoom ({@code ofAPixel}), or the zoom alone. A line longer than the
     * window is cut with "…"; its tooltip holds the whole of the last pixel's
     * line, and keeps it once the pointer has left the page to point at the
     * line and read it.
     */
    void inspect(String line, boolean ofAPixel) {
        boolean blank = line == null || line.isEmpty();
        inspector.setText(blank ? " " : line);
        if (ofAPixel && !blank) {
            lastPixelLine = line;
        }
        inspector.setToolTipText(ofAPixel || lastPixelLine == null ? blank ? null : line
                : "the last pixel inspected: " + lastPixelLine);
    }

    /**
     * A new picture is shown (another page, a scene saved again): the last pixel's line was of the picture before,
     * and stops being the tooltip.
     */
    void forgetLastPixel() {
        lastPixelLine = null; // the tooltip follows at the next inspect()
    }

    String inspectorText() {
        return inspector.getText();
    }

    /** What hovering the inspector's line shows in full. */
    String inspectorToolTip() {
        return inspector.getToolTipText();
    }

    String messageText() {
        return text.getText();
    }

    /** What the progress bar says, e.g. "12,000 of about 40,000 lines read (30 %)". */
    String progressText() {
        return bar.getString();
    }

    /** The text shown (when no progress is). */
    String text() {
        return text.getText();
    }

    boolean showingProgress() {
        return bar.isShowing();
    }

    /** Whether the progress bar is animating (it should only while a job shows). */
    boolean animating() {
        return bar.isIndeterminate();
    }

    JButton cancelButton() {
        return cancel;
    }

    private void tick() {
        if (watched == null || watched.millisSinceCreated() < PROGRESS_DELAY_MS) {
            return;
        }
        working.setText("Drawing " + describe(watched.view()) + "…");
        long lines = watched.linesSoFar();
        double share = watched.topFileShare();
        if (share > 0) {
            // The share of the top file's bytes: included files are read in between.
            int percent = (int) Math.min(99, 100 * share);
            bar.setIndeterminate(false);
            bar.setValue(percent);
            bar.setString(String.format("%,d lines read (%d %% of the scene file)", lines, percent));
        } else {
            bar.setString(String.format("%,d lines read", lines));
            bar.setIndeterminate(true);
        }
        cards.show(panel, PROGRESS);
    }

    private static String describe(View view) {
        if (view instanceof View.OfAssignment1Page page) {
            return "assignment 1, page " + page.number();
        }
        return view instanceof View.OfPage page
                ? "page " + page.number()
                : ((View.OfScene) view).file().getFileName().toString();
    }
}
