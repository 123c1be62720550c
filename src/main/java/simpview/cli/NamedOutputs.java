package simpview.cli;

import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import picocli.CommandLine;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParseResult;
import simpview.compare.OutputFiles;

/**
 * The output files a command line names, found in its words as given: for a
 * line that could not be parsed (a mistyped option, a value that is no
 * number), whose options never reached its command, so that a FIFO it names
 * as an output is still opened and closed ({@link OutputFiles#release}) and
 * its reader sees the end of the file. Those are the files named by an option
 * of their own (--out, --diff), and those in a folder option's folder
 * (--out-dir, --html) that the line's words tell it would have written: the
 * tables compare and check write there whatever else the line says, the
 * pages render --all or --page N writes there when the line says which. A
 * file there whose name depends on what the run would have read (a batch's
 * diff images, named for the pictures found; the pictures of --scenes) is
 * not known and left alone: a FIFO it was not going to write may be another
 * program's. For the same reason a file the line also names otherwise (the
 * picture to compare given again as --diff, a scene) is left alone: it may
 * be an input, whose writer must not be let in to write into nothing.
 */
final class NamedOutputs {

    /** A command whose options name files it writes, each a file of its own: render's --out. */
    interface OfCommand {
        /** The options whose value is a file the command writes, e.g. "--out". */
        List<String> outputFileOptions();

        /**
         * The files the command would write in the folders its folder options name in {@code args} (render's
         * --out-dir, compare's --html), as far as the words tell them without being parsed ({@link #valuesOf},
         * {@link #given}); none by default.
         */
        default List<Path> filesInOutputFolders(String[] args) {
            return List.of();
        }
    }

    private NamedOutputs() {
    }

    /**
     * After a usage error in parsing at {@code where}: each file that
     * {@code args} names by an output option of its command is released. At
     * the top (the command's name mistyped, "rendr"), the options are those of
     * the command it was taken for.
     */
    static void release(CommandLine where, String[] args) {
        if (args == null) {
            return;
        }
        Object command = where.getCommand();
        if (where.getParent() == null) {
            for (String word : args) {
                Optional<String> meant = SimpviewCommand.mistypedCommand(word, where.getSubcommands().keySet());
                if (meant.isPresent()) {
                    command = where.getSubcommands().get(meant.get()).getCommand();
                    break;
                }
            }
        }
        if (command instanceof OfCommand writer) {
            filesNamed(writer, args).forEach(OutputFiles::release);
        }
    }

    /**
     * The words of the line being parsed at {@code where}, each @FILE replaced by the words it holds as picocli
     * read them ("render @args.txt" names --out in args.txt); {@code args} as given when picocli kept none.
     */
    static String[] expanded(CommandLine where, String[] args) {
        CommandLine top = where;
        while (top.getParent() != null) {
            top = top.getParent();
        }
        ParseResult parsed = top.getParseResult();
        return parsed == null || parsed.expandedArgs().isEmpty() ? args : parsed.expandedArgs().toArray(String[]::new);
    }

    /**
     * At the end of a command's run, failed or not: once it listed the files it writes ({@code files}), each FIFO
     * among them it did not write is opened and closed ({@link OutputPaths#releaseUnwritten}: a page that failed,
     * those after a write that failed, a diff image not made); after a usage error met before that ({@code files}
     * null), each file its line (as {@link #expanded}) names by one of its output options, as after a line that
     * cannot be parsed: so that no reader is left waiting.
     */
    static void releaseAtEnd(OutputPaths files, int code, CommandSpec spec, OfCommand command) {
        if (files != null) {
            files.releaseUnwritten();
            return;
        }
        if (code == ExitCode.OK) {
            return;
        }
        String[] words = expanded(spec.commandLine(), new String[0]);
        filesNamed(command, words).forEach(OutputFiles::release);
    }

