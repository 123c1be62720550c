package simpview.window;

import java.awt.Dimension;
import java.awt.Font;
import java.awt.Insets;
import java.awt.Rectangle;
import java.awt.event.ActionEvent;
import java.awt.event.KeyEvent;
import java.nio.file.Path;
import java.util.function.Supplier;
import javax.swing.AbstractAction;
import javax.swing.JComponent;
import javax.swing.JDialog;
import javax.swing.JFrame;
import javax.swing.JScrollPane;
import javax.swing.JTextArea;
import javax.swing.KeyStroke;
import javax.swing.SwingUtilities;
import simpview.pages.PageContext;
import simpview.window.instruments.FolderCheck;

/**
 * A folder dropped on the window (issue 21), checked as {@code simpview check
 * FOLDER} checks it, on a thread of its own; its table shown in a window of
 * its own and its last line on the status line. The table's window is one
 * per window, each folder's table shown in it in turn; it comes up beside the
 * page without taking the keys from it (the check ends seconds after the
 * drop, while the keys may be turning pages), and Escape closes it, giving
 * the keys back to the page. Called on the EDT.
 */
final class DroppedFolderCheck {

    private final JFrame frame;
    private final StatusStrip status;
    private final Supplier<PageContext> pageContext;
    private FolderCheck folderCheck = FolderCheck.NONE;
    private String lastCheck;
    /** The window the tables are shown in, made with the first; null before. */
    private JDialog tableWindow;
    private JTextArea tableText;
    private JScrollPane tableScroll;

    /** The check of the folders dropped on {@code frame}, drawn with what {@code pageContext} gives as each is dropped. */
    DroppedFolderCheck(JFrame frame, StatusStrip status, Supplier<PageContext> pageContext) {
        this.frame = frame;
        this.status = status;
        this.pageContext = pageContext;
    }

    /** What a dropped folder does from now on: the command line gives {@code simpview check}. */
    void checkWith(FolderCheck check) {
        this.folderCheck = check;
    }

    /**
     * A folder dropped (issue 21): {@code simpview check FOLDER} (its pages, the first assignment's,
     * its own scenes with their pictures, its own compare.json), on its own thread (drawn with this
     * window's seed and scene folder); the table in a window of its own.
     */
    void check(Path folder) {
        status.say("Checking the pictures in " + folder + " against the pages ...");
        PageContext context = pageContext.get();
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
        if (tableWindow == null) {
            makeTableWindow();
        }
        tableText.setText(table);
        tableText.setCaretPosition(0);
        tableWindow.setTitle("check: " + folder.getFileName());
        if (!tableWindow.isShowing()) {
            fitTableWindow(new Dimension());
            tableWindow.setLocationRelativeTo(frame);
            tableWindow.setVisible(true);
        } else {
            fitTableWindow(tableWindow.getSize()); // a wider or longer table: grown to show it, never shrunk
        }
        lastCheck = table;
        String[] lines = table.split("\n");
        status.say(folder.getFileName() + ": " + lines[lines.length - 1]);
    }

    /**
     * Sizes the table's window to show its widest line whole, with a margin, within the usable screen, and no
     * smaller than {@code atLeast}: a table longer than the screen is as high as the screen allows, and wider by
     * the scroll bar beside its lines, which would otherwise take the width of its last column.
     */
    private void fitTableWindow(Dimension atLeast) {
        tableWindow.pack();
        Rectangle usable = WindowPlacement.usableArea(frame.getGraphicsConfiguration());
        Dimension wanted = tableWindow.getSize();
        if (wanted.height > usable.height) {
            wanted.width += tableScroll.getVerticalScrollBar().getPreferredSize().width;
        }
        wanted.width = Math.min(usable.width, Math.max(wanted.width, atLeast.width));
        wanted.height = Math.min(usable.height, Math.max(wanted.height, atLeast.height));
        Rectangle bounds = new Rectangle(tableWindow.getLocation(), wanted);
        bounds.x = Math.max(usable.x, Math.min(bounds.x, usable.x + usable.width - bounds.width));
        bounds.y = Math.max(usable.y, Math.min(bounds.y, usable.y + usable.height - bounds.height));
        tableWindow.setBounds(bounds);
        tableWindow.validate();
    }

    private void makeTableWindow() {
        tableText = new JTextArea();
        tableText.setEditable(false);
        tableText.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 13));
        tableText.setMargin(new Insets(4, 8, 4, 8)); // the last column clear of the window's edge
        tableText.getAccessibleContext().setAccessibleName("folder check");
        tableText.getAccessibleContext().setAccessibleDescription("a row for each picture checked, with its page, "
                + "whether it passes and how much matches; Escape closes it");
        tableWindow = new JDialog(frame, false);
        tableWindow.setAutoRequestFocus(false);
        tableScroll = new JScrollPane(tableText);
        tableWindow.getContentPane().add(tableScroll);
        String close = "close";
        tableWindow.getRootPane().getInputMap(JComponent.WHEN_IN_FOCUSED_WINDOW)
                .put(KeyStroke.getKeyStroke(KeyEvent.VK_ESCAPE, 0), close);
        tableWindow.getRootPane().getActionMap().put(close, new AbstractAction() {
            private static final long serialVersionUID = 1L;

            @Override
            public void actionPerformed(ActionEvent e) {
                tableWindow.setVisible(false);
                // the keys go back to the page (with no window manager to give them, nothing would have them)
                frame.requestFocus();
            }
        });
    }

    /** The window the last table is shown in, or null before the first: for the tests. */
    JDialog tableWindow() {
        return tableWindow;
    }

    /** The table of the last folder checked, or null: for the tests. */
    String lastCheck() {
        return lastCheck;
    }
}
