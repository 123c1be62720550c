package simpview.window;

import simpview.compare.PngFiles;
import simpview.window.render.RenderedView;

import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import javax.swing.JFileChooser;
import javax.swing.JFrame;
import javax.swing.JOptionPane;
import javax.swing.filechooser.FileNameExtensionFilter;

/** The window's file dialogs: open a scene, save the page as PNG. On the EDT. */
public final class FileDialogs {

    private final JFrame owner;
    private File sceneFolder;
    private File saveFolder = new File(".");

    FileDialogs(JFrame owner, Path simpDir) {
        this.owner = owner;
        this.sceneFolder = simpDir.toFile();
    }

    /**
     * Asks for a .simp file to open, starting in {@code shownSceneFolder} (the
     * folder of the scene on screen), or where the dialog was last left when
     * that is null (at first the course's pages' folder).
     */
    Optional<Path> chooseScene(Path shownSceneFolder) {
        try {
            return askForScene(shownSceneFolder);
        } finally {
            owner.requestFocus(); // the keys back to the page, which no window manager may give it
        }
    }

    private Optional<Path> askForScene(Path shownSceneFolder) {
        JFileChooser chooser = new JFileChooser(shownSceneFolder != null ? shownSceneFolder.toFile() : sceneFolder);
        chooser.setDialogTitle("Open a SIMP scene");
        chooser.setFileFilter(new FileNameExtensionFilter("SIMP scenes (*.simp)", "simp"));
        if (chooser.showOpenDialog(owner) != JFileChooser.APPROVE_OPTION) {
            return Optional.empty();
        }
        sceneFolder = chooser.getCurrentDirectory();
        return Optional.of(chooser.getSelectedFile().toPath());
    }

    /**
     * Asks where to save the page and writes it; returns the file written. The
     * page is the one shown when asked: its pixels are copied first, as the
     * window may give a turning frame's image back to be drawn on while the
     * dialog is open.
     */
    Optional<Path> save(RenderedView view) {
        BufferedImage shown = view.image();
        BufferedImage page = new BufferedImage(shown.getColorModel(), shown.copyData(null),
                shown.isAlphaPremultiplied(), null);
        try {
            return askAndSave(view.suggestedFileName(), page);
        } finally {
            owner.requestFocus(); // the keys back to the page, which no window manager may give it
        }
    }

    private Optional<Path> askAndSave(String suggestedName, BufferedImage page) {
        JFileChooser chooser = new JFileChooser(saveFolder);
        chooser.setDialogTitle("Save the page as PNG");
        chooser.setFileFilter(new FileNameExtensionFilter("PNG images (*.png)", "png"));
        chooser.setSelectedFile(new File(saveFolder, suggestedName));
        if (chooser.showSaveDialog(owner) != JFileChooser.APPROVE_OPTION) {
            return Optional.empty();
        }
        saveFolder = chooser.getCurrentDirectory();
        Path file = PngFiles.withPngExtension(chooser.getSelectedFile().toPath());
        if (!PngFiles.isPngName(file)) {
            JOptionPane.showMessageDialog(owner, file.getFileName() + ": simpview saves PNG files only; name it .png",
                    "Save page", JOptionPane.ERROR_MESSAGE);
            return Optional.empty();
        }
        if (Files.exists(file) && JOptionPane.showConfirmDialog(owner, file + " exists. Replace it?",
                "Save page", JOptionPane.YES_NO_OPTION) != JOptionPane.YES_OPTION) {
            return Optional.empty();
        }
        try {
            PngFiles.write(page, file);
            return Optional.of(file);
        } catch (IOException e) {
            JOptionPane.showMessageDialog(owner, e.getMessage(), "Save page", JOptionPane.ERROR_MESSAGE);
            return Optional.empty();
        }
    }
}
