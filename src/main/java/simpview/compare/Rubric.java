package simpview.compare;

import com.google.gson.stream.JsonReader;
import com.google.gson.stream.JsonToken;
import java.io.IOException;
import java.io.Reader;
import java.io.StringReader;
import java.math.BigDecimal;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import simpview.scene.FileProblem;

/**
 * A grading rubric: how each page or scene is judged and what it is worth.
 * Read from a JSON file (with Gson's streaming reader, so every error names
 * its line and column):
 *
 * <pre>
 * { "defaults": { "tolerance": 8, "deviation": 1, "min_share": 99, "points": 1 },
 *   "pages": [ { "match": "1-3", "points": 2 },
 *              { "match": "6-8", "min_share": 92, "max_failing_pixels": 40000 },
 *              { "match": "pageC", "metric": "blur", "alternates": "alternates/pageC" } ] }
 * </pre>
 *
 * The first rule whose {@code match} fits a page or scene is its rule; a
 * field it leaves out comes from {@code defaults}, and one left out there from
 * the command line (today's defaults). Without a rubric every page has the
 * command line's rule. What JSON readers pass over is an error here too: a key
 * given twice in one object, and a zero_share above its min_share.
 */
public final class Rubric {

    private static final Set<String> VISIBILITIES = Set.of("hidden", "after_due_date", "after_published", "visible");

    private final RubricRule defaults;
    private final List<RubricRule> rules;
    /** Where each rule is in the file ("line 4, column 5 ($.pages[1])"), for what is said about it later. */
    private final List<String> places;
    /** The file, as its messages name it. */
    private final Path file;

    private Rubric(RubricRule defaults, List<RubricRule> rules, List<String> places, Path file) {
        this.defaults = defaults;
        this.rules = List.copyOf(rules);
        this.places = List.copyOf(places);
        this.file = file;
    }

    /** No file: every page judged by {@code defaults}. */
    public static Rubric of(RubricRule defaults) {
        return new Rubric(defaults, List.of(), List.of(), null);
    }

    /** The rule for a page or scene: key "page6" and page 6, or key "pageC" (the scene's name without .simp) and 0. */
    public RubricRule ruleFor(String key, int page) {
        for (RubricRule rule : rules) {
            if (rule.matches(key, page)) {
                return rule;
            }
        }
        return defaults;
    }

    public List<RubricRule> rules() {
        return rules;
    }

    public RubricRule defaults() {
        return defaults;
    }

    /**
     * A warning for each rule that fits none of {@code subjects}, the pages and scenes a run can compare (each
     * key with its page number, 0 for a scene, as {@link #ruleFor} takes them): a "9" under --pages 1-8, a
     * "pageZ" where no scene is so named. Not an error: one rubric may serve several assignments.
     */
    public List<String> unusedRules(Map<String, Integer> subjects) {
        List<String> unused = new ArrayList<>();
        for (int i = 0; i < rules.size(); i++) {
            RubricRule rule = rules.get(i);
            if (subjects.entrySet().stream().noneMatch(s -> rule.matches(s.getKey(), s.getValue()))) {
                unused.add("rubric " + file + ": " + places.get(i) + ": the rule \"match\": \"" + rule.match()
                        + "\" fits no page or scene of this run, so it is not used");
            }
        }
        return unused;
    }

