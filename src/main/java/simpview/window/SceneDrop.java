package simpview.window;

import java.awt.datatransfer.DataFlavor;
import java.awt.datatransfer.UnsupportedFlavorException;
import java.io.File;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.BiConsumer;
import java.util.function.Consumer;
import javax.swing.TransferHandler;

/**
 * Opens the .simp files dropped on the window (several become its first pages, as on the command line); a picture
 * dropped is compared with the page (issue 15); a folder dropped is checked, every page picture in it, as
 * {@code simpview check} does (issue 21). What the first file it knows is decides which; the files of a drop left
 * out are named in words for the status line.
 */
public final class SceneDrop extends TransferHandler {

    private static final long serialVersionUID = 1L;

    /** The scenes dropped, in the order given, and the words that name what the drop left out ("" for nothing). */
    private final transient BiConsumer<List<Path>, String> open;
    private final transient Consumer<String> tell;
    // compare (issue 15): pictures dropped go here; null when the window does not compare
    private final transient Consumer<Path> compare;
    // check (issue 21): a folder dropped goes here; null when the window does not check folders
    private final transient Consumer<Path> folder;

    SceneDrop(BiConsumer<List<Path>, String> open, Consumer<String> tell) {
        this(open, null, null, tell);
    }

    SceneDrop(BiConsumer<List<Path>, String> open, Consumer<Path> compare, Consumer<String> tell) {
        this(open, compare, null, tell);
    }

    SceneDrop(BiConsumer<List<Path>, String> open, Consumer<Path> compare, Consumer<Path> folder,
            Consumer<String> tell) {
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
        List<Path> scenes = new ArrayList<>();
        for (Object item : files) {
            if (item instanceof File file && isScene(file)) {
                scenes.add(file.toPath());
            }
        }
        for (Object item : files) {
            if (!scenes.isEmpty() && item instanceof File file && isScene(file)) {
                open.accept(List.copyOf(scenes), leftOut(files));
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

    /**
     * What a drop of scenes leaves out, its files that are no scene, in words for the status line ("Left out
     * notes.txt and b.png: ..."), or "" when it leaves out nothing.
     */
    private static String leftOut(List<?> dropped) {
        List<String> names = new ArrayList<>();
        for (Object item : dropped) {
            if (!(item instanceof File file && isScene(file))) {
                names.add(item instanceof File file ? file.getName() : String.valueOf(item));
            }
        }
        if (names.isEmpty()) {
            return "";
        }
        String named = names.size() == 1 ? names.get(0)
                : String.join(", ", names.subList(0, names.size() - 1)) + " and " + names.get(names.size() - 1);
        return "Left out " + named + ": a drop with .simp files opens those alone (drop a picture or a folder "
                + "on its own).";
    }

    private static boolean isScene(File file) {
        return file.getName().endsWith(".simp");
    }

    // compare (issue 15)
    private static boolean isPicture(String name) {
        String lower = name.toLowerCase(Locale.ROOT);
        return lower.endsWith(".png") || lower.endsWith(".jpg") || lower.endsWith(".jpeg")
                || lower.endsWith(".gif") || lower.endsWith(".bmp");
    }
}
