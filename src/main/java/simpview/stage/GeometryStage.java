package simpview.stage;

import simpview.geometry.Matrix4;

/**
 * The first stage of the pipeline: takes a scene's lines and polygons in
 * object space, with the CTM at their command, through world and camera space
 * to the panel, and hands what is in view to the rasterizers. One stage per
 * rule set: {@link DepthCuedGeometry} (SPEC Part 1) and {@link LitGeometry}
 * (Part 2).
 */
public interface GeometryStage {

    /**
     * A line from vertex 0 to vertex 1.
     *
     * @param xyz object-space positions, x, y, z per vertex
     * @param rgb the vertices' own colours, r, g, b each in [0, 1], or null when they have none
     */
    void line(Matrix4 ctm, double[] xyz, double[] rgb);

    /** A triangle, filled or as its outline ({@code wire}); arguments as for {@link #line}. */
    void polygon(Matrix4 ctm, double[] xyz, double[] rgb, boolean wire);

    /** Primitives skipped because they lie wholly outside one plane of the view. */
    long culledCount();

    /**
     * The planes of the view (bits 1 &lt;&lt; Camera.HITHER ...) that every
     * culled primitive so far lies wholly outside of: what a scene that drew
     * nothing can be told. 0 while none was culled, or when no plane is
     * outside them all.
     */
    int culledOutside();

    /**
     * Primitives that were not culled, but that the clipper cut away whole
     * (a polygon around a corner of the view, outside it but not wholly
     * outside one plane). Part 1 clips nothing: there, those that lie so,
     * whose pixels the scissor drops every one of, are counted instead.
     */
    default long clippedAwayCount() {
        return 0;
    }

    /**
     * The sides of the view (bits 1 &lt;&lt; Camera.HITHER ...) that every
     * primitive {@link #clippedAwayCount} counts reaches beyond: the corner
     * of the view they lie round, for a scene that drew nothing. 0 while
     * there is none, or when they lie round different corners.
     */
    default int clippedAwayOutside() {
        return 0;
    }

    /** Primitives taken, culled or not: lines, triangles and .obj faces. */
    long primitiveCount();

    /**
     * Primitives not drawn because a vertex came out infinite or NaN in
     * camera space: finite numbers through a finite CTM can still overflow
     * (x = 1e308 under a scale of 10).
     */
    long nonFiniteCount();

    /**
     * Whether each of the n vertices of v (stride numbers each, x, y, z
     * first) is finite: asked only once a vertex sum was not finite, which
     * the sum of large finite numbers can also be, so no vertex pays for it.
     */
    static boolean allFinite(double[] v, int stride, int n) {
        for (int k = 0; k < n; k++) {
            int o = k * stride;
            if (!Double.isFinite(v[o]) || !Double.isFinite(v[o + 1]) || !Double.isFinite(v[o + 2])) {
                return false;
            }
        }
        return true;
    }
}
