package simpview.scene.simp;

import java.util.ArrayList;
import simpview.scene.SceneException;
import simpview.stage.PrimitiveTrace;
import simpview.surface.PageCanvas;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.nio.file.Files;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The files a scene reads or looks for, as the pipeline tells them and the
 * window watches them: its .simp files and the .obj models they name, found
 * by the reader itself while it reads (no second pass over the files).
 */
class ReachedFilesTest {

    private static final String MODEL = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

    @TempDir
    Path dir;

    /** Stands for the working directory, so that no test writes into the real one. */
    private Path working;
    private Path scenes;

    @BeforeEach
    void folders() throws IOException {
        working = Files.createDirectory(dir.resolve("working"));
        scenes = Files.createDirectory(dir.resolve("scenes"));
    }

    private static Path write(Path file, String text) throws IOException {
        Files.createDirectories(file.getParent());
        return Files.writeString(file, text);
    }

    /** The files drawing {@code top} reached, an error or not, with {@link #working} as the working directory. */
    private List<Path> reached(Path top) {
        return reached(top, ScenePipeline.Options.byCommands(new SceneLibrary()).withWorkingDir(working));
    }

    private static List<Path> reached(Path top, ScenePipeline.Options options) {
        List<List<Path>> told = new ArrayList<>();
        SceneMonitor monitor = new SceneMonitor() {
            @Override
            public void reached(List<Path> files) {
                told.add(files);
            }
        };
        PageCanvas canvas = new PageCanvas();
        List<Path> drawn = null;
        try {
            drawn = ScenePipeline.draw(top, canvas, options, monitor).files();
        } catch (SceneException e) {
            // the files reached up to the error are told all the same
        }
        assertEquals(1, told.size(), "the monitor is told once");
        if (drawn != null) {
            assertEquals(drawn, told.get(0), "what was drawn says the same");
        }
        return told.get(0);
    }

    @Test
    void modelsBesideTheSceneAreListedQuotedOrBareInTheOrderMet() throws Exception {
        Path bowling = write(scenes.resolve("bowling.obj"), MODEL);
        Path pin = write(scenes.resolve("pin.obj"), MODEL);
        Path top = write(scenes.resolve("lit.simp"),
                "ambient 0.2 0.2 0.2\nobj \"bowling\"\n{\n\tobj\tpin\n}\nobj bowling\n");
        assertEquals(List.of(top, bowling, pin), reached(top), "each model once, none from the working directory");
    }

    @Test
    void aModelNamedInAnIncludedFileIsLookedForBesideThatFile() throws Exception {
        Path part = write(scenes.resolve("parts/part.simp"), "obj \"wheel\"\n");
        Path wheel = write(scenes.resolve("parts/wheel.obj"), MODEL);
        write(scenes.resolve("wheel.obj"), MODEL); // beside the top file: not the one part.simp names
        Path top = write(scenes.resolve("car.simp"), "file \"parts/part\"\n");
        assertEquals(List.of(top, part, wheel), reached(top));
    }

    @Test
    void aModelOnlyInTheWorkingDirectoryIsListedWithThePlaceThatWouldTakeItOver() throws Exception {
        Path model = write(working.resolve("bowling.obj"), MODEL);
        Path top = write(scenes.resolve("lit.simp"), "obj \"bowling\"\n");
        assertEquals(List.of(top, model, scenes.resolve("bowling.obj")), reached(top));
        assertFalse(Files.exists(scenes.resolve("bowling.obj")), "watched for appearing");
    }

    @Test
    void aMissingModelIsWatchedAtBothPlacesTheReaderLooks() throws Exception {
        Path top = write(scenes.resolve("lit.simp"), "obj \"notyet\"\n");
        assertEquals(List.of(top, scenes.resolve("notyet.obj"), working.resolve("notyet.obj")), reached(top));
    }

    @Test
    void theRealWorkingDirectoryIsTheOneThePublicMethodUses() throws Exception {
        Path top = write(scenes.resolve("lit.simp"), "obj \"no-such-model-3f9\"\n");
        assertEquals(List.of(top, scenes.resolve("no-such-model-3f9.obj"),
                Path.of("no-such-model-3f9.obj").toAbsolutePath()),
                reached(top, ScenePipeline.Options.byCommands(new SceneLibrary())));
    }

