package simpview.testing;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.imageio.ImageIO;
import simpview.pages.PageRenderer;
import simpview.scene.SceneException;

/** `gradle updateGoldens`: re-renders every golden image on purpose. */
public final class GoldenUpdater {

    private GoldenUpdater() {
    }

    public static void main(String[] args) throws IOException {
        Path dir = Path.of(args[0]);
        Files.createDirectories(dir);
        List<GoldenCase> cases = new ArrayList<>(GoldenCase.seededPages());
        cases.addAll(GoldenCase.ownScenePages());
        cases.addAll(GoldenCase.coursePages());
        PageRenderer renderer = new PageRenderer();
        int failed = 0;
        for (GoldenCase c : cases) {
            Path file = dir.resolve(c.name() + ".png");
            try {
                ImageIO.write(renderer.renderImage(c.page(), c.context()), "png", file.toFile());
                System.out.println("wrote " + file);
            } catch (SceneException e) {
                failed++;
                System.err.println("not remade, " + c.name() + ": " + e.getMessage());
            }
        }
        for (LitGoldens.Case c : LitGoldens.all()) {
            Path file = dir.resolve(c.name() + ".png");
            try {
                ImageIO.write(c.render(), "png", file.toFile());
                System.out.println("wrote " + file);
            } catch (SceneException e) {
                failed++;
                System.err.println("not remade, " + c.name() + ": " + e.getMessage());
            }
        }
        if (GoldenCase.courseSimpDir() == null) {
            System.out.println("course scenes not found beside the project: pages 6-8 were not remade");
        }
        if (failed > 0) {
            System.exit(1);
        }
    }
}
