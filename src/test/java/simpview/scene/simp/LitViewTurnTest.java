package simpview.scene.simp;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.io.TempDir;
import simpview.geometry.Axis;
import simpview.geometry.Matrix4;
import simpview.surface.PageCanvas;

/**
 * The window's orbit on a lit scene moves the camera: drawing with a view
 * turn O (camera space, after W) shows what the same scene shows with its
 * camera placed by C * inverse(O), written as commands before the camera.
 * Lights given before the camera and after it must go with the world. The
 * two are computed differently, so they may differ by rounding only.
 */
class LitViewTurnTest {

    @TempDir
    Path dir;

    @ParameterizedTest
    @CsvSource({"30, 0", "0, -25", "-140, 40"})
    void aTurnedViewIsTheSceneSeenFromACameraMovedTheOtherWay(double yaw, double pitch) throws Exception {
        double[] c = {2, -1, -30};
        String undo = String.format(Locale.ROOT, "translate %s %s %s\nrotate Y %s\nrotate X %s\ntranslate %s %s %s\n",
                c[0], c[1], c[2], -yaw, -pitch, -c[0], -c[1], -c[2]);
        Path plain = Files.writeString(dir.resolve("plain.simp"), scene(""));
        Path moved = Files.writeString(dir.resolve("moved.simp"), scene(undo));
        Matrix4 turn = Matrix4.translation(c[0], c[1], c[2]).times(Matrix4.rotation(Axis.X, pitch))
                .times(Matrix4.rotation(Axis.Y, yaw)).times(Matrix4.translation(-c[0], -c[1], -c[2]));

        BufferedImage unturned = draw(plain, null);
        BufferedImage turned = draw(plain, turn);
        BufferedImage expected = draw(moved, null);
        int panel = PageCanvas.PANEL * PageCanvas.PANEL;
        assertTrue(differing(unturned, turned, 8) > panel / 20, "the turn changes the picture");
        int off = differing(expected, turned, 2);
        assertTrue(off < panel / 400, off + " pixels differ by more than 2/255 from the moved camera's picture");
    }

    /** A lit room: a light before the camera, one after it, a floor, a wall and a box, phong. */
    private static String scene(String beforeCamera) {
        return String.join("\n",
                "ambient 0.15 0.15 0.15",
                "{", "translate -10 12 -20", "light 1 0.9 0.8 1 0.01", "}",
                "{", "translate 0 4 0", beforeCamera + "camera -1 -1 1 1 -1 -200", "}",
                "{", "translate 12 2 -35", "light 0.3 0.4 1 1 0", "}",
                "surface 0.8 0.8 0.8 0.6 20",
                "polygon (-40, -5, 0) (40, -5, 0) (40, -5, -80)",
                "polygon (-40, -5, 0) (40, -5, -80) (-40, -5, -80)",
                "surface 0.9 0.4 0.3",
                "polygon (-40, -5, -60) (40, -5, -60) (40, 30, -60)",
                "polygon (-40, -5, -60) (40, 30, -60) (-40, 30, -60)",
                "surface 0.3 0.9 0.4",
                "gouraud",
                "polygon (-4, -5, -26) (6, -5, -26) (6, 5, -30)",
                "polygon (-4, -5, -26) (6, 5, -30) (-4, 5, -30)",
                "flat",
                "polygon (6, -5, -26) (8, -5, -36) (8, 5, -36)",
                "line (-30, 20, -50) (30, 20, -50)", "");
    }

    private static BufferedImage draw(Path scene, Matrix4 turn) throws Exception {
        PageCanvas canvas = new PageCanvas();
        canvas.clear();
        ScenePipeline.draw(scene, canvas, ScenePipeline.Options.lit(new SceneLibrary()), new SceneMonitor() {
            @Override
            public Matrix4 viewTurn() {
                return turn;
            }
        });
        return canvas.snapshot();
    }

    /** Pixels where some channel differs by more than {@code by}. */
    private static int differing(BufferedImage a, BufferedImage b, int by) {
        int n = 0;
        for (int y = 0; y < a.getHeight(); y++) {
            for (int x = 0; x < a.getWidth(); x++) {
                int p = a.getRGB(x, y);
                int q = b.getRGB(x, y);
                for (int shift = 0; shift <= 16; shift += 8) {
                    if (Math.abs((p >> shift & 0xFF) - (q >> shift & 0xFF)) > by) {
                        n++;
                        break;
                    }
                }
            }
        }
        return n;
    }
}
