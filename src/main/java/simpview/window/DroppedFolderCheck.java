package simpview.window;

import java.awt.Font;
import java.nio.file.Path;
import java.util.function.Supplier;
import javax.swing.JDialog;
import javax.swing.JFrame;
import javax.swing.JScrollPane;
import javax.swing.JTextArea;
import javax.swing.SwingUtilities;
import simpview.pages.PageContext;
import simpview.window.instruments.FolderCheck;

/**
 * A folder dropped on the window (issue 21), checked as {@code simpview check
 * FOLDER} checks it, on a thread of its own; its table shown in a window of
 * its own and its last line on the status line. Called on the EDT.
 */
final class DroppedFolderCheck {

    private final JFrame frame;
    private final StatusStrip status;
    private final Supplier<PageContext> pageContext;
    private FolderCheck folderCheck = FolderCheck.NONE;
    private String lastCheck;

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
}
