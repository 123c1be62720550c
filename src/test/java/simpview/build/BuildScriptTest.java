package simpview.build;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Properties;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;

/**
 * build.gradle uses nothing that a supported Gradle (Debian's 4.4.1, or 7.3
 * to 9.x on JDK 17) lacks, so a later change cannot bring back a construct
 * the upgrade guides removed. The same check run on the build file of
 * commit e9cbb85, which failed on every Gradle from 7.0, finds its problems.
 */
class BuildScriptTest {

    private static final String BUILD_DIR = "Project.buildDir (deprecated from 8.3: every build warns)";

    @Test
    void theBuildFileUsesOnlyWhatEverySupportedGradleHas() throws IOException {
        Path file = Path.of(System.getProperty("simpview.projectDir", ".")).resolve("build.gradle");
        List<BuildScriptLint.Finding> findings = BuildScriptLint.check(Files.readString(file));
        assertTrue(findings.isEmpty(), () -> findings.stream().map(Object::toString)
                .collect(Collectors.joining("\n", "constructs a supported Gradle lacks:\n", "")));
    }

    @Test
    void theOldBuildFileIsCaughtOnEachRemovedConstruct() throws IOException {
        List<BuildScriptLint.Finding> findings = BuildScriptLint.check(resource("build-e9cbb85.gradle"));
        Set<String> found = findings.stream().map(f -> f.line() + " " + f.construct())
                .collect(Collectors.toCollection(TreeSet::new));
        Set<String> expected = new TreeSet<>(List.of(
                "13 mainClassName",
                "16 a convention property set at the top of the script",
                "54 a source set's <name>Compile or <name>Runtime configuration",
                "54 the compile and runtime configurations",
                "55 a source set's <name>Compile or <name>Runtime configuration",
                "55 the compile and runtime configurations",
                "59 the compile and runtime configurations",
                "61 a source set's <name>Compile or <name>Runtime configuration",
                "62 a source set's <name>Compile or <name>Runtime configuration",
                "63 a source set's <name>Compile or <name>Runtime configuration",
                "65 a source set's <name>Compile or <name>Runtime configuration",
                "67 a source set's <name>Compile or <name>Runtime configuration",
                "71 " + BUILD_DIR,
                // line 92 sets the console launcher's main only where Gradle is below 4.6: allowed
                "118 JavaExec's main",
                "129 JavaExec's main",
                "132 " + BUILD_DIR,
                "133 " + BUILD_DIR,
                "144 Project.exec and Project.javaexec",
                "146 JavaExec's main",
                "147 " + BUILD_DIR,
                "152 a convention property set at the top of the script"));
        assertEquals(expected, found, findings.stream().map(Object::toString).collect(Collectors.joining("\n")));
    }

    @Test
    void aGuardedBranchIsJudgedForItsOwnGradles() {
        String script = """
                def gradleBelow = { String v -> GradleVersion.current() < GradleVersion.version(v) }
                if (gradleBelow('6.4')) {
                    mainClassName = 'a.Main'
                } else {
                    application { mainClass.set('a.Main') }
                }
                """;
        assertEquals(List.of(), BuildScriptLint.check(script));
    }

    @Test
    void theWrongSideOfAGuardIsCaught() {
        String script = """
                if (gradleBelow('6.4')) {
                    application { mainClass.set('a.Main') }
                } else {
                    mainClassName = 'a.Main'
                }
                if (!gradleBelow('9.1')) {
                    run { main = 'a.Main' }
                }
                """;
        List<String> found = BuildScriptLint.check(script).stream().map(f -> f.line() + " " + f.construct()).toList();
        assertEquals(List.of("2 JavaApplication/JavaExec mainClass", "2 the application and java extension blocks",
                "4 mainClassName", "7 JavaExec's main"), found);
    }

    @Test
    void unguardedNewConstructsAreCaughtBecauseGradle44LacksThem() {
        String script = """
                tasks.register('fat', Jar) { archiveFileName.set('x.jar') }
                dependencies { annotationProcessor 'a:b:1' }
                test { useJUnitPlatform() }
                """;
        List<String> found = BuildScriptLint.check(script).stream().map(f -> f.line() + " " + f.construct()).toList();
        assertEquals(List.of("1 archiveFileName and the other archive properties",
                "1 lazy task configuration (tasks.register, tasks.named, configureEach)",
                "2 annotation processor configurations", "3 useJUnitPlatform()"), found);
    }

    @Test
    void aDoubleQuotedStringsInterpolationsAreCode() {
        String script = """
                args "$buildDir/big"
                args "${buildDir}/big", "x"
                args '$buildDir/big', "buildDir", "\\$buildDir", "$version-${project.name}"
                """;
        List<String> found = BuildScriptLint.check(script).stream().map(f -> f.line() + " " + f.construct()).toList();
        assertEquals(List.of("1 " + BUILD_DIR, "2 " + BUILD_DIR), found);
    }

    @Test
    void commentsAndStringsAreNotCode() {
        String script = """
                // compile 'old:style:1' was removed in Gradle 7
                /* mainClassName = 'x' */
                description = 'the compile and testRuntime configurations are gone; main = x'
                """;
        assertEquals(List.of(), BuildScriptLint.check(script));
    }

    @Test
    void theWrapperIsPinnedToAGradle8ReleaseAndTheReadmeSaysWhich() throws IOException {
        Path project = Path.of(System.getProperty("simpview.projectDir", "."));
        Properties wrapper = new Properties();
        try (InputStream in = Files.newInputStream(project.resolve("gradle/wrapper/gradle-wrapper.properties"))) {
            wrapper.load(in);
        }
        Matcher m = Pattern.compile("https://services\\.gradle\\.org/distributions/gradle-(8\\.[0-9.]+)-bin\\.zip")
                .matcher(wrapper.getProperty("distributionUrl", ""));
        assertTrue(m.matches(), "distributionUrl: " + wrapper.getProperty("distributionUrl"));
        assertTrue(Files.readString(project.resolve("README.md")).contains("(" + m.group(1) + ")"),
                "the README names the wrapper's Gradle " + m.group(1));
        assertTrue(Files.isExecutable(project.resolve("gradlew")), "gradlew is executable");
        assertTrue(Files.size(project.resolve("gradle/wrapper/gradle-wrapper.jar")) > 10_000);
    }

    private static String resource(String name) throws IOException {
        try (InputStream in = BuildScriptTest.class.getResourceAsStream(name)) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }
}