    @Test
    void theExtensionIsAlwaysAddedAsTheReaderAddsIt() throws Exception {
        write(scenes.resolve("bowling.obj"), MODEL);
        Path top = write(scenes.resolve("lit.simp"), "obj \"bowling.obj\"\n");
        assertEquals(List.of(top, scenes.resolve("bowling.obj.obj"), working.resolve("bowling.obj.obj")),
                reached(top), "the reader looks for bowling.obj.obj, so that is what is watched");
    }

    @Test
    void aSceneInTheWorkingDirectoryListsAMissingModelOnce() throws Exception {
        Path top = write(working.resolve("lit.simp"), "obj gone\n");
        assertEquals(List.of(top, working.resolve("gone.obj")), reached(top));
    }

    @Test
    void aMissingIncludeIsWatchedToo() throws Exception {
        Path top = write(scenes.resolve("top.simp"), "file \"later\"\n");
        assertEquals(List.of(top, scenes.resolve("later.simp"), working.resolve("later.simp")), reached(top));
    }

    @Test
    void windowsLineEndsAreHandled() throws Exception {
        Path model = write(scenes.resolve("m.obj"), MODEL);
        Path a = write(scenes.resolve("a.simp"), "file b\r\nobj m\r\n");
        Path b = write(scenes.resolve("b.simp"), "wire\r\n");
        assertEquals(List.of(a, b, model), reached(a));
    }

    @Test
    void anIncludeCycleEndsTheReadingAndWhatWasReadIsWatched() throws Exception {
        write(scenes.resolve("m.obj"), MODEL);
        Path a = write(scenes.resolve("a.simp"), "file b\nobj m\n");
        Path b = write(scenes.resolve("b.simp"), "file \"a\"\n");
        assertEquals(List.of(a, b), reached(a), "a save of either file fixes the cycle, and then m is read");
    }

    @Test
    void aMissingTopFileIsWatchedForItToAppear() {
        Path absent = scenes.resolve("absent.simp");
        assertEquals(List.of(absent), reached(absent));
    }

    @Test
    void namesAreTheNamesTheReaderRead() throws Exception {
        Path spaced = write(scenes.resolve("a b.simp"), "wire\n");
        Path top = write(scenes.resolve("top.simp"), "file \"a b\"  \nfile\tcube\r\n");
        assertEquals(List.of(top, spaced, scenes.resolve("cube.simp"), working.resolve("cube.simp")), reached(top));
    }

    @Test
    void aModelIsLookedUpOnceAPictureHoweverOftenItIsDrawn() throws Exception {
        Path model = write(scenes.resolve("m.obj"), MODEL);
        Path top = write(scenes.resolve("twice.simp"),
                "camera -1 -1 1 1 -1 -100\ntranslate 0 0 -5\nobj m\nobj \"m\"\n");
        SceneLibrary library = new SceneLibrary();
        List<Integer> read = new ArrayList<>();
        SceneMonitor deletingAfterTheFirstFace = new SceneMonitor() {
            @Override
            public PrimitiveTrace trace() {
                return new PrimitiveTrace() {
                    @Override
                    public void read(int index, Path file, int line, int kind, double[] p, int at, int stride,
                            int vertices) {
                        read.add(index);
                        try {
                            Files.deleteIfExists(model);
                        } catch (IOException e) {
                            throw new UncheckedIOException(e);
                        }
                    }

                    @Override
                    public boolean drawing(int index) {
                        return true;
                    }
                };
            }
        };
        ScenePipeline.Options options = ScenePipeline.Options.lit(library).withWorkingDir(working);
        ScenePipeline.draw(top, new PageCanvas(), options, deletingAfterTheFirstFace);
        assertEquals(List.of(0, 1), read, "the second obj draws the model the picture looked up, gone since");
        SceneException next = assertThrows(SceneException.class,
                () -> ScenePipeline.draw(top, new PageCanvas(), options, SceneMonitor.NONE));
        assertEquals(3, next.line(), "the next picture looks again: " + next.getMessage());
    }
}
