package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;

/** Every option of every command (its every spelling) is in README.md, which a user reads first. */
public class ReadmeOptionsTest {

    @Test
    void everyOptionOfEveryCommandIsInTheReadme() throws IOException {
        String readme = Files.readString(Path.of(System.getProperty("simpview.projectDir", ".")).resolve("README.md"));
        CommandLine root = new CommandLine(new SimpviewCommand(() -> true));
        Set<String> missing = new TreeSet<>();
        for (CommandLine command : commands(root)) {
            CommandSpec spec = command.getCommandSpec();
            for (OptionSpec option : spec.options()) {
                if (option.usageHelp() || option.versionHelp() || option.hidden()) {
                    continue;
                }
                for (String name : option.names()) {
                    if (name.startsWith("--") && !Pattern.compile("(?<![\\w-])" + name + "(?![\\w-])")
                            .matcher(readme).find()) {
                        missing.add(spec.qualifiedName() + " " + name);
                    }
                }
            }
        }
        assertEquals(Set.of(), missing, "options --help shows that README.md does not name");
    }

    private static List<CommandLine> commands(CommandLine root) {
        List<CommandLine> all = new ArrayList<>(List.of(root));
        all.addAll(root.getSubcommands().values());
        return all;
    }
}
