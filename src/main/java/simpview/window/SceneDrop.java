package simpview.window;

import java.awt.datatransfer.DataFlavor;
import java.awt.datatransfer.UnsupportedFlavorException;
import java.io.File;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;
import javax.swing.TransferHandler;

/**
 * Opens a .simp file dropped on the window; a picture dropped is compared with the page (issue 15);
 * a folder dropped is checked, every page picture in it, as {@code simpview check} does (issue 21).
 */
public final class SceneDrop extends TransferHandler {

    private static final long serialVersionUID = 1L;

    private final transient Consumer<Path> open;
    private final transient Consumer<String> tell;
    // compare (issue 15): pictures dropped go here; null when the window does not compare
    private final transient Consumer<Path> compare;
    // check (issue 21): a folder dropped goes here; null when the window does not check folders
    private final transient Consumer<Path> folder;

    SceneDrop(Consumer<Path> open, Consumer<String> tell) {
        this(open, null, null, tell);
    }

    SceneDrop(Consumer<Path> open, Consumer<Path> compare, Consumer<String> tell) {
        this(open, compare, null, tell);
    }

    SceneDrop(Consumer<Path> open, Consumer<Path> compare, Consumer<Path> folder, Consumer<String> tell) {
        this.open = open;
        this.compare = compare;
        this.folder = folder;
        this.tell = tell;
    }

    @Override
    public boolean canImport(TransferSupport support) {
        return support.isDataFlavorSupported(DataFlavor.javaFileListFlavor);
    }

    @Override
    public boolean importData(TransferSupport support) {
        if (!canImport(support)) {
            return false;
        }
        List<?> files;
        try {
            files = (List<?>) support.getTransferable().getTransferData(DataFlavor.javaFileListFlavor);
        } catch (UnsupportedFlavorException | IOException e) {
            tell.accept("Could not read what was dropped: " + e.getMessage());
            return false;
        }
        for (Object item : files) {
            if (item instanceof File file && file.getName().endsWith(".simp")) {
                open.accept(file.toPath());
                return true;
            }
            // compare (issue 15)
            if (compare != null && item instanceof File file && isPicture(file.getName())) {
                compare.accept(file.toPath());
                return true;
            }
            // check (issue 21)
            if (folder != null && item instanceof File file && file.isDirectory()) {
                folder.accept(file.toPath());
                return true;
            }
        }
        tell.accept(compare == null ? "Drop a .simp file to open it."
                : folder == null ? "Drop a .simp file to open it, or a picture (.png, .jpg) to compare it with the page."
                : "Drop a .simp file to open it, a picture (.png, .jpg) to compare it with the page, "
                        + "or a folder of your pages to check them all.");
        return false;
    }

    // compare (issue 15)
    private static boolean isPicture(String name) {
        String lower = name.toLowerCase(Locale.ROOT);
        return lower.endsWith(".png") || lower.endsWith(".jpg") || lower.endsWith(".jpeg")
                || lower.endsWith(".gif") || lower.endsWith(".bmp");
    }
}
