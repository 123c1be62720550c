package simpview.scene.simp;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.geometry.Camera;
import simpview.geometry.Vertex;
import simpview.raster.LineRenderer;
import simpview.raster.PolygonRenderer;
import simpview.scene.SceneException;
import simpview.testing.RecordingDrawable;

/** The stack of files: includes, their errors, depth and file descriptors. */
class FileStackTest {

    @TempDir
    Path dir;

    @Test
    void missingFileNamesThePathLookedFor() throws Exception {
        SceneFixture scene = new SceneFixture(dir);
        scene.write("s", "# top", "\tfile \"nothere\"");
        SceneException e = scene.failure("s");
        assertEquals(dir.resolve("s.simp"), e.file());
        assertEquals(2, e.line());
        assertEquals(7, e.column());
        assertEquals("\tfile \"nothere\"", e.lineText());
        assertEquals("file not found: nothere.simp; looked for " + dir.resolve("nothere.simp").toAbsolutePath().normalize()
                + " and " + Path.of("nothere.simp").toAbsolutePath().normalize(), e.problem());
    }

    /**
     * A name that misses a file only by case, as a scene written on Windows
     * or macOS names it: the file that is there is named. A name found in
     * neither place gets no such hint.
     */
    @Test
    void aFileThatDiffersOnlyInCaseIsNamed() throws Exception {
        SceneFixture scene = new SceneFixture(dir);
        scene.write("Cube", "line (0,0,-1) (1,1,-1)");
        Files.createDirectory(dir.resolve("parts"));
        new SceneFixture(dir.resolve("parts")).write("Wheel", "line (0,0,-1) (1,1,-1)");
        scene.write("s", "file \"cube\"");
        assertTrue(scene.failure("s").problem().startsWith("file not found: cube.simp (there is Cube.simp: names are"
                + " case-sensitive here); looked for " + dir.resolve("cube.simp")), "beside the scene");
        scene.write("s", "file \"parts/wheel\"");
        assertTrue(scene.failure("s").problem().startsWith("file not found: parts/wheel.simp (there is parts/Wheel.simp:"
                + " names are case-sensitive here); looked for "), "in a folder");
        scene.write("s", "file \"cubes\"");
        assertTrue(scene.failure("s").problem().startsWith("file not found: cubes.simp; looked for "), "no near miss");
    }

    /**
     * A part in a folder of its own that names a file as the scene's folder sees it ("parts/wheel" inside
     * parts/car.simp): names are looked for from the folder of the file holding the command, so it is not found
     * (unless the scene runs in its own folder, the working directory); the error names the file that is there
     * and how to name it from the part. A name found from no including file's folder gets no such hint.
     */
    @Test
    void aNameReadFromTheIncludingFilesFolderSaysHowToNameIt() throws Exception {
        SceneFixture scene = new SceneFixture(dir);
        Path parts = Files.createDirectory(dir.resolve("parts"));
        Files.createDirectory(parts.resolve("round"));
        scene.write("parts/round/wheel", "line (0,0,-1) (1,1,-1)");
        scene.write("parts/car", "file \"parts/round/wheel\"");
        scene.write("s", "file \"parts/car\"");
        SceneException e = scene.failure("s");
        assertEquals(parts.resolve("car.simp"), e.file());
        assertEquals("file not found: parts/round/wheel.simp; there is " + parts.resolve("round/wheel.simp")
                + ", this name read from the folder of s.simp, but a name is looked for from the folder of the file"
                + " that holds the command, car.simp: write file \"round/wheel\"; looked for "
                + parts.resolve("parts/round/wheel.simp") + " and " + Path.of("parts/round/wheel.simp").toAbsolutePath(),
                e.problem());
        scene.write("parts/car", "file \"parts/round/tyre\"");
        assertTrue(scene.failure("s").problem().startsWith("file not found: parts/round/tyre.simp; looked for "));
    }

    /** The working directory, the second place looked, is named in full. */
    @Test
    void aFileThatDiffersOnlyInCaseInTheWorkingDirectoryIsNamedInFull() throws Exception {
        Path scenes = Files.createDirectory(dir.resolve("scenes"));
        Path working = Files.createDirectory(dir.resolve("working"));
        Files.writeString(working.resolve("Teapot.obj"), "");
        FilePlaces places = FilePlaces.of(scenes.resolve("s.simp"), "teapot", ".obj", working);
        assertEquals(" (there is " + working.resolve("Teapot.obj") + ": names are case-sensitive here)",
                places.nearMisses("teapot"));
        assertEquals("", FilePlaces.of(scenes.resolve("s.simp"), "kettle", ".obj", working).nearMisses("kettle"));
    }

