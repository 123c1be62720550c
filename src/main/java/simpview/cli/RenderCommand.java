package simpview.cli;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.ParentCommand;
import picocli.CommandLine.Spec;
import simpview.compare.OutputFiles;
import simpview.compare.PngFiles;
import simpview.pages.Assignment1;
import simpview.pages.Assignment2;
import simpview.pages.Page;
import simpview.pages.PageContext;
import simpview.pages.PageRenderer;
import simpview.pages.SceneList;
import simpview.scene.SceneException;
import simpview.scene.simp.SceneMonitor;
import simpview.scene.simp.ScenePipeline;
import simpview.surface.DrawingThreads;
import simpview.surface.Rgb;

/** {@code simpview render ...}: pages or any scene to PNG, without a window. */
@Command(name = "render",
        mixinStandardHelpOptions = true,
        version = ExitCode.VERSION,
        description = "Renders pages, or any scene as a page, to PNG files (no display needed).",
        footer = {"", "Examples:",
            "  simpview render --page 3 --seed 7 --out page3.png",
            "  simpview render --all --simp-dir course/ --out-dir pages/",
            "  simpview render --assignment 1 --page 2 --out a1-page2.png",
            "  simpview render --assignment 1 --all --seed 7 --out-dir a1/",
            "  simpview render house.simp --out house.png",
            "  simpview render --scene house.simp --near-color 0,1,0 --out house.png",
            "  simpview render --scene house.simp --own-colors --out house.png",
            "  simpview render --scene house.simp --out-dir pictures/",
            "  simpview render --scenes ../shared/course-simp-a3 --out-dir a3/",
            "  simpview render --contact-sheet --out docs/pages.png",
            "  simpview render --contact-sheet --out lit.png \\",
            "      simp/lit-shading.simp simp/lit-lights.simp"},
        exitCodeListHeading = "%nExit codes:%n",
        exitCodeList = {"0:success", "1:scene error, or an output file that cannot be written", "2:usage error"})
public final class RenderCommand implements Callable<Integer>, NamedOutputs.OfCommand {

    /** Exactly one of these says what to render. */
    static final class What {
        @Option(names = "--page", paramLabel = "N", required = true, description = "one page, 1 to 8")
        Integer page;

        @Option(names = "--all", required = true, description = "all eight pages, as page1.png ... page8.png (--assignment 1: a1-page1.png ... a1-page5.png)")
        boolean all;

        @Option(names = "--scene", paramLabel = "F.simp", required = true, description = "any scene, as a full page: lit by its own rules, or depth-cued")
        Path scene;

        @Option(names = "--scenes", arity = "1..*", paramLabel = "F|DIR", required = true,
                description = "every scene named (a folder: its .simp files), each as NAME.png in --out-dir; scenes of "
                        + "one name from different folders as FOLDER-NAME.png (course-simp-a3-cube.png)")
        List<Path> scenes;

        @Option(names = "--contact-sheet", required = true,
                description = "the pages that render (or the SCENE files given), side by side at half size")
        boolean contactSheet;
    }

    @Spec
    private CommandSpec spec;

    /** The top command, which knows where the project's own scenes are. */
    @ParentCommand
    private SimpviewCommand parent;

    /** What to render; when no option says, the SCENE files given do ({@link #impliedByScenes}). */
    @ArgGroup(exclusive = true, multiplicity = "0..1")
    private What what;

    @Option(names = "--assignment", paramLabel = "A",
            description = "whose pages --page and --all mean: 1 (the first assignment's five pages) or 2 (the eight pages; default)")
    private Integer assignment;

    @Option(names = "--seed", paramLabel = "S", description = PageDrawing.SEED_HELP + " (default: 361)")
    private Long seed;

    @Option(names = "--simp-dir", paramLabel = "D", description = "folder holding the course's page6.simp to page8.simp (default: the scene folder below)")
    private Path simpDir;

