package simpview.pages;

import java.util.List;
import simpview.geometry.Vertex;

/**
 * A line or a triangle that a page made itself (not read from a scene
 * file), with its vertices exactly as its drawer is given them: what
 * {@code render --primitives} writes, so that a student's own renderer can
 * draw the seeded pages from simpview's numbers and be compared with them.
 *
 * @param panel which panel draws it: 1 to 4 on the first assignment's pages, 1 on the eight pages'
 * @param vertices two (a line) or three (a triangle), in panel coordinates as the course counts them (x right,
 *     y up from the panel's bottom-left pixel), z as given, colours 0 to 1
 */
public record ListedPrimitive(int panel, List<Vertex> vertices) {

    public ListedPrimitive {
        vertices = List.copyOf(vertices);
        if (vertices.size() != 2 && vertices.size() != 3) {
            throw new IllegalArgumentException("a line or a triangle, not " + vertices.size() + " vertices");
        }
    }

    public boolean isLine() {
        return vertices.size() == 2;
    }

    /**
     * One line of text: "line" or "triangle", the panel, then x y z r g b of each vertex. Every number is
     * Java's shortest decimal that reads back as the same double (Double.toString), so a program that parses
     * it (Java, C's strtod, Python's float) has simpview's very numbers.
     */
    public String text() {
        StringBuilder out = new StringBuilder(isLine() ? "line" : "triangle").append(' ').append(panel);
        for (Vertex v : vertices) {
            for (double number : new double[] {v.x(), v.y(), v.z(), v.r(), v.g(), v.b()}) {
                out.append(' ').append(number);
            }
        }
        return out.toString();
    }
}
