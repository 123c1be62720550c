package simpview.window;

import simpview.window.render.RenderJob;
import simpview.window.render.View;

import java.awt.BorderLayout;
import java.awt.CardLayout;
import java.awt.Dimension;
import java.awt.Insets;
import java.awt.event.ComponentAdapter;
import java.awt.event.ComponentEvent;
import javax.swing.BorderFactory;
import javax.swing.Box;
import javax.swing.BoxLayout;
import javax.swing.JButton;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JProgressBar;
import javax.swing.Timer;
import java.util.List;
import simpview.surface.PageCanvas;

/**
 * The line under the page: key hints and messages, or, while a picture takes
 * more than a moment, a progress bar (lines read) with a Cancel button.
 * In a narrow window what does not fit is cut with "…" and shown whole on
 * hovering it: the lines of text, what is being drawn, the bar's words (then
 * the bar says its share alone); the bar and Cancel always keep their room.
 * Everything here runs on the EDT.
 */
public final class StatusStrip {

    /** Quick pictures never flash a progress bar. */
    static final int PROGRESS_DELAY_MS = 150;
    private static final String TEXT = "text";
    private static final String PROGRESS = "progress";
    /** The bar's width when room is short: enough for "99 %" or "1,234,567 lines"; it grows with the window. */
    private static final int BAR_LEAST = 110;

    private final CardLayout cards = new CardLayout();
    private final JPanel panel = new JPanel(cards);
    /** The key hints, the menus' keys named as the menus name them. */
    private final String hints = hints(MenuKey.ofPlatform());
    private final JLabel text = new JLabel(hints);
    private final JLabel inspector = new JLabel(" ");
    private final JLabel working = new JLabel();
    private final JProgressBar bar = new JProgressBar();
    private final JButton cancel = new JButton("Cancel");
    private final Timer ticker = new Timer(100, e -> tick());
    private RenderJob watched;
    /** What the bar says in full, and briefly for when that does not fit it ("30 %"). */
    private String barWords = "";
    private String barBrief = "";
    /** The inspector's last line of a pixel, or null. */
    private String lastPixelLine;

    StatusStrip(Runnable onCancel) {
        panel.setPreferredSize(new Dimension(PageCanvas.SIZE, 46));
        panel.setBorder(BorderFactory.createEmptyBorder(4, 8, 4, 8));
        text.setToolTipText(hints);
        bar.setStringPainted(true);
        // Keys belong to the page: a focused button would swallow Space.
        cancel.setFocusable(false);
        cancel.addActionListener(e -> onCancel.run());
        // What a screen reader says of the line's parts: the labels speak their own text.
        cancel.getAccessibleContext().setAccessibleDescription("stop drawing (Escape); the page on screen stays");
        bar.getAccessibleContext().setAccessibleName("drawing progress");
        inspector.getAccessibleContext().setAccessibleDescription("the inspected pixel, and the zoom");
        text.getAccessibleContext().setAccessibleDescription("the status line: messages, and the keys when none");
        working.getAccessibleContext().setAccessibleDescription("what is being drawn");
        // One row: what is being drawn at its own width, the bar taking the rest, Cancel at the end. When the
        // row is short of room, the words of what is being drawn give it up (cut with "…"); the bar keeps
        // BAR_LEAST and Cancel its own width, so neither is covered.
        JPanel progress = new JPanel();
        progress.setLayout(new BoxLayout(progress, BoxLayout.X_AXIS));
        working.setMinimumSize(new Dimension(0, 0));
        Dimension least = new Dimension(BAR_LEAST, bar.getPreferredSize().height);
        bar.setMinimumSize(least);
        bar.setPreferredSize(least);
        // the bar's words are chosen again whenever its width changes (a window resized, the words beside it)
        bar.addComponentListener(new ComponentAdapter() {
            @Override
            public void componentResized(ComponentEvent e) {
                sayOnTheBar();
            }
        });
        progress.add(working);
        progress.add(Box.createHorizontalStrut(8));
        progress.add(bar);
        progress.add(Box.createHorizontalStrut(8));
        progress.add(cancel);
        JPanel lines = new JPanel(new BorderLayout());
        lines.add(inspector, BorderLayout.NORTH);
        lines.add(text, BorderLayout.SOUTH);
        panel.add(lines, TEXT);
        panel.add(progress, PROGRESS);
        cards.show(panel, TEXT);
    }

    /**
     * The key hints the line shows between messages, with {@code menuKey}'s
     * words for opening and saving: "Ctrl+O open", or "⌘O open" on a Mac.
     */
    static String hints(MenuKey menuKey) {
        return "Click/→ next · ← back · 1–8 · wheel zoom · drag pan · right-drag turn · F fit · Z 1:1 · D depth · "
                + "P pin · C own colours · ] step · F5 redraw · " + WindowAction.OPEN.keysShown(menuKey) + " open · "
                + WindowAction.SAVE.keysShown(menuKey) + " save · F1 all keys";
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

    /** Back to the key hints. */
    void sayHints() {
        say(hints);
    }

    /** The key hints as this line shows them. */
    String hints() {
        return hints;
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

    /** The words of what is being drawn, beside the bar. */
    JLabel workingLabel() {
        return working;
    }

    JProgressBar progressBar() {
        return bar;
    }

    /** The two lines of text: the inspector's, then the hints and messages. */
    List<JLabel> textLines() {
        return List.of(inspector, text);
    }

    private void tick() {
        if (watched == null || watched.millisSinceCreated() < PROGRESS_DELAY_MS) {
            return;
        }
        String drawing = "Drawing " + describe(watched.view()) + "…";
        working.setText(drawing);
        working.setToolTipText(drawing);
        long lines = watched.linesSoFar();
        double share = watched.topFileShare();
        String words;
        String brief;
        if (share > 0) {
            // The share of the top file's bytes: included files are read in between.
            int percent = (int) Math.min(99, 100 * share);
            bar.setIndeterminate(false);
            bar.setValue(percent);
            words = String.format("%,d lines read (%d %% of the scene file)", lines, percent);
            brief = percent + " %";
        } else {
            words = String.format("%,d lines read", lines);
            brief = String.format("%,d lines", lines);
            bar.setIndeterminate(true);
        }
        barWords = words;
        barBrief = brief;
        sayOnTheBar();
        cards.show(panel, PROGRESS);
    }

    /** The bar's words in full when they fit it, else briefly; in full on hovering it. */
    private void sayOnTheBar() {
        bar.setString(fitsTheBar(barWords) ? barWords : barBrief);
        bar.setToolTipText(barWords.isEmpty() ? null : barWords);
    }

    /** Whether the bar, as wide as it is now, shows {@code words} whole. */
    private boolean fitsTheBar(String words) {
        Insets insets = bar.getInsets();
        return bar.getFontMetrics(bar.getFont()).stringWidth(words) <= bar.getWidth() - insets.left - insets.right - 4;
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