    @Option(names = "--out", paramLabel = "F.png", description = "the PNG to write (--page, --scene, --contact-sheet)")
    private Path out;

    @Option(names = "--out-dir", paramLabel = "D", description = "the folder to write to (--all: page1.png ... page8.png; --page N: pageN.png; "
            + "--scene and --scenes: NAME.png)")
    private Path outDir;

    @Option(names = "--primitives", paramLabel = "F.txt",
            description = "with --page: write the page's own lines and triangles, as its drawers are given them, to F.txt "
                    + "(- for standard output), with --out or alone: the seeded pages' random values, for your own "
                    + "renderer to draw")
    private Path primitives;

    @Option(names = "--near-color", paramLabel = "r,g,b", converter = RgbConverter.class,
            description = "depth cue colour at z = 0, channels 0 to 1 (depth-cued scenes; default: 1,1,1)")
    private Rgb near;

    @Option(names = "--far-color", paramLabel = "r,g,b", converter = RgbConverter.class,
            description = "depth cue colour at z = -200 (depth-cued scenes; default: 0,0,0)")
    private Rgb far;

    @Parameters(paramLabel = "SCENE", arity = "0..*",
            description = "scenes to draw without naming an option: one file as --scene draws it, several (or a "
                    + "folder) as --scenes; with --contact-sheet, scenes to tile instead of the pages (a folder: its "
                    + ".simp files), each drawn as --scene draws it")
    private List<Path> scenes = new ArrayList<>();

    @Option(names = {"--own-colors", "--own-colours"},
            description = "--scene: draw the vertices' own colours (white where none) without the depth cue")
    private boolean ownColours;

    @Mixin
    private ThreadsOption threads;

    @Mixin
    private A1RuleOption a1Rule;

    @Override
    public List<String> outputFileOptions() {
        return List.of("--out", "--primitives");
    }

    /**
     * The pages --all or --page N would write in --out-dir, and --scene F's picture there, when the words name
     * one of those alone, once, and (for the pages) an assignment that has them. The pictures of --scenes and of
     * SCENE files are not known: which words are scenes depends on the options that could not be read.
     */
    @Override
    public List<Path> filesInOutputFolders(String[] args) {
        List<String> pages = NamedOutputs.valuesOf("--page", args);
        List<String> scene = NamedOutputs.valuesOf("--scene", args);
        boolean all = NamedOutputs.given("--all", args);
        if ((all ? 1 : 0) + pages.size() + scene.size() != 1) {
            return List.of();
        }
        if (!scene.isEmpty()) {
            try {
                Path named = Path.of(scene.get(0));
                return named.getFileName() == null ? List.of()
                        : NamedOutputs.inFolders("--out-dir", List.of(SceneList.pictureName(named)), args);
            } catch (InvalidPathException e) {
                return List.of();
            }
        }
        List<String> assignments = NamedOutputs.valuesOf("--assignment", args);
        if (assignments.size() > 1 || !assignments.isEmpty() && !List.of("1", "2").contains(assignments.get(0))) {
            return List.of();
        }
        boolean first = assignments.equals(List.of("1"));
        int count = first ? Assignment1.COUNT : Assignment2.COUNT;
        int page;
        try {
            page = all ? 0 : Integer.parseInt(pages.get(0));
        } catch (NumberFormatException e) {
            return List.of();
        }
        List<String> names = new ArrayList<>();
        for (int n = 1; n <= count; n++) {
            if (all || n == page) {
                names.add((first ? "a1-page" : "page") + n + ".png");
            }
        }
        return NamedOutputs.inFolders("--out-dir", names, args);
    }

    /** Whether the scenes to draw were given as SCENE files alone, not by --scenes ({@link #impliedByScenes}). */
    private boolean impliedScenes;

    /** The threads drawing while the command runs: made and closed by call(). */
    private DrawingThreads drawingThreads;

