package simpview.scene.simp;

import java.util.List;
import simpview.geometry.Matrix4;
import simpview.scene.SceneException;
import simpview.stage.GeometryStage;

/**
 * What a scene's primitives do under the rules it is drawn by: the
 * depth-cued rules of SPEC Part 1 ({@link DepthCuedRules}) or the lit rules
 * of Part 2 ({@link LitRules}, which also carries out the lit commands).
 * {@link SimpClient} holds exactly one, and every command that is the same
 * under both rules is its own.
 */
sealed interface RuleSet permits DepthCuedRules, LitRules {

    /** A line, its vertices in object space, transformed by {@code ctm}; rgb null when it has no colours. */
    void line(Matrix4 ctm, double[] xyz, double[] rgb) throws SceneException;

    /** A triangle, likewise; {@code wire} for its outline. */
    void polygon(Matrix4 ctm, double[] xyz, double[] rgb, boolean wire) throws SceneException;

    /** The stage these rules send their primitives through: what it counts is what the scene warns of. */
    GeometryStage geometry();

    /** Primitives skipped because they lie wholly outside one plane of the view volume. */
    default long culledCount() {
        return geometry().culledCount();
    }

    /** The planes every culled primitive lies wholly outside of, bits 1 &lt;&lt; Camera.HITHER ...; 0 when none. */
    default int culledOutside() {
        return geometry().culledOutside();
    }

    /** Primitives not culled that the clipper cut away whole (Part 1: that lie so, none of their pixels shown). */
    default long clippedAwayCount() {
        return geometry().clippedAwayCount();
    }

    /** The sides of the view every one of those reaches beyond, bits 1 &lt;&lt; Camera.HITHER ...; 0 when none. */
    default int clippedAwayOutside() {
        return geometry().clippedAwayOutside();
    }

    /** Primitives taken, culled or not. */
    default long primitiveCount() {
        return geometry().primitiveCount();
    }

    /** Primitives not drawn because a vertex came out infinite or NaN in camera space. */
    default long nonFiniteCount() {
        return geometry().nonFiniteCount();
    }

    /**
     * Where the first of those stands, for the scene's warning: "ovf.simp:3
     * polygon", or for an obj face its model's line and the command that drew
     * it; null while there is none.
     */
    String firstNonFinite();

    /**
     * Why the first of those was not drawn, for the scene's warning: "a vertex
     * comes out infinite or NaN ..." and why it could (its numbers are finite).
     */
    String nonFiniteWhy();

    /**
     * Where the first colour outside 0 to 1 that these rules read themselves
     * (an .obj model's, "dummy.obj:12") was clamped, or null; asked after
     * each lit command, so that the scene's warning names the first in
     * reading order.
     */
    default String firstClampedColour() {
        return null;
    }

    /** The largest channel, as written, of the colour {@link #firstClampedColour} names, or NaN. */
    default double firstClampedChannel() {
        return Double.NaN;
    }

    /** What the models these rules read warned of, in reading order, each once ("de.obj:1:3: ..."). */
    default List<String> modelWarnings() {
        return List.of();
    }

    /**
     * Draws what is still recorded, when several threads draw (see
     * {@link DepthCuedRules#drawWith} and {@link LitRules#drawWith}); nothing otherwise. Called once the scene is read,
     * also after an error, so what was read before it is drawn.
     */
    void flush();
}
