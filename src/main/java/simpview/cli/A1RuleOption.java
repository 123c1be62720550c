package simpview.cli;

import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;
import simpview.pages.A1Rule;
import simpview.pages.PageContext;

/**
 * {@code --a1-rule spec|course}, for every command that draws the first
 * assignment's pages: SPEC Part 3's Bresenham and fill rule (the default), or
 * the rule the course's own pictures show ({@link A1Rule}).
 */
final class A1RuleOption {

    @Spec(Spec.Target.MIXEE)
    private CommandSpec spec;

    @Option(names = "--a1-rule", paramLabel = "R",
            description = "the first assignment's Bresenham panels and fills: spec (SPEC Part 3's integer "
                    + "Bresenham on rounded ends, pixel centres; default) or course (as the course's pictures "
                    + "show: Bresenham on the ends' given minor coordinates, rows sampled at integer y)")
    private String rule;

    /** Whether the option was given. */
    boolean given() {
        return rule != null;
    }

    /** An unknown word is a usage error, now: before anything is drawn or read. */
    void check() {
        rule();
    }

    /** The rule asked for, SPEC's by default; an unknown word is a usage error. */
    A1Rule rule() {
        if (rule == null) {
            return A1Rule.SPEC;
        }
        A1Rule chosen = A1Rule.byKey(rule);
        if (chosen == null) {
            throw new ParameterException(spec.commandLine(), "--a1-rule must be spec or course, not " + rule);
        }
        return chosen;
    }

    /** {@code context} with the rule asked for. */
    PageContext applyTo(PageContext context) {
        return context.withA1Rule(rule());
    }
}