    /**
     * A name that misses its file only by the extension says what to write: a model named to {@code file}, or
     * a scene file to {@code obj} (the other command draws it); a file whose own extension is not the one added
     * (Oct.OBJ, wing.txt: rename it); a name given the wrong extension (obj "oct.simp" beside oct.obj: leave it
     * off). In the working directory the file is named in full. A name near nothing gets no such hint.
     */
    @Test
    void aFileThatDiffersOnlyInItsExtensionIsNamed() throws Exception {
        Path scenes = Files.createDirectory(dir.resolve("scenes"));
        Path working = Files.createDirectory(dir.resolve("working"));
        Path from = scenes.resolve("s.simp");
        for (String file : List.of("oct.obj", "Oct.OBJ", "cube.simp", "wing.txt")) {
            Files.writeString(scenes.resolve(file), "");
        }
        Files.writeString(working.resolve("tyre.obj"), "");
        assertEquals(" (there is oct.obj, a model: obj \"oct\" draws it)",
                FilePlaces.of(from, "oct", ".simp", working).nearMisses("oct"));
        assertEquals(" (there is oct.obj, a model: obj \"oct\" draws it)",
                FilePlaces.of(from, "oct.obj", ".simp", working).nearMisses("oct.obj"));
        assertEquals(" (there is cube.simp, a scene file: file \"cube\" includes it)",
                FilePlaces.of(from, "cube", ".obj", working).nearMisses("cube"));
        assertEquals(" (there is Oct.OBJ, but obj adds .obj to the name it is given: rename the file Oct.obj and write"
                + " obj \"Oct\")", FilePlaces.of(from, "Oct.OBJ", ".obj", working).nearMisses("Oct.OBJ"));
        assertEquals(" (there is wing.txt, but obj adds .obj to the name it is given: rename the file wing.obj and"
                + " write obj \"wing\")", FilePlaces.of(from, "wing.txt", ".obj", working).nearMisses("wing.txt"));
        assertEquals(" (there is oct.obj: obj adds .obj to the name it is given, so write obj \"oct\")",
                FilePlaces.of(from, "oct.simp", ".obj", working).nearMisses("oct.simp"));
        assertEquals(" (there is " + working.resolve("tyre.obj") + ", a model: obj \"tyre\" draws it)",
                FilePlaces.of(from, "tyre", ".simp", working).nearMisses("tyre"));
        assertEquals("", FilePlaces.of(from, "kettle", ".obj", working).nearMisses("kettle"));
        for (String name : List.of("/", "", ".", "..", "a/")) {
            assertEquals("", FilePlaces.of(from, name, ".obj", working).nearMisses(name), "a name of no file: " + name);
        }
        SceneFixture scene = new SceneFixture(scenes);
        scene.write("s", "file \"oct\"");
        assertTrue(scene.failure("s").problem().startsWith("file not found: oct.simp (there is oct.obj, a model: obj"
                + " \"oct\" draws it); looked for "), "from a scene");
    }

    /** A backslash is part of a name on this system, not a folder separator: the name with / is suggested. */
    @Test
    void aBackslashInANameGetsAHint() throws Exception {
        SceneFixture scene = new SceneFixture(dir);
        scene.write("s", "file \"parts\\cube\"");
        SceneException e = scene.failure("s");
        assertTrue(e.problem().startsWith("file not found: parts\\cube.simp (a backslash is part of a name here: write"
                + " \"parts/cube\", with / between folders); looked for "), e.problem());
        scene.write("s", "file \"parts\\\\cube\"");
        e = scene.failure("s");
        assertTrue(e.problem().startsWith("file not found: parts\\\\cube.simp (a backslash is part of a name here:"
                + " write \"parts/cube\", with / between folders); looked for "), e.problem());
    }

