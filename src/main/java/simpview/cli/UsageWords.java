package simpview.cli;

import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import picocli.CommandLine.MaxValuesExceededException;
import picocli.CommandLine.MutuallyExclusiveArgsException;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.UnmatchedArgumentException;
import simpview.pages.Assignment1;
import simpview.pages.Assignment2;

/**
 * A usage error in a student's words rather than the parser's: picocli's
 * own messages name argument groups by their synopsis, Java's types ("not
 * an int") and argument indexes. Messages simpview wrote itself pass
 * through as they are.
 */
final class UsageWords {

    /** A matched member of an exclusive group, as picocli lists it: "(--page=N | --all ...)={--page=3}". */
    private static final Pattern MATCHED = Pattern.compile("=\\{([^}]*)\\}");
    private static final Pattern OPTION = Pattern.compile("--[a-z0-9][a-z0-9-]*");
    private static final Pattern UNMATCHED = Pattern.compile("^Unmatched arguments? (?:at|from) index \\d+: (.*)$");
    private static final List<String[]> TYPES = List.of(
            new String[] {"' is not an int", "' is not a whole number"},
            new String[] {"' is not a long", "' is not a whole number"},
            new String[] {"' is not a double", "' is not a number"},
            new String[] {"' is not a float", "' is not a number"});
    /** A whole number in digits, as a user writes one: one that is not a long or an int is out of range. */
    private static final Pattern WHOLE = Pattern.compile("[-+]?[0-9]+");
    /** The option a value is of, as picocli names it: "Invalid value for option '--page': ...". */
    private static final Pattern OPTION_NAMED = Pattern.compile("option '(--[a-z0-9][a-z0-9-]*)'");
    /**
     * The whole-number options that take a range of their own, and that range, as each command says it of a value
     * outside it ("--page must be 1 to 8, not 9"): a value too large for an int is told the same range.
     */
    private static final Map<String, String> RANGES = Map.of(
            "--page", "1 to " + Assignment2.COUNT + " (1 to " + Assignment1.COUNT + " for the first assignment)",
            "--assignment", "1 or 2",
            "--threads", "1 to " + ThreadsOption.MOST);

    private UsageWords() {
    }

    /** The message of {@code e} for the user; {@code command} is the command's full name, "simpview check". */
    static String of(ParameterException e, String command) {
        String message = e.getMessage();
        if (e instanceof MaxValuesExceededException && message.startsWith("Error: expected only one match")) {
            // "(--page=N | --all | ...)={--page=3} and (--page=N | --all | ...)={--page=4}"; an optional group
            // is in brackets: "[--page=N | --all | ...]={--page=3} and ..."
            int firstMatch = Math.max(message.indexOf(")={"), message.indexOf("]={"));
            List<String> found = MATCHED.matcher(message).results().map(r -> r.group(1)).toList();
            if (firstMatch > 0 && !found.isEmpty()) {
                return "give only one of " + options(message.substring(0, firstMatch)) + ": found "
                        + String.join(" and ", found);
            }
        }
        if (e instanceof MutuallyExclusiveArgsException && message.startsWith("Error: ")) {
            // "--page=N, --all are mutually exclusive (specify only one)"
            return "give only one of " + options(message);
        }
        if (e instanceof UnmatchedArgumentException) {
            Matcher m = UNMATCHED.matcher(message);
            if (m.matches()) {
                return m.group(1) + (m.group(1).contains(", ") ? ": more arguments than " : ": one argument more than ")
                        + command + " takes";
            }
        }
        for (String[] type : TYPES) {
            if (message.endsWith(type[0])) {
                String before = message.substring(0, message.length() - type[0].length());
                String range = outOfRange(before, type[0]);
                return before + (range.isEmpty() ? type[1] : range);
            }
        }
        return message;
    }

    /**
     * What a whole number too large (or too small) for its type is told: for a long (a seed), "' is out of range:
     * give a whole number from -9223372036854775808 to 9223372036854775807", every long being a seed. It is a
     * whole number, and "not a whole number" would send the user looking for a typo. "" when {@code before}
     * ("... '--seed': '12x") does not end in one.
     */
    private static String outOfRange(String before, String type) {
        String value = before.substring(before.lastIndexOf('\'') + 1);
        if (!WHOLE.matcher(value).matches()) {
            return "";
        }
        if (type.endsWith("a long")) {
            return "' is out of range: give a whole number from " + Long.MIN_VALUE + " to " + Long.MAX_VALUE;
        }
        if (type.endsWith("an int")) {
            // an int option (a page, a count of threads) takes a range of its own: said here as the command says it
            // of a value outside it, so --page=2147483648 is told what --page=2147483647 is
            Matcher option = OPTION_NAMED.matcher(before);
            String range = option.find() ? RANGES.get(option.group(1)) : null;
            if (range != null) {
                return "' is out of range: " + option.group(1) + " must be " + range;
            }
            return "' is out of range: far " + (value.startsWith("-") ? "smaller" : "larger") + " than any value it "
                    + "takes";
        }
        return "";
    }

    /** The options named in {@code text}, each once: "--page, --all or --scene". */
    private static String options(String text) {
        Set<String> options = new LinkedHashSet<>();
        Matcher names = OPTION.matcher(text);
        while (names.find()) {
            options.add(names.group());
        }
        return joined(List.copyOf(options), "or");
    }

    /** The first three of some names, then how many more: "alice, bob, carol and 9 more"; "alice, bob". */
    static String firstThree(List<String> names) {
        return String.join(", ", names.subList(0, Math.min(3, names.size())))
                + (names.size() > 3 ? " and " + (names.size() - 3) + " more" : "");
    }

    /** Words in a sentence: "a", "a or b", "a, b or c" (with {@code conjunction} "or"). */
    static String joined(List<String> words, String conjunction) {
        return words.size() == 1 ? words.get(0) : String.join(", ", words.subList(0, words.size() - 1)) + " "
                + conjunction + " " + words.get(words.size() - 1);
    }
}
