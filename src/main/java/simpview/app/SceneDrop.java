package simpview.app;

import java.awt.datatransfer.DataFlavor;
import java.awt.datatransfer.UnsupportedFlavorException;
import java.io.File;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.function.Consumer;
import javax.swing.TransferHandler;

/** Opens a .simp file dropped on the window. */
final class SceneDrop extends TransferHandler {

    private static final long serialVersionUID = 1L;

    private final transient Consumer<Path> open;
    private final transient Consumer<String> tell;

    SceneDrop(Consumer<Path> open, Consumer<String> tell) {
        this.open = open;
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
        }
        tell.accept("Drop a .simp file to open it.");
        return false;
    }
}
