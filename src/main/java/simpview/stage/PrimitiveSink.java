package simpview.stage;

/**
 * Where the depth-cued geometry stage puts each primitive it has transformed,
 * culled and projected: straight to the renderers ({@link Painter}), or into a
 * batch that the drawing thread draws later.
 */
public interface PrimitiveSink {

    /**
     * @param kind {@link Painter#LINE}, {@link Painter#FILLED} or {@link Painter#WIRE}
     * @param p the vertices in panel space, {@link simpview.geometry.Vertex#NUMBERS} numbers each
     *     (x, y, z, r, g, b); read before the call returns, never kept
     */
    void add(int kind, double[] p);
}
