package simpview.pages;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import simpview.scene.SceneException;
import simpview.scene.simp.ScenePipeline;
import simpview.scene.simp.Setting;
import simpview.surface.PageCanvas;
import simpview.surface.Rgb;

/** Pages 4 to 8: a SIMP scene drawn with depth cueing from a near colour to black. */
public final class ScenePage implements Page {

    private final String title;
    private final String fileName;
    private final boolean ownScene;
    private final Rgb near;

    private ScenePage(String title, String fileName, boolean ownScene, Rgb near) {
        this.title = title;
        this.fileName = fileName;
        this.ownScene = ownScene;
        this.near = near;
    }

    /** A scene the project wrote, from the project's own scene folder. */
    public static ScenePage own(String title, String fileName, Rgb near) {
        return new ScenePage(title, fileName, true, near);
    }

    /** A course scene, from the scene folder the user chose, near colour white. */
    public static ScenePage course(String fileName) {
        return new ScenePage(fileName, fileName, false, Rgb.WHITE);
    }

    @Override
    public String title() {
        return title;
    }

    /** None: a scene page's primitives are its file's. */
    @Override
    public List<ListedPrimitive> primitives(PageContext context) {
        return List.of();
    }

    /** Whether it is one of the course's scenes (read from the folder {@link PageContext#simpDir} names), not one of simpview's own. */
    public boolean isCourses() {
        return !ownScene;
    }

    /** The depth cue's near colour (far is black). */
    public Rgb near() {
        return near;
    }

    /** The scene file this page reads in {@code context}. */
    public Path file(PageContext context) {
        return (ownScene ? context.ownSimpDir() : context.simpDir()).resolve(fileName);
    }

    /**
     * The page's scene file, when it is there; else the error that says
     * where it was looked for and, for a course's file, how to name its folder.
     */
    public Path existingFile(PageContext context) throws SceneException {
        Path file = file(context);
        if (!Files.isRegularFile(file)) {
            Path dir = ownScene ? context.ownSimpDir() : context.simpDir();
            Path folder = dir.toAbsolutePath().normalize();
            String missing = fileName + " was not found in " + folder;
            if (ownScene) {
                throw new SceneException(file, 0, 0, "", missing);
            }
            String setting = context.monitor().nameOf(Setting.COURSE_FOLDER);
            if (Files.isRegularFile(folder) && folder.getParent() != null) {
                // the course's page6.simp named itself, not its folder
                throw new SceneException(file, 0, 0, "", missing + ", which is a file, not a folder: name its "
                        + "folder, " + folder.getParent() + ", with " + setting);
            }
            throw new SceneException(file, 0, 0, "", missing + "; name the folder of the course's scene files with "
                    + setting);
        }
        return file;
    }

    @Override
    public void draw(PageCanvas canvas, PageContext context) throws SceneException {
        Path file = existingFile(context);
        ScenePipeline.draw(file, canvas, ScenePipeline.Options.depthCued(near, context.library())
                .withOwnColours(context.ownColours()), context.monitor());
    }
}
