package simpview.scene.obj;

import simpview.stage.ObjFace;

import java.util.ArrayList;
import java.util.List;

/** A sink that copies every face it gets into plain values, to compare whole models. */
final class CollectedFaces implements ObjSink {

    /** One vertex of a face as the sink saw it; colour and normal NaN when absent. */
    record Corner(double x, double y, double z, boolean colored, double r, double g, double b,
            boolean hasNormal, double nx, double ny, double nz, int vertex, int normal) {
    }

    record Face(int line, List<Corner> corners) {
    }

    final List<Face> faces = new ArrayList<>();

    @Override
    public void face(ObjFace face) {
        List<Corner> corners = new ArrayList<>();
        for (int k = 0; k < face.size(); k++) {
            boolean n = face.hasNormal(k);
            corners.add(new Corner(face.x(k), face.y(k), face.z(k), face.hasColor(k), face.r(k), face.g(k),
                    face.b(k), n, n ? face.nx(k) : Double.NaN, n ? face.ny(k) : Double.NaN,
                    n ? face.nz(k) : Double.NaN, face.vertex(k), face.normal(k)));
        }
        faces.add(new Face(face.line(), corners));
    }

    static Corner at(double x, double y, double z, int vertex) {
        return new Corner(x, y, z, false, Double.NaN, Double.NaN, Double.NaN, false, Double.NaN, Double.NaN,
                Double.NaN, vertex, -1);
    }

    static Corner coloured(double x, double y, double z, double r, double g, double b, int vertex) {
        return new Corner(x, y, z, true, r, g, b, false, Double.NaN, Double.NaN, Double.NaN, vertex, -1);
    }

    static Corner withNormal(Corner c, double nx, double ny, double nz, int normal) {
        return new Corner(c.x(), c.y(), c.z(), c.colored(), c.r(), c.g(), c.b(), true, nx, ny, nz, c.vertex(),
                normal);
    }
}
