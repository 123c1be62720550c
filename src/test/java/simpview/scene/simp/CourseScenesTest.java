package simpview.scene.simp;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import simpview.testing.CourseFiles;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import simpview.surface.PageCanvas;
import simpview.surface.Rgb;

/** The course's own scenes, read from where the build says they are; never copied into the project. */
class CourseScenesTest {

    private static Path courseDir() {
        return CourseFiles.requireSimpDir();
    }

    @ParameterizedTest
    @ValueSource(strings = {"page6.simp", "page7.simp", "page8.simp"})
    void courseScenesRenderWithoutError(String name) throws Exception {
        Path file = courseDir().resolve(name);
        PageCanvas canvas = new PageCanvas();
        List<String> warnings = new ArrayList<>();
        ScenePipeline.drawDepthCued(file, canvas.depthCued(Rgb.WHITE, Rgb.BLACK), new SceneMonitor() {
            @Override
            public void warning(String message) {
                warnings.add(message);
            }
        });
        assertEquals(List.of(), warnings);
        int lit = 0;
        for (int y = 0; y < PageCanvas.PANEL; y++) {
            for (int x = 0; x < PageCanvas.PANEL; x++) {
                lit += (canvas.panel().getPixel(x, y) & 0xFFFFFF) != 0 ? 1 : 0;
            }
        }
        assertTrue(lit > 10_000, name + " lit only " + lit + " pixels");
    }
}