    /** The files {@code args} names as outputs of {@code command}: by its output options, and in its folders. */
    static List<Path> filesNamed(OfCommand command, String[] args) {
        return filesNamed(command.outputFileOptions(), command.filesInOutputFolders(args), args);
    }

    /**
     * The values {@code args} gives {@code option}, as "--out-dir D" or "--out-dir=D", in order, up to "--"
     * (after it, every word is a parameter).
     */
    static List<String> valuesOf(String option, String[] args) {
        List<String> values = new ArrayList<>();
        for (int i = 0; i < args.length && !"--".equals(args[i]); i++) {
            if (args[i].equals(option) && i + 1 < args.length) {
                values.add(args[i + 1]);
                i++;
            } else if (args[i].startsWith(option + "=")) {
                values.add(args[i].substring(option.length() + 1));
            }
        }
        return values;
    }

    /** Whether {@code args} gives {@code option} (a word of its own, or with "="), before any "--". */
    static boolean given(String option, String[] args) {
        for (int i = 0; i < args.length && !"--".equals(args[i]); i++) {
            if (args[i].equals(option) || args[i].startsWith(option + "=")) {
                return true;
            }
        }
        return false;
    }

    /**
     * The files named {@code names} in each folder {@code args} gives {@code option} ("--out-dir"); none for
     * a value that is empty or no path.
     */
    static List<Path> inFolders(String option, List<String> names, String[] args) {
        List<Path> files = new ArrayList<>();
        for (String folder : valuesOf(option, args)) {
            if (folder.isEmpty()) {
                continue;
            }
            try {
                Path given = Path.of(folder);
                for (String name : names) {
                    files.add(given.resolve(name));
                }
            } catch (InvalidPathException e) {
                // no folder: nothing in it
            }
        }
        return files;
    }

    /**
     * The values {@code args} gives the options {@code options}, as "--out F" or "--out=F", up to "--" (after it,
     * every word is a parameter); "-" (standard output) is no file; then the files {@code inFolders} (those a
     * folder option's folder would hold). Each file is listed once, however many names it is given, and none that
     * another word of the line names too (a word of its own, or the value in "--scene=F"): that one may be read.
     */
    static List<Path> filesNamed(List<String> options, List<Path> inFolders, String[] args) {
        Map<Path, Path> files = new LinkedHashMap<>();
        Set<Integer> values = new HashSet<>();
        int end = args.length;
        for (int i = 0; i < args.length; i++) {
            if ("--".equals(args[i])) {
                end = i;
                break;
            }
            for (String option : options) {
                String value = null;
                if (args[i].equals(option) && i + 1 < args.length) {
                    value = args[i + 1];
                    values.add(i + 1);
                } else if (args[i].startsWith(option + "=")) {
                    value = args[i].substring(option.length() + 1);
                    values.add(i);
                }
                if (value != null && !value.isEmpty() && !"-".equals(value)) {
                    String named = value;
                    identity(named).ifPresent(file -> files.putIfAbsent(file, Path.of(named)));
                }
            }
        }
        for (Path inFolder : inFolders) {
            identity(inFolder.toString()).ifPresent(file -> files.putIfAbsent(file, inFolder));
        }
        Set<Path> namedOtherwise = new HashSet<>();
        for (int i = 0; i < args.length; i++) {
            if (values.contains(i) || i < end && options.contains(args[i])) {
                continue;
            }
            String word = args[i];
            int equals = word.indexOf('=');
            if (i < end && word.startsWith("-") && equals > 0) {
                word = word.substring(equals + 1);
            }
            identity(word).ifPresent(namedOtherwise::add);
        }
        files.keySet().removeAll(namedOtherwise);
        return new ArrayList<>(files.values());
    }

    /** The file {@code word} names ({@link OutputFiles#identity}), or none when it can be no path. */
    private static Optional<Path> identity(String word) {
        try {
            return Optional.of(OutputFiles.identity(Path.of(word)));
        } catch (InvalidPathException e) {
            return Optional.empty();
        }
    }
}
