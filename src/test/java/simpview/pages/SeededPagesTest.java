package simpview.pages;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.awt.image.BufferedImage;
import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.api.Test;
import simpview.geometry.Vertex;
import simpview.scene.SceneException;
import simpview.surface.PageCanvas;

/**
 * Pages 1 to 3 against SPEC's numbers, for many seeds, rather than against
 * golden pictures: the mesh's 11x11 vertices 60 px apart, inset 25 px, each
 * moved by at most 15 px in x and y, colours in [0, 1]; the z-buffer page's
 * six regular triangles on the circle of radius 275 around the panel centre,
 * turned by [0, 120) degrees, at world z in [-199, -1], greys 1 to .25 in
 * drawing order, drawn without depth cueing: the panel centre, inside all
 * six, shows the grey of the nearest, and no other grey appears anywhere.
 */
class SeededPagesTest {

    private static final int SEEDS = 200;
    private static final double CENTRE = PageCanvas.PANEL / 2.0;

    @Test
    void theMeshIsAnElevenByElevenGridMovedByAtMostFifteenPixels() {
        double largest = 0;
        double smallest = Double.MAX_VALUE;
        for (long seed = 0; seed < SEEDS; seed++) {
            PerturbedMesh mesh = new PerturbedMesh(seed);
            for (int row = 0; row < 11; row++) {
                for (int col = 0; col < 11; col++) {
                    Vertex v = mesh.vertex(row, col);
                    for (double offset : new double[] {v.x() - (25 + 60 * col), v.y() - (25 + 60 * row)}) {
                        if (Math.abs(offset) > 15) {
                            fail("seed " + seed + ", vertex " + row + "," + col + " moved too far: " + v);
                        }
                        largest = Math.max(largest, offset);
                        smallest = Math.min(smallest, offset);
                    }
                    if (!(inUnit(v.r()) && inUnit(v.g()) && inUnit(v.b()))) {
                        fail("seed " + seed + ", colour " + v);
                    }
                }
            }
        }
        assertTrue(largest > 14.9 && smallest < -14.9, "offsets spread over [-15, 15]: " + smallest + " to " + largest);
    }

    private static boolean inUnit(double c) {
        return c >= 0 && c <= 1;
    }

    @Test
    void theMeshIsTwoTrianglesACellOverItsGrid() {
        PerturbedMesh mesh = new PerturbedMesh(7);
        Set<Vertex> used = new HashSet<>();
        int[] triangles = {0};
        mesh.forEachTriangle((a, b, c) -> {
            triangles[0]++;
            used.add(a);
            used.add(b);
            used.add(c);
        });
        assertEquals(2 * 10 * 10, triangles[0]);
        assertEquals(11 * 11, used.size(), "every grid vertex is a corner");
    }

    @Test
    void theZBufferPagesTrianglesAreRegularOnTheCircleTurnedAndSetInDepth() {
        double smallestTurn = 360;
        double largestTurn = 0;
        for (long seed = 0; seed < SEEDS; seed++) {
            Vertex[][] triangles = ZBufferPage.triangles(seed);
            assertEquals(6, triangles.length);
            for (int t = 0; t < 6; t++) {
                double grey = 1 - 0.15 * t;
                Vertex[] tri = triangles[t];
                double z = tri[0].z();
                assertTrue(z >= -199 && z <= -1, "seed " + seed + ", triangle " + t + " at z " + z);
                for (int k = 0; k < 3; k++) {
                    Vertex v = tri[k];
                    assertEquals(275, Math.hypot(v.x() - CENTRE, v.y() - CENTRE), 1e-9, "on the circle");
                    assertEquals(z, v.z(), "one depth for the triangle");
                    assertEquals(grey, v.r(), 1e-12, "grey of triangle " + t);
                    assertEquals(grey, v.g(), 1e-12);
                    assertEquals(grey, v.b(), 1e-12);
                    Vertex next = tri[(k + 1) % 3];
                    assertEquals(275 * Math.sqrt(3), Math.hypot(next.x() - v.x(), next.y() - v.y()), 1e-9, "regular");
                }
                // A regular triangle's turn is the angle of a corner, less 90 degrees, modulo 120.
                double corner = Math.toDegrees(Math.atan2(tri[0].y() - CENTRE, tri[0].x() - CENTRE)) - 90;
                double turn = ((corner % 120) + 120) % 120;
                smallestTurn = Math.min(smallestTurn, turn);
                largestTurn = Math.max(largestTurn, turn > 120 - 1e-9 ? 0 : turn);
            }
        }
        assertTrue(smallestTurn < 1 && largestTurn > 119, "turns spread over [0, 120): " + smallestTurn + " to "
                + largestTurn);
    }

    @Test
    void theZBufferPageShowsTheNearestGreyAtTheCentreAndOnlyTheGivenGreys() throws SceneException {
        PageRenderer renderer = new PageRenderer();
        Set<Integer> levels = new HashSet<>();
        for (int t = 0; t < 6; t++) {
            levels.add((int) Math.round((1 - 0.15 * t) * 255));
        }
        for (long seed = 1; seed <= 3; seed++) {
            BufferedImage page = renderer.renderImage(3, PageContext.defaults().withSeed(seed));
            Vertex[][] triangles = ZBufferPage.triangles(seed);
            int nearest = 0;
            for (int t = 1; t < 6; t++) {
                nearest = triangles[t][0].z() > triangles[nearest][0].z() ? t : nearest;
            }
            int grey = (int) Math.round((1 - 0.15 * nearest) * 255);
            int centre = page.getRGB(PageCanvas.MARGIN + 325, PageCanvas.MARGIN + 325) & 0xFFFFFF;
            assertEquals(grey * 0x010101, centre, "seed " + seed + ": the nearest triangle, " + nearest);
            for (int y = PageCanvas.MARGIN; y < PageCanvas.MARGIN + PageCanvas.PANEL; y++) {
                for (int x = PageCanvas.MARGIN; x < PageCanvas.MARGIN + PageCanvas.PANEL; x++) {
                    int rgb = page.getRGB(x, y) & 0xFFFFFF;
                    int level = rgb & 0xFF;
                    if (rgb != 0 && !(rgb == level * 0x010101 && levels.contains(level))) {
                        fail("seed " + seed + ", pixel " + x + "," + y + ": " + Integer.toHexString(rgb));
                    }
                }
            }
        }
    }
}