    /** A name in single quotes, as Python or a shell quotes it, is not a quoted name here: write it in '"'. */
    @Test
    void aNameInSingleQuotesGetsAHint() throws Exception {
        SceneFixture scene = new SceneFixture(dir);
        scene.write("cube", "line (0,0,-1) (1,1,-1)");
        scene.write("s", "file 'cube'");
        SceneException e = scene.failure("s");
        assertTrue(e.problem().startsWith("file not found: 'cube'.simp (a name is quoted with '\"', not with \"'\": "
                + "write file \"cube\"); looked for "), e.problem());
        assertEquals(" (a name is quoted with '\"', not with \"'\": write obj \"cube\")",
                FilePlaces.of(dir.resolve("s.simp"), "'cube'", ".obj", dir).nearMisses("'cube'"), "a model's name too");
        scene.write("s", "file \"it's\"");
        assertTrue(scene.failure("s").problem().startsWith("file not found: it's.simp; looked for "),
                "a quote inside a name is part of it");
    }

    @Test
    void missingTopFileIsAnError() {
        SceneException e = assertThrows(SceneException.class,
                () -> ScenePipeline.drawDepthCued(dir.resolve("absent.simp"), SceneFixture.NOWHERE, SceneMonitor.NONE));
        assertEquals(0, e.line());
        assertTrue(e.problem().startsWith("file not found: ") && e.problem().endsWith("absent.simp"), e.problem());
    }

    @Test
    void fileCycleNamesTheChain() throws Exception {
        SceneFixture scene = new SceneFixture(dir);
        scene.write("a", "file \"b\"");
        scene.write("b", "line (0,0,-1) (1,1,-1)", "file a");
        SceneException e = scene.failure("a");
        assertEquals(dir.resolve("b.simp"), e.file());
        assertEquals(2, e.line());
        assertEquals(6, e.column());
        assertEquals("file cycle: a.simp → b.simp → a.simp", e.problem());
        assertEquals(1, scene.lines.size(), "what came before the error was drawn");
    }

    /**
     * A cycle through two folders' files of one name names each by its folder too, as the files at the start of
     * a message are named: "x.simp → x.simp → x.simp" would not say which file to mend.
     */
    @Test
    void fileCycleTellsTwoFoldersFilesOfOneNameApart() throws Exception {
        Files.createDirectories(dir.resolve("parts"));
        SceneFixture scene = new SceneFixture(dir);
        scene.write("s", "file \"x\"");
        scene.write("x", "file \"parts/x\"");
        Files.write(dir.resolve("parts/x.simp"), List.of("file \"../x\""));
        assertEquals("file cycle: x.simp → parts/x.simp → x.simp", scene.failure("s").problem());
    }

    @Test
    void fileIncludingItselfIsACycle() throws Exception {
        SceneFixture scene = new SceneFixture(dir);
        scene.write("self", "{", "file self", "}");
        assertEquals("file cycle: self.simp → self.simp", scene.failure("self").problem());
    }

    @Test
    void includingTheSameFileTwiceInARowIsNoCycle() throws Exception {
        SceneFixture scene = new SceneFixture(dir);
        scene.write("leaf", "line (0,0,-1) (1,1,-1)");
        scene.write("s", "file leaf", "file leaf", "{", "file leaf", "}");
        scene.run("s");
        assertEquals(3, scene.lines.size());
    }

    @Test
    void folderIsNoSceneFile() throws Exception {
        Files.createDirectories(dir.resolve("box.simp"));
        SceneFixture scene = new SceneFixture(dir);
        scene.write("s", "file box");
        SceneException e = scene.failure("s");
        assertTrue(e.problem().startsWith("not a file but a folder: "), e.problem());
        assertEquals(1, e.line());
    }

    @Test
    void deviceIsNoSceneFile() throws Exception {
        Assumptions.assumeTrue(Files.exists(Path.of("/dev/zero")), "no /dev/zero on this system");
        Files.createSymbolicLink(dir.resolve("zero.simp"), Path.of("/dev/zero"));
        SceneFixture scene = new SceneFixture(dir);
        scene.write("s", "file zero");
        assertTrue(scene.failure("s").problem().startsWith("not a regular file"));
    }

    /** Makes {@code link}, leading to {@code target} as written; the test is skipped where links cannot be made. */
    private static void link(Path link, String target) {
        try {
            Files.createSymbolicLink(link, Path.of(target));
        } catch (IOException | UnsupportedOperationException | SecurityException e) {
            Assumptions.abort("no symbolic links here: " + e);
        }
    }