    /** The files the run reads and writes, once its options are checked; null before. */
    private OutputPaths files;

    @Override
    public Integer call() {
        int code = ExitCode.SCENE_ERROR;
        try {
            checkOptions();
            try (DrawingThreads drawing = threads.open()) {
                drawingThreads = drawing;
                code = render();
                return code;
            } finally {
                drawingThreads = null;
            }
        } finally {
            NamedOutputs.releaseAtEnd(files, code, spec, this);
        }
    }

    private int render() {
        if (what.page != null) {
            return renderPage(what.page);
        }
        if (what.all) {
            return renderAll();
        }
        if (what.scene != null) {
            return renderScene();
        }
        if (what.scenes != null) {
            return renderScenes();
        }
        return scenes.isEmpty() ? renderContactSheet() : renderSceneSheet();
    }

    /** Options that make no sense together are usage errors (exit 2), not silently ignored. */
    private void checkOptions() {
        if (what == null) {
            what = impliedByScenes();
        }
        if (what.scenes != null) {
            checkScenes();
            return;
        }
        boolean pages = what.scene == null;
        usage(assignment == null || assignment == 1 || assignment == 2,
                "--assignment must be 1 or 2 (the later assignments' pages are scenes: use --scenes), not " + assignment);
        usage(assignment == null || what.page != null || what.all, "--assignment goes with --page or --all");
        usage(!a1Rule.given() || firstAssignment(), "--a1-rule goes with --assignment 1");
        a1Rule.check();
        usage(!firstAssignment() || simpDir == null, "--simp-dir goes with assignment 2's pages: the first assignment's read no files");
        int count = firstAssignment() ? Assignment1.COUNT : Assignment2.COUNT;
        usage(what.page == null || what.page >= 1 && what.page <= count,
                "--page must be 1 to " + count + (firstAssignment() ? " for the first assignment" : "") + ", not " + what.page);
        // --all writes into --out-dir; --page and --scene write --out, or into --out-dir under their own
        // name; a contact sheet writes --out.
        boolean oneFile = what.page != null || what.scene != null;
        if (what.all) {
            usage(out == null, (firstAssignment() ? "--all writes five files (a1-page1.png ... a1-page5.png)"
                    : "--all writes eight files") + ": use --out-dir D, not --out");
            usage(outDir != null, "--all needs --out-dir D");
        } else if (oneFile) {
            usage(out != null || outDir != null || primitives != null, "missing --out F.png (or --out-dir D)");
            usage(out == null || outDir == null, "give --out F.png or --out-dir D, not both");
        } else {
            usage(outDir == null, "--contact-sheet writes one file: use --out F.png, not --out-dir");
            usage(out != null, "missing --out F.png");
        }
        usage(out == null || !out.toString().isEmpty(), "--out needs a file name");
        usage(outDir == null || !outDir.toString().isEmpty(), "--out-dir needs a folder name");
        String outOption = out != null ? "--out" : "--out-dir";
        usage(primitives == null || what.page != null, "--primitives goes with --page N");
        usage(primitives == null || !primitives.toString().isEmpty(), "--primitives needs a file name, or -");
        if (oneFile && out == null && outDir != null) {
            out = outDir.resolve(what.scene != null ? SceneList.pictureName(what.scene)
                    : (firstAssignment() ? "a1-page" : "page") + what.page + ".png");
        }
        files = new OutputPaths().reads(what.scene, "the scene").writes(out, outOption);
        if (primitives != null && !OutputPaths.STANDARD_OUTPUT.equals(primitives.toString())) {
            files.writes(primitives, "--primitives");
        }
        if (what.all) {
            for (int n = 1; n <= count; n++) {
                files.writes(pictureOfAll(n), "--out-dir");
            }
        }
        usage(!pages || near == null && far == null, "--near-color and --far-color go with --scene only");
        usage(pages || seed == null && simpDir == null, "--seed and --simp-dir go with the pages, not with --scene");
        if (!scenes.isEmpty() && !what.contactSheet) {
            usage(false, UsageWords.joined(scenes.stream().map(Path::toString).toList(), "and") + ": a scene file "
                    + "is drawn on its own (simpview render F.simp --out F.png) or tiled with --contact-sheet, not "
                    + "with " + (what.page != null ? "--page" : what.all ? "--all" : "--scene"));
        }
        usage(scenes.isEmpty() || seed == null && simpDir == null,
                "--seed and --simp-dir go with the pages, not with a sheet of scenes");
        usage(!ownColours || !pages, "--own-colors goes with --scene only");
        usage(!ownColours || near == null && far == null,
                "--own-colors draws without the depth cue: it does not go with --near-color or --far-color");
        usage(out == null || PngFiles.isPngName(out), "--out " + out + ": " + PngFiles.PNG_ONLY);
    }

