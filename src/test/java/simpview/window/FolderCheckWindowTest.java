package simpview.window;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.datatransfer.DataFlavor;
import java.awt.datatransfer.Transferable;
import java.awt.image.BufferedImage;
import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import javax.imageio.ImageIO;
import javax.swing.TransferHandler;
import org.junit.jupiter.api.Test;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;
import simpview.scene.simp.SceneDrawer;
import simpview.window.instruments.FolderCheck;

/** A folder dropped on the real window is checked as {@code simpview check} checks it (issue 21). */
class FolderCheckWindowTest extends WindowTestCase {

    private static final long SEED = 361;

    @Test
    void aDroppedFolderIsCheckedPageByPage() throws Exception {
        Path mine = Files.createDirectories(dir.resolve("mine"));
        PageContext context = PageContext.defaults().withSeed(SEED);
        ImageIO.write(new PageRenderer().renderImage(1, context), "png", mine.resolve("page1.png").toFile());
        BufferedImage two = new PageRenderer().renderImage(2, context);
        for (int y = 200; y < 300; y++) {
            for (int x = 200; x < 300; x++) {
                two.setRGB(x, y, 0x00FFFF);
            }
        }
        ImageIO.write(two, "png", mine.resolve("page2.png").toFile());
        driver = WindowDriver.open(new WindowOptions(SEED, TestScenes.courseSimpDir(), Optional.empty()), SceneDrawer.SIMP);

        Transferable folder = new Transferable() {
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
                return List.of(new File(mine.toString()));
            }
        };
        assertTrue(driver.onEdt(() -> driver.window().frame().getTransferHandler().importData(
                new TransferHandler.TransferSupport(driver.window().frame().getRootPane(), folder))), "the window took the folder");
        driver.awaitEdt(() -> driver.window().lastCheck() != null, "the folder's table");

        String table = driver.onEdt(() -> driver.window().lastCheck());
        assertEquals(FolderCheck.text(mine, context.withSimpDir(TestScenes.courseSimpDir())), table);
        assertTrue(table.contains("page1.png  page 1 (seed 361)  PASS"), table);
        assertTrue(table.contains("page2.png  page 2 (seed 361)  FAIL"), table);
        assertTrue(table.contains("no picture of page 8 found"), table);
        assertTrue(table.endsWith("1 of 2 pictures pass; 6 pages without a picture\n"), table);
        assertEquals("mine: 1 of 2 pictures pass; 6 pages without a picture",
                driver.onEdt(() -> driver.window().status().text()));
    }
}
