package simpview.testing;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import simpview.scene.SceneException;
import simpview.scene.simp.SceneLibrary;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.ScenePipeline;
import simpview.surface.DrawingThreads;
import simpview.surface.PageCanvas;

/**
 * The golden images of lit scenes: the project's own (own-lit-shading,
 * own-lit-corridor, own-lit-lights, from simp/), every page of the course's
 * third assignment (a3-pageA ... a3-tomsPageJ) and of its fourth
 * (a4-page-a1 ... a4-page-h), drawn from ../shared/course-simp-a3 and
 * course-simp-a4.
 */
public final class LitGoldens {

    /** The scenes of each assignment that are pages (the others are parts they include). */
    public static final List<String> A3 = List.of("pageA", "pageB", "pageC", "pageD", "pageE", "pageF", "pageG",
            "pageH", "pageI", "tomsPageJ");
    public static final List<String> A4 = List.of("page-a1", "page-a2", "page-a3", "page-b1", "page-b2", "page-b3",
            "page-c1", "page-c2", "page-c3", "page-d", "page-e", "page-f1", "page-f2", "page-g", "page-h");

    /** The project's own lit scenes under simp/, which come with every clone. */
    public static final List<String> OWN = List.of("lit-shading", "lit-corridor", "lit-lights");

    private LitGoldens() {
    }

    /** One golden: its name and its scene file. */
    public record Case(String name, Path scene) {
        @Override
        public String toString() {
            return name;
        }

        public BufferedImage render() throws SceneException {
            return render(1);
        }

        /** The scene drawn by that many threads. */
        public BufferedImage render(int threads) throws SceneException {
            try (DrawingThreads drawing = DrawingThreads.of(threads)) {
                PageCanvas canvas = new PageCanvas();
                canvas.drawWith(drawing);
                ScenePipeline.draw(scene, canvas, ScenePipeline.Options.lit(new SceneLibrary()),
                        SceneMonitor.NONE);
                return canvas.snapshot();
            }
        }
    }

    /** The cases of one folder ("course-simp-a3" with prefix "a3"), or none when it is absent. */
    public static List<Case> cases(String folder, String prefix, List<String> scenes) {
        Path dir = CourseFiles.folder(folder);
        List<Case> cases = new ArrayList<>();
        if (Files.isDirectory(dir)) {
            for (String s : scenes) {
                cases.add(new Case(prefix + "-" + s, dir.resolve(s + ".simp")));
            }
        }
        return cases;
    }

    /** The project's own lit scenes, as own-lit-shading and so on. */
    public static List<Case> own() {
        Path dir = Goldens.projectDir().resolve("simp");
        List<Case> cases = new ArrayList<>();
        for (String s : OWN) {
            cases.add(new Case("own-" + s, dir.resolve(s + ".simp")));
        }
        return cases;
    }

    public static List<Case> all() {
        List<Case> all = new ArrayList<>(own());
        all.addAll(cases("course-simp-a3", "a3", A3));
        all.addAll(cases("course-simp-a4", "a4", A4));
        return all;
    }
}