    /**
     * What {@code simpview render house.simp --out house.png} means, no option saying what to render: one scene
     * file is drawn as --scene draws it, several files or a folder as --scenes draws them. Without a SCENE
     * either, the usage error names the choices.
     */
    private What impliedByScenes() {
        usage(!scenes.isEmpty(), "say what to render: --page N, --all, --scene F.simp, --scenes F|DIR... or "
                + "--contact-sheet (or give a scene file: simpview render house.simp --out house.png)");
        What implied = new What();
        if (scenes.size() == 1 && !Files.isDirectory(scenes.get(0))) {
            implied.scene = scenes.get(0);
        } else {
            implied.scenes = List.copyOf(scenes);
            impliedScenes = true;
        }
        scenes = new ArrayList<>();
        return implied;
    }

    /** --scenes: the list must name scenes, and the pictures go to a folder. */
    private void checkScenes() {
        usage(out == null, "--scenes writes one picture per scene: give --out-dir D, not --out");
        usage(outDir != null, (impliedScenes ? "several scenes, or a folder, are drawn" : "--scenes draws")
                + " one picture per scene, NAME.png: give --out-dir D");
        usage(!outDir.toString().isEmpty(), "--out-dir needs a folder name");
        usage(seed == null && simpDir == null, "--seed and --simp-dir go with the pages, not with --scenes");
        usage(!ownColours, "--own-colors goes with --scene only");
        usage(!a1Rule.given(), "--a1-rule goes with --assignment 1");
        usage(primitives == null, "--primitives goes with --page N");
        try {
            sceneList = SceneList.of(what.scenes);
        } catch (IllegalArgumentException e) {
            usage(false, e.getMessage());
        }
        // a scene named twice (a folder and a file of it) is drawn once
        Map<Path, Path> distinct = new LinkedHashMap<>();
        sceneList.forEach(scene -> distinct.putIfAbsent(OutputFiles.identity(scene), scene));
        sceneList = List.copyOf(distinct.values());
        List<String> names = SceneList.pictureNames(sceneList);
        files = new OutputPaths();
        sceneList.forEach(scene -> files.reads(scene, "a scene to draw"));
        Map<String, Path> drawnAs = new HashMap<>();
        pictures = new ArrayList<>();
        for (int i = 0; i < sceneList.size(); i++) {
            Path picture = outDir.resolve(names.get(i));
            Path other = drawnAs.putIfAbsent(names.get(i).toLowerCase(Locale.ROOT), sceneList.get(i));
            usage(other == null, "the scenes " + other + " and " + sceneList.get(i) + " would both be written to "
                    + picture + "; render them into different --out-dir folders");
            files.writes(picture, "--out-dir");
            pictures.add(picture);
        }
    }

    /** The scenes of --scenes, once checked, each named once. */
    private List<Path> sceneList;
    /** Where each scene of {@link #sceneList} is written. */
    private List<Path> pictures;