    /** Reads a rubric file over {@code base} (the command line's rule). Alternates are relative to the file's folder. */
    public static Rubric read(Path file, RubricRule base) throws CompareException {
        String text;
        try {
            text = Files.readString(file, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new CompareException("rubric " + file + ": cannot be read: " + FileProblem.of(file, e));
        }
        try (Reader reader = new StringReader(text)) {
            JsonReader json = new JsonReader(reader);
            return new Parser(file, text, json).rubric(base);
        } catch (IOException | IllegalStateException | NumberFormatException e) {
            String comma = trailingComma(e.getMessage(), text);
            throw new CompareException("rubric " + file + ": " + (comma != null ? comma : notJson(e.getMessage(), text)));
        }
    }

    /**
     * A ',' after the last entry of an object or list ({@code "points": 1, }}), which JSON does not allow and Gson
     * tells as "Expected name" (or as JSON it reads only leniently) just past the '}' or ']': said in words at the
     * comma's own line and column, what was expected after it, and what to do; null when Gson's account is of
     * something else.
     */
    static String trailingComma(String gson, String text) {
        Matcher m = GSON_PLACE.matcher(gson);
        if (!m.find()) {
            return null;
        }
        int line = Integer.parseInt(m.group(2));
        int column = Integer.parseInt(m.group(3));
        int at = lineStart(text, line);
        int closer = at < 0 ? -1 : at + column - 2; // Gson has read the '}' or ']' it met instead of a key or value
        if (closer < 1 || closer >= text.length() || "}]".indexOf(text.charAt(closer)) < 0) {
            return null;
        }
        int comma = closer - 1;
        while (comma >= 0 && Character.isWhitespace(text.charAt(comma))) {
            comma--;
        }
        if (comma < 0 || text.charAt(comma) != ',') {
            return null;
        }
        int commaLine = 1 + (int) text.substring(0, comma).chars().filter(c -> c == '\n').count();
        int commaColumn = comma - (text.lastIndexOf('\n', comma - 1) + 1) + 1;
        boolean object = text.charAt(closer) == '}';
        return "line " + commaLine + ", column " + commaColumn + " (" + m.group(4) + "): a ',' after the last "
                + (object ? "entry of an object, before its '}': expected another \"key\": value after it"
                        : "item of a list, before its ']': expected another item after it")
                + "; JSON allows no ',' there, so remove it";
    }

    private static final Pattern GSON_PLACE =
            Pattern.compile("^(.*?) at line (\\d+) column (\\d+) path (\\S+)$");

    /**
     * Gson's account of JSON it could not read ("End of input at line 2
     * column 1 path $.pages[0]", "Use JsonReader.setLenient(true) to accept
     * malformed JSON at ..."), in words, the place first as {@link Parser}
     * gives it.
     */
    static String notJson(String gson, String text) {
        Matcher m = GSON_PLACE.matcher(gson);
        if (!m.find()) {
            return "not valid JSON: " + gson;
        }
        String what = m.group(1);
        int line = Integer.parseInt(m.group(2));
        int column = Integer.parseInt(m.group(3));
        int at = Math.max(lineStart(text, line), 0) + column - 1;
        // Gson's place is past the character it stopped at, except at the end, where a value was expected, and
        // at a word without quotes (which starts there, after a blank or a mark).
        boolean atIt = what.equals("End of input") || what.equals("Expected value")
                || what.startsWith("Use JsonReader.setLenient") && at < text.length() && isLiteral(text.charAt(at))
                && (at == 0 || !isLiteral(text.charAt(at - 1)) && text.charAt(at - 1) != '\'');
        if (!atIt && column > 1) {
            column--;
        }
        String words;
        if (what.equals("End of input")) {
            words = "the file ends before its JSON does (a ']' or '}' missing?)";
        } else if (what.equals("Unterminated object")) {
            words = "an object's '}', or a ',' between two of its entries, is missing";
        } else if (what.equals("Unterminated array")) {
            words = "a list's ']', or a ',' between two of its items, is missing";
        } else if (what.equals("Expected ':'")) {
            words = "a ':' between a key and its value is missing";
        } else if (what.equals("Expected name")) {
            words = "expected a key in double quotes (\"points\")";
        } else if (what.startsWith("Use JsonReader.setLenient")) {
            words = "not valid JSON here (a word without its quotes, a missing comma, or a comment?)";
        } else {
            words = "not valid JSON: " + what;
        }
        return "line " + line + ", column " + column + " (" + m.group(4) + "): " + words;
    }

    /** A character of a literal: a number, true, false, null, or a word without quotes. */
    private static boolean isLiteral(char c) {
        return Character.isLetterOrDigit(c) || c == '-' || c == '+' || c == '.';
    }

    /** Where {@code text}'s line {@code line} (from 1) starts; -1 past its last. */
    private static int lineStart(String text, int line) {
        int at = 0;
        for (int l = 1; l < line && at >= 0; l++) {
            at = text.indexOf('\n', at);
            at = at < 0 ? -1 : at + 1;
        }
        return at;
    }

    /** The streaming parse, one object at a time, each error with its place. */
    private static final class Parser {

        /**
         * A rule object as read: the rule, where it starts, and where it gave its min_share and its zero_share
         * (null: it left that out), so a zero_share above a min_share can say where each came from.
         */
        private record Read(RubricRule rule, String at, String minShareAt, String zeroShareAt) {
        }

        private final Path file;
        private final Path folder;
        private final String text;
        private final JsonReader json;
        /** Where the token last looked at ({@link #peek}) starts: its line and its column, each from 1. */
        private int tokenLine = 1;
        private int tokenColumn = 1;

        Parser(Path file, String text, JsonReader json) {
            this.file = file;
            this.folder = file.toAbsolutePath().getParent();
            this.text = text;
            this.json = json;
        }

        /**
         * The next token, its start kept for what is said about it. Gson's own place is past what its peek has
         * read: the opening '{', '[' or '"' of a bracket, a string or a key; the whole of a whole number, true,
         * false or null; nothing of a number with a fraction or an exponent. So the start is one character back
         * for the first kind, and at the first of the characters of a literal just before Gson's place for the
         * others (none, for a number Gson has not read: a literal follows a ':', ',', '[' or a blank). Neither
         * crosses a line's end.
         */
        private JsonToken peek() throws IOException {
            JsonToken token = json.peek();
            Matcher m = GSON_PLACE.matcher(json.toString().trim());
            if (!m.find()) {
                return token;
            }
            int line = Integer.parseInt(m.group(2));
            int column = Integer.parseInt(m.group(3));
            int back = switch (token) {
                case NUMBER, BOOLEAN, NULL -> {
                    int at = Math.max(lineStart(text, line), 0) + column - 1;
                    int start = at;
                    while (start > 0 && start <= text.length() && isLiteral(text.charAt(start - 1))) {
                        start--;
                    }
                    yield at - start;
                }
                case END_DOCUMENT -> 0;
                default -> 1;
            };
            tokenLine = line;
            tokenColumn = Math.max(1, column - back);
            return token;
        }

        /** A key, its start kept as for a value. */
        private String name() throws IOException {
            peek();
            return json.nextName();
        }


        Rubric rubric(RubricRule base) throws IOException, CompareException {
            expect(JsonToken.BEGIN_OBJECT, "an object with \"defaults\" and \"pages\"");
            json.beginObject();
            Read defaults = new Read(base, null, null, null);
            List<Read> rules = new ArrayList<>();
            Map<String, String> seen = new HashMap<>();
            while (json.hasNext()) {
                String name = name();
                once(name, seen);
                switch (name) {
                    case "defaults" -> defaults = defaults(base);
                    case "pages" -> {
                        expect(JsonToken.BEGIN_ARRAY, "a list of page rules");
                        json.beginArray();
                        while (json.hasNext()) {
                            rules.add(rule(null, true));
                        }
                        json.endArray();
                    }
                    default -> throw error("unknown key \"" + name + "\": expected \"defaults\" or \"pages\"");
                }
            }
            json.endObject();
            if (peek() != JsonToken.END_DOCUMENT) {
                throw error("text after the rubric's closing }");
            }
            if (seen.isEmpty()) {
                throw new CompareException("rubric " + file + ": neither \"defaults\" nor \"pages\" given");
            }
            // Page rules left open fall back on the defaults as the file gives them.
            List<RubricRule> filled = new ArrayList<>();
            List<String> places = new ArrayList<>();
            for (Read rule : rules) {
                filled.add(fill(rule, defaults));
                places.add(rule.at());
            }
            return new Rubric(defaults.rule(), filled, places, file);
        }

        /** The "defaults" object over the command line's rule, its zero_share at most its min_share. */
        private Read defaults(RubricRule base) throws IOException, CompareException {
            Read read = rule(base, false);
            if (read.zeroShareAt() != null) {
                inOrder(read.at(), "\"defaults\"", read.rule().zeroShare(), read.zeroShareAt(), read.rule().minShare(),
                        read.minShareAt() != null ? read.minShareAt() : "from --min: the rubric sets none");
            }
            return read;
        }

        /** A rule object; over {@code base}, or with its missing fields left null-ish (NaN, MIN_VALUE) to fill later. */
        private Read rule(RubricRule base, boolean needsMatch) throws IOException, CompareException {
            expect(JsonToken.BEGIN_OBJECT, needsMatch ? "a page rule: an object with \"match\"" : "an object of default fields");
            String where = place();
            json.beginObject();
            String match = base == null ? null : base.match();
            int tolerance = base == null ? Integer.MIN_VALUE : base.tolerance();
            int deviation = base == null ? Integer.MIN_VALUE : base.deviation();
            double minShare = base == null ? Double.NaN : base.minShare();
            int maxFailing = base == null ? Integer.MIN_VALUE : base.maxFailing();
            double points = base == null ? Double.NaN : base.points();
            double zeroShare = base == null ? Double.NaN : base.zeroShare();
            Comparison.Metric metric = base == null ? null : base.metric();
            Path alternates = base == null ? null : base.alternates();
            String visibility = base == null ? null : base.visibility();
            double flipThreshold = base == null ? Double.NaN : base.flipThreshold();
            String minShareAt = null;
            String zeroShareAt = null;
            Map<String, String> seen = new HashMap<>();
            while (json.hasNext()) {
                String name = name();
                once(name, seen);
                switch (name) {
                    case "match" -> {
                        if (!needsMatch) {
                            throw error("\"match\" belongs in a page rule, not in the defaults");
                        }
                        match = string("a page range like \"6\" or \"1-3\", or a name pattern like \"page*\"");
                        if (match.isBlank()) {
                            throw error("\"match\" is empty");
                        }
                        String backwards = RubricRule.backwardsRange(match);
                        if (backwards != null) {
                            String[] ends = backwards.split("-");
                            throw error("\"match\": \"" + match + "\": the range " + backwards + " runs backwards, so "
                                    + "it fits no page: write it " + ends[1].trim() + "-" + ends[0].trim());
                        }
                    }
                    case "tolerance" -> tolerance = (int) number(0, 255, true, "a whole number of 1/255 steps, 0 to 255");
                    case "deviation" -> deviation = (int) number(0, Comparison.MAX_DEVIATION, true,
                            "a position deviation of 0, 1 or 2 pixels");
                    case "min_share" -> {
                        minShareAt = lineAndColumn();
                        minShare = share();
                    }
                    case "max_failing_pixels" -> maxFailing = (int) number(0, Comparison.N * Comparison.N, true,
                            "a whole number of pixels, 0 to 422500");
                    case "points" -> points = number(0, 1e6, false, "points, 0 or more");
                    case "zero_share" -> {
                        zeroShareAt = lineAndColumn();
                        zeroShare = share();
                    }
                    case "metric" -> metric = switch (string("\"exact\", \"blur\" or \"flip\"")) {
                        case "exact" -> Comparison.Metric.EXACT;
                        case "blur" -> Comparison.Metric.BLUR;
                        case "flip" -> Comparison.Metric.FLIP;
                        default -> throw error("\"metric\" must be \"exact\", \"blur\" or \"flip\"");
                    };
                    case "alternates" -> alternates = folder(string("a folder of extra accepted pictures"));
                    case "flip_threshold" -> flipThreshold = number(0, 1, false, "a FLIP value, 0 to 1");
                    case "visibility" -> {
                        visibility = string("one of " + VISIBILITIES);
                        if (!VISIBILITIES.contains(visibility)) {
                            throw error("\"visibility\" must be hidden, after_due_date, after_published or visible");
                        }
                    }
                    default -> throw error("unknown key \"" + name + "\": expected match, tolerance, deviation, "
                            + "min_share, max_failing_pixels, points, zero_share, metric, flip_threshold, alternates or "
                            + "visibility");
                }
            }
            json.endObject();
            if (needsMatch && match == null) {
                throw new CompareException("rubric " + file + ": the page rule " + where + " has no \"match\"");
            }
            if (base != null && zeroShareAt == null) {
                // The command line has no zero_share: left out here too, it is 90 or this min_share if lower.
                zeroShare = Math.min(RubricRule.ZERO_SHARE, minShare);
            }
            return new Read(new RubricRule(match, tolerance, deviation, minShare, maxFailing, points, zeroShare, metric,
                    alternates, visibility, flipThreshold), where, minShareAt, zeroShareAt);
        }

        /**
         * A page rule with what it leaves out from the defaults. Its zero_share: its own, else the defaults' if
         * they give one, else 90 or its min_share if lower; one it gives or inherits must not be above its
         * min_share (its own, the defaults' or --min).
         */
        private RubricRule fill(Read read, Read defaults) throws CompareException {
            RubricRule r = read.rule();
            RubricRule d = defaults.rule();
            double minShare = Double.isNaN(r.minShare()) ? d.minShare() : r.minShare();
            String zeroFrom = read.zeroShareAt() != null ? "its own, " + read.zeroShareAt()
                    : defaults.zeroShareAt() != null ? "from \"defaults\", " + defaults.zeroShareAt() : null;
            double zeroShare = !Double.isNaN(r.zeroShare()) ? r.zeroShare()
                    : zeroFrom != null ? d.zeroShare() : Math.min(RubricRule.ZERO_SHARE, minShare);
            if (zeroFrom != null) {
                String minFrom = read.minShareAt() != null ? "its own, " + read.minShareAt()
                        : defaults.minShareAt() != null ? "from \"defaults\", " + defaults.minShareAt()
                        : "from --min: the rubric sets none";
                inOrder(read.at(), "the rule for \"" + r.match() + "\"", zeroShare, zeroFrom, minShare, minFrom);
            }
            return new RubricRule(r.match(),
                    r.tolerance() == Integer.MIN_VALUE ? d.tolerance() : r.tolerance(),
                    r.deviation() == Integer.MIN_VALUE ? d.deviation() : r.deviation(),
                    minShare,
                    r.maxFailing() == Integer.MIN_VALUE ? d.maxFailing() : r.maxFailing(),
                    Double.isNaN(r.points()) ? d.points() : r.points(),
                    zeroShare,
                    r.metric() == null ? d.metric() : r.metric(),
                    r.alternates() == null ? d.alternates() : r.alternates(),
                    r.visibility() == null ? d.visibility() : r.visibility(),
                    Double.isNaN(r.flipThreshold()) ? d.flipThreshold() : r.flipThreshold());
        }

        /**
         * A failing page scores in part between zero_share and min_share, so zero_share above min_share is a
         * mistake (the file's, or between the file and --min), said with where each value came from.
         */
        private void inOrder(String at, String what, double zeroShare, String zeroFrom, double minShare, String minFrom)
                throws CompareException {
            if (zeroShare > minShare) {
                throw new CompareException("rubric " + file + ": " + at + ": " + what + " has zero_share "
                        + share(zeroShare) + " (" + zeroFrom + ") above its min_share " + share(minShare) + " ("
                        + minFrom + "); zero_share must be at most min_share");
            }
        }

        /** 96 or 97.5, as the file would give it. */
        private static String share(double percent) {
            return BigDecimal.valueOf(percent).stripTrailingZeros().toPlainString();
        }

        /**
         * A key given twice in one object: JSON readers keep the last without a word, so "points": 2, "points": 5
         * would be 5 points. Said at the second, with the first's place.
         */
        private void once(String name, Map<String, String> seen) throws CompareException {
            String first = seen.putIfAbsent(name, lineAndColumn());
            if (first != null) {
                throw error("\"" + name + "\" is given twice in this object (first at " + first + "); give it once");
            }
        }

        private Path folder(String name) throws CompareException {
            Path path = folder == null ? Path.of(name) : folder.resolve(name);
            if (!Files.isDirectory(path)) {
                throw error("\"alternates\": no such folder: " + path);
            }
            return path;
        }

        private String string(String what) throws IOException, CompareException {
            expect(JsonToken.STRING, what);
            return json.nextString();
        }

        private double number(double min, double max, boolean whole, String what) throws IOException, CompareException {
            expect(JsonToken.NUMBER, what);
            String where = place();
            double value = json.nextDouble();
            if (value < min || value > max || whole && value != Math.rint(value)) {
                throw new CompareException("rubric " + file + ": " + where + ": " + value + " is not " + what);
            }
            return value;
        }

        /** A share in percent, 0 to 100; not one between 0 and 1: a fraction ({@link Percent#fractionInstead}). */
        private double share() throws IOException, CompareException {
            String what = "a share in percent, 0 to 100";
            expect(JsonToken.NUMBER, what);
            String where = place();
            double value = number(0, 100, false, what);
            String fraction = Percent.fractionInstead(value, String.valueOf(value));
            if (fraction != null) {
                throw new CompareException("rubric " + file + ": " + where + ": " + fraction);
            }
            return value;
        }

        private void expect(JsonToken token, String what) throws IOException, CompareException {
            JsonToken found = peek();
            if (found != token) {
                throw error("expected " + what + ", found " + inWords(found));
            }
        }

        private static String inWords(JsonToken token) {
            return switch (token) {
                case BEGIN_ARRAY -> "a list ('[')";
                case END_ARRAY -> "the end of a list (']')";
                case BEGIN_OBJECT -> "an object ('{')";
                case END_OBJECT -> "the end of an object ('}')";
                case NAME -> "a key";
                case STRING -> "a string";
                case NUMBER -> "a number";
                case BOOLEAN -> "true or false";
                case NULL -> "null";
                case END_DOCUMENT -> "the end of the file";
            };
        }

        private CompareException error(String message) {
            return new CompareException("rubric " + file + ": " + place() + ": " + message);
        }

        /** E.g. "line 3, column 14": where the token last looked at starts. */
        private String lineAndColumn() {
            return "line " + tokenLine + ", column " + tokenColumn;
        }

        /**
         * E.g. "line 3, column 14 ($.pages[0].tolerance)": where the token last looked at starts, and the reader's
         * path to it (after a key is read, the key's own).
         */
        private String place() {
            Matcher m = GSON_PLACE.matcher(json.toString().trim());
            return lineAndColumn() + (m.find() ? " (" + m.group(4) + ")" : "");
        }
    }
}
