package simpview.window;

import java.awt.datatransfer.DataFlavor;
import java.awt.datatransfer.Transferable;
import java.io.File;
import java.nio.file.Path;
import java.util.List;
import javax.swing.TransferHandler.TransferSupport;

/** Files as a desktop's drag and drop hands them over: a list of files, and nothing else. */
final class DroppedFiles {

    private DroppedFiles() {
    }

    /** The files named, as given (relative names stay relative). */
    static Transferable named(String... names) {
        return of(List.of(names).stream().map(File::new).toList());
    }

    static Transferable of(Path... files) {
        return of(List.of(files).stream().map(Path::toFile).toList());
    }

    private static Transferable of(List<File> files) {
        return new Transferable() {
            @Override
            public DataFlavor[] getTransferDataFlavors() {
                return new DataFlavor[] {DataFlavor.javaFileListFlavor};
            }

            @Override
            public boolean isDataFlavorSupported(DataFlavor flavor) {
                return DataFlavor.javaFileListFlavor.equals(flavor);
            }

            @Override
            public Object getTransferData(DataFlavor flavor) {
                return files;
            }
        };
    }

    /** Drops the files on the window's frame, as the desktop would, on the EDT: whether the window took them. */
    static boolean dropOn(WindowDriver driver, Path... files) throws Exception {
        SimpviewWindow window = driver.window();
        return driver.onEdt(() -> window.frame().getTransferHandler()
                .importData(new TransferSupport(window.frame().getRootPane(), of(files))));
    }
}