    /** Depth-cue or own colours given, and the scene's first lit command showed it is lit: a usage error (exit 2). */
    private void refuseIfLit(Path scene, ScenePipeline.Drawn drawn) {
        if (!drawn.drawn()) {
            throw new UsageProblem(PageDrawing.cueColoursProblem(scene, drawn.litBecause(), ownColours));
        }
    }

    private void usage(boolean fine, String message) {
        if (!fine) {
            throw new ParameterException(spec.commandLine(), message);
        }
    }

    private boolean firstAssignment() {
        return assignment != null && assignment == 1;
    }

    private int renderPage(int number) {
        if (primitives != null && writePrimitives(number) != ExitCode.OK) {
            return ExitCode.SCENE_ERROR;
        }
        if (out == null) {
            return ExitCode.OK; // --primitives alone
        }
        if (firstAssignment()) {
            return write(Assignment1.render(number, context()), out);
        }
        try {
            return write(new PageDrawing(monitor(), drawingThreads).page(number, context()).image(), out);
        } catch (SceneException e) {
            err().println(e.getMessage());
            return ExitCode.SCENE_ERROR;
        }
    }

    /** Where --all writes page n: page3.png, or a1-page3.png for the first assignment's. */
    private Path pictureOfAll(int n) {
        return outDir.resolve((firstAssignment() ? "a1-page" : "page") + n + ".png");
    }

    private int renderAll() {
        if (firstAssignment()) {
            for (int n = 1; n <= Assignment1.COUNT; n++) {
                if (write(Assignment1.render(n, context()), pictureOfAll(n)) != ExitCode.OK) {
                    return ExitCode.SCENE_ERROR;
                }
            }
            return ExitCode.OK;
        }
        PageDrawing drawing = new PageDrawing(monitor(), drawingThreads);
        PageContext context = context();
        int code = ExitCode.OK;
        for (int n = 1; n <= Assignment2.COUNT; n++) {
            BufferedImage image;
            try {
                image = drawing.page(n, context).image();
            } catch (SceneException e) {
                err().println("page " + n + " not written: " + e.getMessage());
                code = ExitCode.SCENE_ERROR;
                continue;
            }
            if (write(image, pictureOfAll(n)) != ExitCode.OK) {
                return ExitCode.SCENE_ERROR; // the folder is unwritable: the other pages would fail alike
            }
        }
        return code;
    }

    /** Each scene to NAME.png; one that fails is named on stderr and not written, the others are. */
    private int renderScenes() {
        PageDrawing drawing = new PageDrawing(monitor(), drawingThreads);
        int code = ExitCode.OK;
        for (int i = 0; i < sceneList.size(); i++) {
            Path scene = sceneList.get(i);
            BufferedImage image;
            try {
                ScenePipeline.Drawn drawn = drawing.scene(scene, near, far, false);
                refuseIfLit(scene, drawn);
                image = drawing.canvas().image();
            } catch (SceneException e) {
                err().println(pictures.get(i).getFileName() + " not written: " + e.getMessage());
                code = ExitCode.SCENE_ERROR;
                continue;
            }
            if (write(image, pictures.get(i)) != ExitCode.OK) {
                return ExitCode.SCENE_ERROR;
            }
        }
        return code;
    }

    private int renderScene() {
        try {
            PageDrawing drawing = new PageDrawing(monitor(), drawingThreads);
            ScenePipeline.Drawn drawn = drawing.scene(what.scene, near, far, ownColours);
            refuseIfLit(what.scene, drawn);
            return write(drawing.canvas().image(), out);
        } catch (SceneException e) {
            err().println(e.getMessage());
            return ExitCode.SCENE_ERROR;
        }
    }

