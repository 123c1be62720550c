package simpview.tools.shapes;

/**
 * Builds the text of a Wavefront .obj file in the subset simpview reads:
 * {@code v}, {@code vn} and {@code f} lines, 1-based indices. Numbers are
 * written as {@link SimpWriter#number} writes them, so regenerating a model
 * gives the same bytes.
 */
final class ObjWriter {

    private final StringBuilder text = new StringBuilder();

    ObjWriter comment(String line) {
        text.append("# ").append(line).append('\n');
        return this;
    }

    ObjWriter blank() {
        text.append('\n');
        return this;
    }

    ObjWriter vertex(double[] p) {
        return triple("v", p);
    }

    ObjWriter normal(double[] n) {
        return triple("vn", n);
    }

    /** A face of vertices only ({@code f 1 2 3}): its normal is the face's. */
    ObjWriter face(int... vertices) {
        text.append('f');
        for (int v : vertices) {
            text.append(' ').append(v);
        }
        text.append('\n');
        return this;
    }

    /** A face whose every vertex has the normal of the same index ({@code f 1//1 2//2 3//3}). */
    ObjWriter smoothFace(int... vertices) {
        text.append('f');
        for (int v : vertices) {
            text.append(' ').append(v).append("//").append(v);
        }
        text.append('\n');
        return this;
    }

    private ObjWriter triple(String keyword, double[] p) {
        text.append(keyword).append(' ').append(SimpWriter.number(p[0])).append(' ')
                .append(SimpWriter.number(p[1])).append(' ').append(SimpWriter.number(p[2])).append('\n');
        return this;
    }

    @Override
    public String toString() {
        return text.toString();
    }
}
