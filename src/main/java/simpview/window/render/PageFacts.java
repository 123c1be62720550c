package simpview.window.render;

import java.nio.file.Path;
import java.util.List;

/**
 * What the instruments can read about a finished picture besides its image.
 *
 * @param depths the panel's z-buffer when the picture was done (row y at y * 650, panel y up), or null: not
 *     kept for a frame of a drag that turns the view, unless the depth view is on ({@link DrawSettings#keepsDepths})
 * @param depthStart what the z-buffer started at: the far plane, -200, or a lit scene's -infinity
 * @param owners which primitive drew each panel pixel, laid out like depths, or null when not recorded
 * @param primitives the primitives read, in drawing order (owners index into them)
 * @param files the scene files the picture read, for reloading on save; empty for pages without a file
 * @param drewSomething false when an error stopped the picture before anything of it was drawn
 * @param shownCentre for a lit scene, the camera-space centre of what its view showed (what the orbit
 *     turns about); null for the rest, which turn about the view volume's centre
 */
public record PageFacts(double[] depths, double depthStart, int[] owners, Primitives primitives, List<Path> files,
        boolean drewSomething, double[] shownCentre) {

    static final PageFacts NONE = new PageFacts(null, -200, null, Primitives.NONE, List.of(), true, null);
}