    /** Pages that fail are left out and named on stderr; the sheet shows the rest. */
    private int renderContactSheet() {
        PageRenderer renderer = new PageRenderer(drawingThreads);
        PageContext context = context();
        List<ContactSheet.Tile> tiles = new ArrayList<>();
        for (int n = 1; n <= Assignment2.COUNT; n++) {
            try {
                String seedNote = Assignment2.page(n).usesSeed() ? " — seed " + context.seed() : "";
                tiles.add(ContactSheet.Tile.of(n + "  " + Assignment2.page(n).title() + seedNote,
                        renderer.renderImage(n, context)));
            } catch (SceneException e) {
                err().println("page " + n + " left out: " + e.getMessage());
            }
        }
        if (tiles.isEmpty()) {
            err().println(out + " not written: no page rendered");
            return ExitCode.SCENE_ERROR;
        }
        int written = write(ContactSheet.compose(tiles), out);
        return tiles.size() == Assignment2.COUNT ? written : ExitCode.SCENE_ERROR;
    }

    /**
     * The scenes given (a folder: its .simp files, in natural order), in that
     * order, each labelled with its file name; one that fails, or is not
     * there, is named and left out.
     */
    private int renderSceneSheet() {
        List<Path> sheet = new ArrayList<>();
        for (Path named : scenes) {
            if (!Files.isDirectory(named)) {
                sheet.add(named);
                continue;
            }
            try {
                sheet.addAll(SceneList.of(List.of(named)));
            } catch (IllegalArgumentException e) {
                throw new ParameterException(spec.commandLine(), e.getMessage());
            }
        }
        OutputPaths sheetFiles = new OutputPaths();
        sheet.forEach(scene -> sheetFiles.reads(scene, "a scene to draw"));
        files = sheetFiles;
        files.writes(out, "--out");
        List<ContactSheet.Tile> tiles = new ArrayList<>();
        PageDrawing drawing = new PageDrawing(monitor(), drawingThreads);
        for (Path scene : sheet) {
            try {
                drawing.scene(scene, null, null, false);
                tiles.add(ContactSheet.Tile.of(String.valueOf(scene.getFileName()), drawing.canvas().image()));
            } catch (SceneException e) {
                err().println(scene + " left out: " + e.getMessage());
            }
        }
        if (tiles.isEmpty()) {
            err().println(out + " not written: no scene rendered");
            return ExitCode.SCENE_ERROR;
        }
        int written = write(ContactSheet.compose(tiles), out);
        return tiles.size() == sheet.size() ? written : ExitCode.SCENE_ERROR;
    }

    /** --primitives: the page's own lines and triangles; a page that draws a scene file has none of its own. */
    private int writePrimitives(int number) {
        Page page = firstAssignment() ? Assignment1.page(number) : Assignment2.page(number);
        PageContext context = context();
        if (page.primitives(context).isEmpty()) {
            throw new UsageProblem("--primitives: page " + number + " draws a scene file (" + page.title()
                    + "): its primitives are that file's lines");
        }
        String listing = PrimitiveListing.of(page, (firstAssignment() ? "the first assignment's page " : "page ")
                + number, context);
        if (OutputPaths.STANDARD_OUTPUT.equals(primitives.toString())) {
            spec.commandLine().getOut().print(listing);
            spec.commandLine().getOut().flush();
            return ExitCode.OK;
        }
        try {
            OutputFiles.writeString(primitives, listing);
            files.wrote(primitives);
            return ExitCode.OK;
        } catch (IOException e) {
            err().println("simpview: " + e.getMessage());
            return ExitCode.SCENE_ERROR;
        }
    }

    private int write(BufferedImage image, Path file) {
        try {
            PngFiles.write(image, file);
            files.wrote(file);
            return ExitCode.OK;
        } catch (IOException e) {
            err().println("simpview: " + e.getMessage());
            return ExitCode.SCENE_ERROR;
        }
    }

    private PageContext context() {
        return a1Rule.applyTo(PageDrawing.context(parent.ownScenes(), seed, simpDir, monitor()));
    }

    private SceneMonitor monitor() {
        return PageDrawing.warningsTo(err());
    }

    private PrintWriter err() {
        return spec.commandLine().getErr();
    }
}