    /**
     * An include and a top file that are a loop of symbolic links, or a link to what does not exist (an obj:
     * RenderCommandTest):
     * each is there, as ls shows it, so "file not found" sent one looking for a file; the error says what the
     * link is, at the command, with its include chain.
     */
    @Test
    void aLinkThatLeadsNowhereIsNamedAsOne() throws Exception {
        Path parts = Files.createDirectory(dir.resolve("parts"));
        link(parts.resolve("loop.simp"), "back.simp");
        link(parts.resolve("back.simp"), "loop.simp");
        link(parts.resolve("gone.simp"), "nothere.simp");
        SceneFixture scene = new SceneFixture(dir);
        scene.write("s", "# top", "file \"parts/car\"");
        scene.write("parts/car", "file \"loop\"");
        SceneException e = scene.failure("s");
        assertEquals(parts.resolve("car.simp") + ":1:6, included from " + dir.resolve("s.simp") + ":2: loop.simp is a "
                + "loop of symbolic links (loop.simp → back.simp → loop.simp); looked for " + parts.resolve("loop.simp")
                + " and " + Path.of("loop.simp").toAbsolutePath(), e.getMessage().lines().findFirst().orElseThrow());
        scene.write("parts/car", "file \"gone\"");
        assertTrue(scene.failure("s").problem().startsWith("gone.simp is a link to nothere.simp, which does not exist"
                + "; looked for "), scene.failure("s").problem());
        SceneException top = new SceneFixture(parts).failure("loop");
        assertEquals(parts.resolve("loop.simp") + " is a loop of symbolic links (loop.simp → back.simp → loop.simp)",
                top.problem());
    }

    @Test
    void errorsInIncludedFilesNameThatFile() throws Exception {
        SceneFixture scene = new SceneFixture(dir);
        scene.write("bad", "wire", "rotate Q 5");
        scene.write("s", "{", "file bad", "}");
        SceneException e = scene.failure("s");
        assertEquals(dir.resolve("bad.simp"), e.file());
        assertEquals(2, e.line());
        assertEquals(8, e.column());
    }

    /**
     * An error 3,000 includes deep names the first five and last five files
     * of the chain (the erring file among the first) and how many stand
     * between, not 3,000 of them; a chain of ten is named whole
     * (docs/simp.md). The count is of the files left out, no more.
     */
    @Test
    void aLongIncludeChainIsShortenedInAnError() throws Exception {
        assertEquals("f8.simp:2, included from f7.simp:2, included from f6.simp:2, included from f5.simp:2,"
                + " included from f4.simp:2, included from f3.simp:2, included from f2.simp:2, included from f1.simp:2,"
                + " included from f0.simp:2", chainOfFailure(10));
        assertEquals("f9.simp:2, included from f8.simp:2, included from f7.simp:2, included from f6.simp:2,"
                + " ... 1 more ..., included from f4.simp:2, included from f3.simp:2, included from f2.simp:2,"
                + " included from f1.simp:2, included from f0.simp:2", chainOfFailure(11));
        assertEquals("f10.simp:2, included from f9.simp:2, included from f8.simp:2, included from f7.simp:2,"
                + " ... 2 more ..., included from f4.simp:2, included from f3.simp:2, included from f2.simp:2,"
                + " included from f1.simp:2, included from f0.simp:2", chainOfFailure(12));
        assertEquals("f11.simp:2, included from f10.simp:2, included from f9.simp:2, included from f8.simp:2,"
                + " ... 3 more ..., included from f4.simp:2, included from f3.simp:2, included from f2.simp:2,"
                + " included from f1.simp:2, included from f0.simp:2", chainOfFailure(13));
        assertEquals("f2998.simp:2, included from f2997.simp:2, included from f2996.simp:2, included from"
                + " f2995.simp:2, ... 2990 more ..., included from f4.simp:2, included from f3.simp:2,"
                + " included from f2.simp:2, included from f1.simp:2, included from f0.simp:2", chainOfFailure(3000));
        assertEquals("f2.simp:2, included from f1.simp:2, included from f0.simp:2", chainOfFailure(4));
    }

    /** The includes named by an error in the last file of a chain of {@code files} files. */
    private String chainOfFailure(int files) throws Exception {
        writeChain(files);
        Files.write(dir.resolve("f" + (files - 1) + ".simp"), List.of("rotate Q 5"));
        SceneException e = new SceneFixture(dir).failure("f0");
        assertEquals(dir.resolve("f" + (files - 1) + ".simp"), e.file());
        return e.includedFrom();
    }

