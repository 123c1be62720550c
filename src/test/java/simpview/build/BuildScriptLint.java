package simpview.build;

import java.util.ArrayList;
import java.util.List;
import java.util.function.UnaryOperator;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Reads a Groovy build script and finds every construct that some Gradle it
 * may run on does not have: removed by a newer Gradle (per the upgrade
 * guides 6 to 7, 7 to 8 and 8 to 9, and the 4.x/5.x ones before them) or
 * not yet in Debian's 4.4.1. Code under {@code if (gradleBelow('N')) {...}
 * else {...}} runs only below N, or only from N on, and is judged for that
 * range. Comments and the contents of strings are not code and are ignored.
 */
final class BuildScriptLint {

    /** The constructs, from docs/building.md, which says where each comes from. */
    static final List<GradleRule> RULES = List.of(
            GradleRule.removed("the compile and runtime configurations", "\\b(compile|runtime)\\b", "7.0",
                    "implementation, runtimeOnly"),
            GradleRule.removed("a source set's <name>Compile or <name>Runtime configuration",
                    "\\b[a-z][A-Za-z0-9]*(Compile|Runtime)\\b", "7.0",
                    "<name>Implementation, <name>RuntimeOnly (testImplementation, testRuntimeOnly, ...)"),
            GradleRule.removed("a single classes folder (classesDir, testClassesDir)",
                    "\\b(classesDir|testClassesDir)\\b", "5.0", "classesDirs, testClassesDirs"),
            GradleRule.removed("Task.leftShift (task x << { })", "<<\\s*\\{", "5.0", "doLast { }"),
            GradleRule.removed("the archive task's archiveName, baseName, appendix or classifier",
                    "\\b(archiveName|baseName|appendix|classifier)\\b", "8.0",
                    "archiveFileName, archiveBaseName, ... (Gradle 5.1+, so under gradleBelow('5.1') else)"),
            GradleRule.removed("a report's enabled flag", "\\b(html|xml|junitXml|csv)\\.enabled\\b", "8.0",
                    "required"),
            GradleRule.removed("mainClassName", "\\bmainClassName\\b", "9.0",
                    "application { mainClass.set(...) } (Gradle 6.4+)"),
            GradleRule.removed("JavaExec's main", "\\bmain\\s*=(?!=)|\\bmain\\s+(?=['\"])|\\bsetMain\\s*\\(", "9.0",
                    "mainClass.set(...) (Gradle 6.4+)"),
            GradleRule.removed("Project.exec and Project.javaexec",
                    "(?<![\\w.])(javaexec|exec)\\s*[({]|\\bproject\\.(javaexec|exec)\\b", "9.0",
                    "an Exec or JavaExec task"),
            GradleRule.removed("jcenter()", "\\bjcenter\\s*\\(", "9.0", "mavenCentral()"),
            GradleRule.removed("the Convention API (project.convention)", "\\bconvention\\b", "9.0",
                    "the extension (application { }, java { }, base { })"),
            GradleRule.removed("Project.buildDir (deprecated from 8.3: every build warns)", "\\bbuildDir\\b", "8.3",
                    "project.layout.buildDirectory (Gradle 4.3+)"),
            GradleRule.removed("CopySpec fileMode and dirMode", "\\b(fileMode|dirMode)\\b", "9.0",
                    "filePermissions, dirPermissions (Gradle 8.3+)"),
            GradleRule.convention("a convention property set at the top of the script",
                    "^\\s*(applicationDefaultJvmArgs|applicationDistribution|applicationName|executableDir"
                            + "|sourceCompatibility|targetCompatibility|archivesBaseName|distsDirName|libsDirName"
                            + "|testResultsDirName|testReportDirName)\\b",
                    "its extension's block, or a common form (startScripts.defaultJvmOpts, distributions { })"),
            GradleRule.added("JavaApplication/JavaExec mainClass", "\\bmainClass\\b", "6.4",
                    "under gradleBelow('6.4') else; mainClassName and main below"),
            GradleRule.added("annotation processor configurations", "\\b\\w*[aA]nnotationProcessor\\b", "4.6",
                    "under gradleBelow('4.6') else; the compile classpath below"),
            GradleRule.added("archiveFileName and the other archive properties",
                    "\\b(archiveFileName|archiveBaseName|archiveAppendix|archiveVersion|archiveExtension"
                            + "|archiveClassifier|destinationDirectory)\\b", "5.1",
                    "under gradleBelow('5.1') else"),
            GradleRule.added("lazy task configuration (tasks.register, tasks.named, configureEach)",
                    "\\btasks\\.(register|named)\\b|\\bconfigureEach\\b", "4.9", "task x(type: T) { }"),
            GradleRule.added("useJUnitPlatform()", "\\buseJUnitPlatform\\b", "4.6",
                    "under gradleBelow('4.6') else; the build's own launcher below"),
            GradleRule.added("Java toolchains", "\\btoolchain\\b", "6.7", "--release 17"),
            GradleRule.added("filePermissions and dirPermissions", "\\b(filePermissions|dirPermissions)\\b", "8.3",
                    "under gradleBelow('8.3') else"),
            GradleRule.addedBlock("the application and java extension blocks", "(?<![\\w.])(application|java)\\s*\\{",
                    "4.10", "under gradleBelow('4.10') else, or a common form"));

