package simpview.pages;

import java.util.List;
import simpview.surface.PageCanvas;

/**
 * One of the first assignment's five pages, drawn in steps for the window's
 * stepping: step n has every panel draw its first n lines (pages 1-3, the
 * same line in each panel, by each panel's drawer) or its first n
 * triangles (pages 4-5, each panel's own scene; a panel whose scene is
 * shorter is whole from its last triangle on). A student steps through
 * a line test to see the four drawers take the same line side by side.
 */
public sealed interface A1Page extends Page permits LineTestPage, PolygonTestPage {

    /** Each panel's name, panel k's at k - 1: its drawer ("Bresenham") on a page of lines, its scene ("mesh") else. */
    List<String> panelNames();

    /** How many steps draw the whole page: the most lines or triangles of any panel. */
    int steps(PageContext context);

    /** Draws the first {@code steps} of every panel (all of them for steps >= {@link #steps}). */
    void drawSteps(PageCanvas canvas, PageContext context, int steps);

    /** What step n (1-based) drew, for the line under the page. */
    String describeStep(PageContext context, int step);

    /** What step n drew, as given, over every panel it drew in. */
    A1Marks stepMarks(PageContext context, int step);
}
