package simpview.cli;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import picocli.CommandLine;
import simpview.compare.OutputFiles;

/**
 * The output files a command line names, found in its words as given: for a
 * line that could not be parsed (a mistyped option, a value that is no
 * number), whose options never reached its command, so that a FIFO it names
 * as an output is still opened and closed ({@link OutputFiles#release}) and
 * its reader sees the end of the file. Only files named by an option of their
 * own are released, never those a folder option (--out-dir, --html) would
 * hold: which of those the run would write depends on the options that could
 * not be read, and a FIFO it was not going to write may be another program's.
 */
final class NamedOutputs {

    /** A command whose options name files it writes, each a file of its own: render's --out. */
    interface OfCommand {
        /** The options whose value is a file the command writes, e.g. "--out". */
        List<String> outputFileOptions();
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
            filesNamed(writer.outputFileOptions(), args).forEach(OutputFiles::release);
        }
    }

    /**
     * The values {@code args} gives the options {@code options}, as "--out F" or "--out=F", up to "--" (after it,
     * every word is a parameter); "-" (standard output) is no file.
     */
    static List<Path> filesNamed(List<String> options, String[] args) {
        List<Path> files = new ArrayList<>();
        for (int i = 0; i < args.length && !"--".equals(args[i]); i++) {
            for (String option : options) {
                String value = null;
                if (args[i].equals(option) && i + 1 < args.length) {
                    value = args[i + 1];
                } else if (args[i].startsWith(option + "=")) {
                    value = args[i].substring(option.length() + 1);
                }
                if (value != null && !value.isEmpty() && !"-".equals(value)) {
                    files.add(Path.of(value));
                }
            }
        }
        return files;
    }
}