    /** A file cycle thousands of files round is shortened as an include chain is; a short one is named whole. */
    @Test
    void aLongFileCycleIsShortenedInAnError() throws Exception {
        writeChain(3000);
        Files.write(dir.resolve("f2999.simp"), List.of("file \"f1\""));
        assertEquals("file cycle: f1.simp → f2.simp → f3.simp → f4.simp → f5.simp → ... 2990 more ... → f2996.simp"
                + " → f2997.simp → f2998.simp → f2999.simp → f1.simp", new SceneFixture(dir).failure("f0").problem());
        writeChain(3);
        Files.write(dir.resolve("f2.simp"), List.of("file \"f1\""));
        assertEquals("file cycle: f1.simp → f2.simp → f1.simp", new SceneFixture(dir).failure("f0").problem());
    }

    /** A name through ".." is shown without it, as the error's file and in the chain, and stays relative. */
    @Test
    void pathsInAnErrorAndItsChainAreNormalised() throws Exception {
        Files.createDirectories(dir.resolve("cyc/x"));
        Files.write(dir.resolve("cyc/c.simp"), List.of("rotate Q 5"));
        Files.write(dir.resolve("cyc/b.simp"), List.of("file \"x/../c\""));
        Files.write(dir.resolve("s.simp"), List.of("file \"cyc/x/../b\""));
        SceneException e = new SceneFixture(dir).failure("s");
        assertEquals(dir.resolve("cyc/c.simp"), e.file());
        assertEquals("b.simp:1, included from " + dir.resolve("s.simp") + ":1", e.includedFrom());
        Path top = Files.write(dir.resolve("cyc/x/top.simp"), List.of("file \"../b\""));
        SceneException across = new SceneFixture(dir.resolve("cyc/x")).failure("top");
        assertEquals(dir.resolve("cyc/c.simp"), across.file());
        assertEquals("b.simp:1, included from " + top + ":1", across.includedFrom());
        assertTrue(top.isAbsolute());
    }

    /** f0 includes f1 ... includes f(depth-1); each draws a line after its include. */
    private void writeChain(int depth) throws Exception {
        for (int i = 0; i < depth; i++) {
            List<String> lines = new ArrayList<>();
            lines.add("# level " + i);
            if (i + 1 < depth) {
                lines.add("file \"f" + (i + 1) + "\"");
            }
            lines.add("line (0, " + i / 10.0 + ", -1) (1, " + i / 10.0 + ", -1)");
            Files.write(dir.resolve("f" + i + ".simp"), lines);
        }
    }

    @Test
    void includeChainThousandDeepKeepsFewFilesOpen() throws Exception {
        int depth = 1000;
        writeChain(depth);
        FileStack files = new FileStack(-1); // stream every file, as a large one would be
        int[] mostOpen = {0};
        int[] deepest = {0};
        List<Double> order = new ArrayList<>();
        LineRenderer lines = (p, q, d) -> {
            order.add(p.y());
            mostOpen[0] = Math.max(mostOpen[0], files.openFiles());
            deepest[0] = Math.max(deepest[0], files.depth());
        };
        PolygonRenderer none = (p, q, r, d) -> { };
        SimpClient client = new SimpClient(SceneFixture.NOWHERE, lines, none, none, files);
        new SimpInterpreter(client, SceneMonitor.NONE).run(dir.resolve("f0.simp"));
        assertEquals(depth, order.size());
        assertEquals(depth, deepest[0]);
        assertTrue(mostOpen[0] <= FileStack.MAX_OPEN, "open files: " + mostOpen[0]);
        // The innermost file draws first, then each level on the way back out.
        assertEquals(Camera.PARALLEL.panelX((depth - 1) / 10.0, 0), order.get(0));
        assertEquals(Camera.PARALLEL.panelX(0, 0), order.get(depth - 1));
        assertEquals(0, files.depth());
    }

    @Test
    void includeChainThousandDeepFromMemoryToo() throws Exception {
        writeChain(1000);
        SceneFixture scene = new SceneFixture(dir);
        scene.run("f0");
        assertEquals(1000, scene.lines.size());
    }

