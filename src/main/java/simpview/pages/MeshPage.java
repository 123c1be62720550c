package simpview.pages;

import java.util.ArrayList;
import java.util.List;
import simpview.raster.DdaLineRenderer;
import simpview.raster.FilledPolygonRenderer;
import simpview.raster.PolygonRenderer;
import simpview.raster.WireframePolygonRenderer;
import simpview.surface.Drawable;
import simpview.surface.PageCanvas;

/** Pages 1 and 2: the perturbed mesh with random vertex colours, as lines or filled. */
public final class MeshPage implements Page {

    private final boolean filled;

    private MeshPage(boolean filled) {
        this.filled = filled;
    }

    /** Page 1: every triangle's edges, colour lerped along each line. */
    public static MeshPage wireframe() {
        return new MeshPage(false);
    }

    /** Page 2: the same mesh filled, colour blerped, no lines. */
    public static MeshPage filled() {
        return new MeshPage(true);
    }

    /** True for page 2's filled mesh, false for page 1's wireframe. */
    public boolean isFilled() {
        return filled;
    }

    @Override
    public String title() {
        return filled ? "Filled mesh (blerp)" : "Wireframe mesh (lerp)";
    }

    @Override
    public boolean usesSeed() {
        return true;
    }

    /** The mesh's triangles, two a cell (page 1 draws their outlines). */
    @Override
    public List<ListedPrimitive> primitives(PageContext context) {
        List<ListedPrimitive> out = new ArrayList<>();
        new PerturbedMesh(context.seed()).forEachTriangle((a, b, c) -> out.add(new ListedPrimitive(1, List.of(a, b, c))));
        return out;
    }

    /** Its triangles are drawn straight onto the panel, without depth or a provenance record. */
    @Override
    public boolean keepsOwners() {
        return false;
    }

    @Override
    public void draw(PageCanvas canvas, PageContext context) {
        PolygonRenderer renderer = filled
                ? new FilledPolygonRenderer()
                : new WireframePolygonRenderer(new DdaLineRenderer());
        Drawable panel = canvas.panel();
        panel.settle(); // what the clear owes, made before the first write rather than by it
        new PerturbedMesh(context.seed()).forEachTriangle((a, b, c) -> renderer.drawPolygon(a, b, c, panel));
    }
}
