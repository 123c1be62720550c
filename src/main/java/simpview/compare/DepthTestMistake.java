package simpview.compare;

/**
 * A picture of the z-buffer page (page 3) that fails as SPEC draws it but
 * passes as that page drawn with a mistake of the depth test: without one
 * (each triangle drawn over those before it, in drawing order) or with it
 * turned round (the farthest triangle in front). Its triangles are all in
 * place and of the right greys; which one covers which is wrong, and the
 * shares and patches alone say only that a large part is another grey.
 * The rule is {@link OtherPage}'s: the picture must pass, by the rule it
 * failed by, against exactly one of the two.
 *
 * @param page the page as the report names it: "page 3 (seed 361)"
 * @param withoutTest whether it passes as the page drawn without a depth test; else with the test turned round
 * @param shareThere its verdict share against the page so drawn
 */
public record DepthTestMistake(String page, boolean withoutTest, double shareThere) implements PanelHint {

    /**
     * The mistake theirs (one n x n panel) passes as by {@code rule}: against {@code withoutTest}, simpview's page
     * drawn without a depth test, or {@code turnedRound}, drawn with it turned round; null when it passes against
     * neither, or both.
     */
    public static DepthTestMistake find(String page, int[] theirs, int n, RubricRule rule, int[] withoutTest,
            int[] turnedRound) {
        RubricRule[] rules = {rule};
        double none = OtherPage.passes(new int[][] {withoutTest}, new int[][] {theirs}, n, rules);
        double turned = OtherPage.passes(new int[][] {turnedRound}, new int[][] {theirs}, n, rules);
        if (Double.isNaN(none) == Double.isNaN(turned)) {
            return null;
        }
        return Double.isNaN(turned) ? new DepthTestMistake(page, true, none) : new DepthTestMistake(page, false, turned);
    }

    @Override
    public String brief() {
        return withoutTest ? "like " + page + " drawn without a depth test" : "like " + page + " drawn with its depth "
                + "test turned round (the farthest in front)";
    }

    @Override
    public String hint(int n) {
        String drawn = withoutTest
                ? "without a depth test: each triangle covers those drawn before it, whatever its depth"
                : "with its depth test turned round: where triangles overlap, the farthest is in front";
        return "your picture passes as simpview's " + page + " drawn " + drawn + " (" + Percent.of(shareThere)
                + " by the same rule). SPEC's z-buffer starts every pixel at the far end and writes a fragment only "
                + "where it is nearer than the z kept there, then keeps its z; z runs from -1 (near) to -199 (far), so "
                + "nearer is the larger z: check that your fill tests and stores z at every pixel, and which way it "
                + "compares.";
    }

    @Override
    public boolean wholePage() {
        return true;
    }
}