    @Test
    void suspendedFileGoesOnWhereItLeftOff() throws Exception {
        // A file longer than one read chunk, suspended in the middle by a deep include.
        StringBuilder big = new StringBuilder();
        for (int i = 0; i < 3000; i++) {
            big.append("line (").append(i / 100.0).append(", 0, -1) (0, 0, -1)").append(" ".repeat(40)).append('\n');
            if (i == 1500) {
                big.append("file \"f0\"\n");
            }
        }
        Files.writeString(dir.resolve("big.simp"), big);
        writeChain(2 * FileStack.MAX_OPEN);
        SceneFixture scene = new SceneFixture(dir);
        scene.run("big", new FileStack(-1));
        assertEquals(3000 + 2 * FileStack.MAX_OPEN, scene.lines.size());
        List<Double> xs = new ArrayList<>();
        for (Vertex[] l : scene.lines) {
            xs.add(l[0].x());
        }
        assertEquals(Camera.PARALLEL.panelX(15.01, 0), xs.get(1501 + 2 * FileStack.MAX_OPEN));
        assertEquals(Camera.PARALLEL.panelX(29.99, 0), xs.get(xs.size() - 1));
    }

    @Test
    void monitorHearsLinesAndCanCancel() throws Exception {
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < 10_000; i++) {
            sb.append("translate 0 0 0\n");
        }
        Files.writeString(dir.resolve("long.simp"), sb);
        List<Long> reports = new ArrayList<>();
        SceneMonitor cancelLater = new SceneMonitor() {
            @Override
            public void linesRead(long lines) {
                reports.add(lines);
            }

            @Override
            public boolean cancelled() {
                return reports.size() >= 3;
            }
        };
        assertThrows(SceneCancelledException.class,
                () -> ScenePipeline.drawDepthCued(dir.resolve("long.simp"), SceneFixture.NOWHERE, cancelLater));
        assertEquals(3, reports.size());
        assertTrue(reports.get(0) > 0 && reports.get(2) > reports.get(0), reports.toString());
        assertTrue(reports.get(2) < 10_000);
    }

    @Test
    void monitorHearsTheFinalLineCount() throws Exception {
        SceneFixture scene = new SceneFixture(dir);
        scene.write("leaf", "# one", "wire");
        scene.write("s", "file leaf", "", "file leaf");
        long[] last = {0};
        ScenePipeline.drawDepthCued(dir.resolve("s.simp"), SceneFixture.NOWHERE, new SceneMonitor() {
            @Override
            public void linesRead(long lines) {
                last[0] = lines;
            }
        });
        assertEquals(3 + 2 + 2, last[0]);
    }

    @Test
    void anErrorInAnIncludedFileNamesTheLinesThatIncludedIt(@TempDir Path where) throws Exception {
        Files.writeString(where.resolve("cube.simp"), "# a cube\n{\nfrobnicate\n");
        Files.writeString(where.resolve("box.simp"), "scale 1 1 1\nfile \"cube\"\n");
        Path page = Files.writeString(where.resolve("page4.simp"), "# page\n\n{\nfile \"box\"\n}\n");
        for (long readAheadFrom : new long[] {Long.MAX_VALUE, 0}) {
            SceneException e = assertThrows(SceneException.class, () -> new SimpInterpreter(
                    new SimpClient(new RecordingDrawable(650, 650)), SceneMonitor.NONE, readAheadFrom)
                    .run(page));
            assertTrue(e.getMessage().startsWith(where.resolve("cube.simp") + ":3:1, included from box.simp:2, "
                    + "included from page4.simp:4: unknown command 'frobnicate'"), e.getMessage());
            assertEquals(3, e.line());
        }
    }

    /** An including file in another folder than the file named before it is named by its path, not its name alone. */
    @Test
    void anIncludingFileOfAnotherFolderIsNamedByItsPath(@TempDir Path where) throws Exception {
        Files.createDirectories(where.resolve("a"));
        Files.createDirectories(where.resolve("b"));
        Files.writeString(where.resolve("a/part.simp"), "frobnicate\n");
        Files.writeString(where.resolve("b/part.simp"), "\nfile \"../a/part\"\n");
        Path top = Files.writeString(where.resolve("top.simp"), "file \"b/part\"\n");
        SceneException e = assertThrows(SceneException.class, () -> new SimpInterpreter(
                new SimpClient(new RecordingDrawable(650, 650)), SceneMonitor.NONE, Long.MAX_VALUE)
                .run(top));
        // the path through "b/.." is shown without it
        assertTrue(e.getMessage().startsWith(where.resolve("a/part.simp") + ":1:1, included from "
                + where.resolve("b/part.simp") + ":2, included from " + top + ":1: unknown command"), e.getMessage());
    }
}