    /** if (gradleBelow('N')), if (!gradleBelow('N')), or GradleVersion.current() compared with {@code <} or {@code >=}. */
    private static final Pattern GUARD = Pattern.compile("\\bif\\s*\\(\\s*(?:(!\\s*)?gradleBelow\\(\\s*'([0-9.]+)'\\s*\\)"
            + "|GradleVersion\\.current\\(\\)\\s*(<|>=)\\s*GradleVersion\\.version\\(\\s*'([0-9.]+)'\\s*\\))"
            + "\\s*\\)\\s*\\{");
    private static final Pattern ELSE = Pattern.compile("\\G\\s*else\\s*\\{");
    private static final Pattern BLOCK_NAME = Pattern.compile("([A-Za-z_]\\w*)\\s*(\\([^()]*\\))?\\s*$");

    /** A construct found where it cannot work. */
    record Finding(int line, String construct, GradleRange range, String instead) {
        @Override
        public String toString() {
            return "build.gradle:" + line + ": " + construct + " is used where " + range
                    + " may run it; use " + instead;
        }
    }

    private record Region(int start, int end, UnaryOperator<GradleRange> narrow) {
    }

    private record Block(int start, int end, String name) {
    }

    private BuildScriptLint() {
    }

    static List<Finding> check(String script) {
        String code = GroovyText.withoutComments(script);
        String bare = GroovyText.withoutStrings(code);
        List<Region> regions = guardedRegions(code, bare);
        List<Block> blocks = blocks(bare);
        List<Finding> findings = new ArrayList<>();
        for (GradleRule rule : RULES) {
            Matcher m = rule.pattern().matcher(bare);
            while (m.find()) {
                int at = m.start() + leadingSpace(m.group());
                GradleRange range = rangeAt(at, regions);
                if (!rule.allowedIn(range) && !exempt(rule, at, blocks)) {
                    findings.add(new Finding(lineOf(script, at), rule.construct(), range, rule.instead()));
                }
            }
        }
        findings.sort((a, b) -> Integer.compare(a.line(), b.line()));
        return findings;
    }

    private static int leadingSpace(String match) {
        int n = 0;
        while (n < match.length() && Character.isWhitespace(match.charAt(n))) {
            n++;
        }
        return n;
    }

    private static List<Region> guardedRegions(String code, String bare) {
        List<Region> regions = new ArrayList<>();
        Matcher m = GUARD.matcher(code);
        while (m.find()) {
            boolean negated = m.group(1) != null || ">=".equals(m.group(3));
            GradleVersionNumber v = GradleVersionNumber.of(m.group(2) != null ? m.group(2) : m.group(4));
            UnaryOperator<GradleRange> below = r -> r.under(v);
            UnaryOperator<GradleRange> from = r -> r.from(v);
            int open = m.end() - 1;
            int close = GroovyText.matchingBrace(bare, open);
            regions.add(new Region(open, close, negated ? from : below));
            Matcher e = ELSE.matcher(bare);
            if (close + 1 < bare.length() && e.find(close + 1)) {
                int elseOpen = e.end() - 1;
                regions.add(new Region(elseOpen, GroovyText.matchingBrace(bare, elseOpen), negated ? below : from));
            }
        }
        return regions;
    }

    private static GradleRange rangeAt(int at, List<Region> regions) {
        GradleRange range = GradleRange.SUPPORTED;
        for (Region r : regions) {
            if (r.start() < at && at < r.end()) {
                range = r.narrow().apply(range);
            }
        }
        return range;
    }

    private static List<Block> blocks(String bare) {
        List<Block> blocks = new ArrayList<>();
        for (int i = 0; i < bare.length(); i++) {
            if (bare.charAt(i) == '{') {
                Matcher name = BLOCK_NAME.matcher(bare.substring(Math.max(0, i - 200), i));
                blocks.add(new Block(i, GroovyText.matchingBrace(bare, i), name.find() ? name.group(1) : ""));
            }
        }
        return blocks;
    }

    private static boolean exempt(GradleRule rule, int at, List<Block> blocks) {
        for (Block b : blocks) {
            if (b.start() < at && at < b.end()
                    && (rule.exemptInside().contains(b.name())
                    || rule.exemptInside().contains("*") && !List.of("", "if", "else").contains(b.name()))) {
                return true;
            }
        }
        return false;
    }

    private static int lineOf(String text, int offset) {
        int line = 1;
        for (int i = 0; i < offset; i++) {
            line += text.charAt(i) == '\n' ? 1 : 0;
        }
        return line;
    }
}
