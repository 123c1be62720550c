package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import picocli.CommandLine;

/**
 * The examples each command's --help ends with: each is printed whole, as
 * written (one too long for the help's width would be folded into a broken
 * command), and each is a command line simpview accepts.
 */
public class HelpExamplesTest {

    @ParameterizedTest
    @ValueSource(strings = {"render", "compare", "check", "inspect"})
    void everyExampleIsPrintedWholeAndParses(String command) {
        CliRun help = CliRun.of(command, "--help");
        assertEquals(ExitCode.OK, help.exitCode(), help.err());
        List<String> examples = examples(help.out());
        assertFalse(examples.isEmpty(), help.out());
        for (String example : examples) {
            List<String> words = ArgumentLine.split(example);
            assertEquals("simpview", words.get(0), example);
            assertEquals(command, words.get(1), example);
            CommandLine parser = new CommandLine(new SimpviewCommand(() -> false));
            assertDoesNotThrow(() -> parser.parseArgs(words.subList(1, words.size()).toArray(String[]::new)),
                    example);
            // pages 6 to 8 are the course's scenes: copied without --simp-dir, such an example grades nothing
            boolean coursePages = example.matches(".* --pages [0-9,-]*(6|7|8|[1-5]-[6-8]).*");
            assertTrue(!coursePages || example.contains("--simp-dir "), "an example without --simp-dir: " + example);
        }
    }

    /**
     * The lines after "Examples:" up to the first blank one, a line ending in
     * a backslash joined to the next; every line must be an example's start
     * ("  simpview ") or the continuation of one.
     */
    private static List<String> examples(String help) {
        List<String> examples = new ArrayList<>();
        String[] lines = help.split("\\R");
        int at = List.of(lines).indexOf("Examples:");
        assertTrue(at >= 0, help);
        StringBuilder pending = null;
        for (int i = at + 1; i < lines.length && !lines[i].isBlank(); i++) {
            String line = lines[i];
            if (pending == null) {
                assertTrue(line.startsWith("  simpview "), "not an example's first line (folded?): " + line);
                pending = new StringBuilder();
            } else {
                assertTrue(line.startsWith("      "), "not a continuation: " + line);
            }
            boolean continued = line.endsWith(" \\");
            pending.append(continued ? line.substring(0, line.length() - 1) : line).append(' ');
            if (!continued) {
                examples.add(pending.toString().trim());
                pending = null;
            }
        }
        assertEquals(null, pending, "an example ends with a backslash");
        return examples;
    }
}
