package simpview.inspect;

import java.util.List;
import simpview.geometry.Camera;
import simpview.geometry.Matrix4;
import simpview.scene.simp.SourcePlace;

/**
 * A primitive as its command wrote it, with what took it to the panel: the
 * include chain of its command, its object-space vertices, the CTM at its
 * command, W (world to camera; the identity for a depth-cued scene) and the
 * camera; and the outline the rasterizer was given, clipped and projected:
 * panel x and y of each of its vertices in turn ({@code drawn.length / 2} of
 * them).
 */
record PrimitiveSource(int primitive, List<SourcePlace> chain, int kind, Matrix4 ctm, Matrix4 worldToCamera,
        Camera camera, boolean lit, double[] xyz, int vertices, double[] drawn) {
}
