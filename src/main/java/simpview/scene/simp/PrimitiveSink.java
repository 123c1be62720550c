package simpview.scene.simp;

/**
 * Where the client puts each primitive it has transformed and not culled:
 * straight to the renderers ({@link Painter}), or into a batch that the
 * drawing thread draws later ({@link PrimitiveBatch}).
 */
interface PrimitiveSink {

    /**
     * @param kind {@link Painter#LINE}, {@link Painter#FILLED} or {@link Painter#WIRE}
     * @param p the vertices in panel space, {@link simpview.geometry.Vertex#NUMBERS} numbers each
     *     (x, y, z, r, g, b); read before the call returns, never kept
     */
    void add(int kind, double[] p);
}
