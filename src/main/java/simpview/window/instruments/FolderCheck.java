package simpview.window.instruments;

import java.nio.file.Path;
import simpview.pages.PageContext;

/**
 * What a folder dropped on the window does: {@code simpview check FOLDER}
 * with the window's seed and scene folder, its table as text. The window
 * cannot reach the command line's batch (it sits below it), so whoever opens
 * the window hands it the check (the command line: {@code CheckCommand.checkFolder}).
 * Called off the EDT, on the {@code simpview-folder-check} thread.
 */
@FunctionalInterface
public interface FolderCheck {

    /** Until one is given: a table saying so. */
    FolderCheck NONE = (folder, context) -> "This window was opened without simpview check: a folder cannot be "
            + "checked here; run simpview check " + folder + "\n";

    /** The folder's table, as {@code simpview check} prints it. */
    String text(Path folder, PageContext context);
}
