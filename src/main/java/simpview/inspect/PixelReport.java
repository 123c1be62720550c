package simpview.inspect;

import java.util.ArrayList;
import java.util.List;
import java.util.function.IntFunction;
import simpview.geometry.Camera;
import simpview.scene.SceneException;
import simpview.scene.simp.ScenePipeline;
import simpview.scene.simp.SourcePlace;
import simpview.stage.Painter;
import simpview.surface.PageCanvas;

/**
 * What a replay found at one pixel: its final colour and depth, and every
 * write attempted at it in drawing order; for a scene with an error, as far
 * as the error, which it names. Printed as text or as JSON.
 */
public final class PixelReport {

    private final InspectedScene scene;
    private final int x;
    private final int y;
    private final int argb;
    private final double depth;
    private final List<HistoryEntry> history;
    private final SourceText text = new SourceText();

    private final IntFunction<PrimitiveSource> sources;

    private final ScenePipeline.Drawn drawn;
    private final SceneException error;
    /** The scene's view at its end: its camera, or the parallel view. */
    private final Camera camera;

    /**
     * @param error what stopped the scene, the history going as far as it; null when it was drawn to its end
     * @param camera the scene's view at its end
     */
    PixelReport(InspectedScene scene, ScenePipeline.Drawn drawn, SceneException error, int x,
            int y, int argb, double depth, List<HistoryEntry> history,
            IntFunction<PrimitiveSource> sources, Camera camera) {
        this.camera = camera;
        this.drawn = drawn;
        this.error = error;
        this.sources = sources;
        this.scene = scene;
        this.x = x;
        this.y = y;
        this.argb = argb;
        this.depth = depth;
        this.history = List.copyOf(history);
    }

    /** The pixel's x in the panel, 0 to 649 from the left. */
    public int x() {
        return x;
    }

    /** The pixel's y in the panel, 0 to 649 from the bottom (y up). */
    public int y() {
        return y;
    }

    /** The pixel's colour at the end, 0xAARRGGBB. */
    public int argb() {
        return argb;
    }

    /** The z-buffer at the pixel at the end (the far plane or -infinity where nothing was written). */
    public double depth() {
        return depth;
    }

    /** True when the scene was drawn (or, not drawn, would have been) by the lit rules. */
    public boolean lit() {
        return drawn.lit();
    }

    /** False when the scene was not drawn at all: depth-cue colours were asked for and it is lit ({@link #litBecause}). */
    public boolean drawn() {
        return drawn.drawn();
    }

    /** Where the scene's first lit command stands ("pageA.simp:3 camera"), or null when depth-cued. */
    public String litBecause() {
        return drawn.litBecause();
    }

    /** Every write attempted at the pixel, in drawing order, each with its outcome (unmodifiable). */
    public List<HistoryEntry> history() {
        return history;
    }

    /** The error the scene stops at, as the page stops there; null when it was drawn to its end. */
    public SceneException error() {
        return error;
    }

    /** The last write that went through: the pixel's owner; null for a background pixel. */
    public HistoryEntry lastWritten() {
        for (int k = history.size() - 1; k >= 0; k--) {
            if (history.get(k).outcome() == Outcome.WRITTEN) {
                return history.get(k);
            }
        }
        return null;
    }

    /** How the pixel's colour was made: the last written entry's explanation, or null for the background. */
    public Terms explanation() {
        HistoryEntry owner = lastWritten();
        return owner == null ? null : owner.explanation();
    }

    /**
     * Primitive n's vertices through every space, for one that reached the
     * pixel (or was asked for when inspecting); null otherwise.
     */
    public Terms vertices(int primitive) {
        PrimitiveSource s = sources.apply(primitive);
        return s == null ? null : VertexTable.of(s, text.describe(s.chain()), x, y);
    }

    /** The planes of outcode bits as a JSON list of their names. */
    private static void planeList(StringBuilder sb, int planes) {
        List<String> names = VertexTable.planeNames(planes);
        sb.append('[');
        for (int j = 0; j < names.size(); j++) {
            sb.append(j == 0 ? "" : ", ");
            Json.string(sb, names.get(j));
        }
        sb.append(']');
    }

    /**
     * A depth-cued scene's culling planes as the sides of its view box
     * (SPEC: -100 to 100 in x and y, z from 0 near to -200 far), not as a
     * camera's planes: the scene has no camera and no eye.
     */
    private static String boxSides(int planes) {
        List<String> sides = new ArrayList<>();
        for (String plane : VertexTable.planeNames(planes)) {
            sides.add(switch (plane) {
                case "hither" -> "near side (z = 0)";
                case "yon" -> "far side (z = -200)";
                case "left" -> "left side (x = -100)";
                case "right" -> "right side (x = 100)";
                case "bottom" -> "bottom side (y = -100)";
                case "top" -> "top side (y = 100)";
                default -> plane;
            });
        }
        return String.join(" and ", sides);
    }

    /** "page7.simp:6 › cubeline.simp:12 › cube.simp:7 polygon (...)". */
    public String describe(HistoryEntry e) {
        return text.describe(e.chain());
    }

    /**
     * Why nothing can be drawn at the pixel when its centre is outside the
     * camera's window on the panel (a window not square leaves bands of the
     * panel black, A3's pageH); else null.
     */
    String outsideTheWindow() {
        if (camera == null || !camera.isPerspective()) {
            return null;
        }
        double[] w = camera.windowOnPanel();
        double cx = x + 0.5;
        double cy = y + 0.5;
        if (cx >= w[0] && cx <= w[2] && cy >= w[1] && cy <= w[3]) {
            return null;
        }
        return "its centre is outside the camera's window, which covers panel x " + Json.number(w[0]) + " to "
                + Json.number(w[2]) + " and y " + Json.number(w[1]) + " to " + Json.number(w[3])
                + ": nothing of the scene lands here";
    }

    /**
     * A primitive's number as the reports and the window's stepping show it:
     * 1, 2, 3, ... in drawing order (the entries hold 0, 1, 2, ...).
     */
    public static int shown(int primitive) {
        return primitive + 1;
    }

    /**
     * The report as {@code simpview inspect} prints it: the pixel's colour, depth and owner, then, when asked for,
     * every write attempted ({@code --history}) and how the owner's colour was made ({@code --explain}).
     *
     * @param withHistory list every write attempted at the pixel
     * @param withExplanation explain the colour, term by term
     * @return lines of text, each ending in a line break
     */
    public String text(boolean withHistory, boolean withExplanation) {
        return text(withHistory, withExplanation, HistoryEntry.NO_NUMBER);
    }

    /** The report as text; with the vertex table of primitive {@code vertices} unless that is NO_NUMBER. */
    public String text(boolean withHistory, boolean withExplanation, int vertices) {
        return text(withHistory, withExplanation, vertices, HistoryEntry.NO_NUMBER);
    }

    /**
     * The last write primitive n attempted at the pixel (written, lost at
     * the depth test, or dropped by the scissor); null when it made none here.
     */
    public HistoryEntry attemptOf(int primitive) {
        for (int k = history.size() - 1; k >= 0; k--) {
            HistoryEntry e = history.get(k);
            if (e.primitive() == primitive && (e.outcome() == Outcome.WRITTEN || e.outcome() == Outcome.DEPTH_FAILED
                    || e.outcome() == Outcome.SCISSORED)) {
                return e;
            }
        }
        return null;
    }

    /**
     * What the text says of a write it does not work out term by term: a
     * depth-cued one that lost the depth test (its colour, and where that
     * came from: the cue, or the vertices' own colours), or one the scissor
     * dropped before the z-buffer.
     */
    private String unexplained(HistoryEntry e) {
        if (e.outcome() == Outcome.SCISSORED) {
            return "z " + Json.number(e.z()) + ", outside the view's depth range (z 0 to -200), so it never reached "
                    + "the z-buffer: nothing of it shows here";
        }
        int c = e.argb();
        return "rgb (" + (c >>> 16 & 0xFF) + ", " + (c >>> 8 & 0xFF) + ", " + (c & 0xFF) + "), "
                + (scene.ownColours() ? "its vertices' own colours at the pixel" : "the depth cue's colour at its depth")
                + "; not worked out term by term for a write that lost the depth test";
    }

    /** Whether the explanation asked for is another primitive's than the owner's. */
    private boolean explainsOther(int explained) {
        HistoryEntry owner = lastWritten();
        return explained != HistoryEntry.NO_NUMBER && (owner == null || owner.primitive() != explained);
    }

    /**
     * The report as text; with the vertex table of primitive {@code vertices}
     * unless that is NO_NUMBER, and with the explanation of primitive
     * {@code explained}'s write at the pixel instead of the owner's unless that
     * is NO_NUMBER (a write the depth test threw away, or one covered later).
     */
    public String text(boolean withHistory, boolean withExplanation, int vertices, int explained) {
        StringBuilder sb = new StringBuilder();
        sb.append("pixel (").append(x).append(", ").append(y).append(") of the panel (image pixel ")
                .append(x + PageCanvas.MARGIN).append(", row ").append(PageCanvas.MARGIN + PageCanvas.PANEL - 1 - y)
                .append("): rgb (").append(argb >>> 16 & 0xFF).append(", ").append(argb >>> 8 & 0xFF).append(", ")
                .append(argb & 0xFF).append("), depth ").append(Json.number(depth)).append('\n');
        HistoryEntry owner = lastWritten();
        String outside = outsideTheWindow();
        sb.append(owner == null ? "drawn by no primitive (background)" + (outside == null ? "" : ": " + outside) + "\n"
                : "drawn by primitive " + shown(owner.primitive()) + ": " + describe(owner) + "\n");
        if (withHistory) {
            int missed = 0;
            for (HistoryEntry e : history) {
                if (e.outcome() == Outcome.CULLED || e.outcome() == Outcome.CLIPPED) {
                    missed++;
                }
            }
            int attempted = history.size() - missed;
            sb.append("history: ").append(attempted).append(attempted == 1 ? " write" : " writes").append(" attempted");
            if (missed > 0) {
                sb.append(", and ").append(missed).append(missed == 1 ? " primitive" : " primitives")
                        .append(" culled or clipped that would have covered the pixel");
            }
            sb.append(", in drawing order\n");
            for (HistoryEntry e : history) {
                sb.append("  ").append(e.primitive() == HistoryEntry.NO_NUMBER ? "-" : "#" + shown(e.primitive()))
                        .append(' ').append(describe(e)).append('\n');
                sb.append("      ").append(e.outcome().word());
                if (!Double.isNaN(e.z())) {
                    int c = e.argb();
                    sb.append(", z ").append(Json.number(e.z())).append(", rgb (").append(c >>> 16 & 0xFF)
                            .append(", ").append(c >>> 8 & 0xFF).append(", ").append(c & 0xFF).append(')');
                }
                if (e.outcome() == Outcome.DEPTH_FAILED) {
                    sb.append(": stored depth ").append(Json.number(e.storedDepth())).append(e.storedOwner()
                            == HistoryEntry.NO_NUMBER ? " (nothing drawn yet)" : " of primitive " + shown(e.storedOwner()));
                    if (e.z() == e.storedDepth()) {
                        sb.append(", as deep: a write must be strictly nearer, so the first of the two stays");
                    }
                } else if (e.outcome() == Outcome.SCISSORED) {
                    sb.append(": outside the view's depth range");
                } else if (e.outcome() == Outcome.CULLED && !lit()) {
                    sb.append(": every vertex beyond the view box's ").append(boxSides(e.planes()))
                            .append("; seen straight down z, it covers the pixel");
                } else if (e.outcome() == Outcome.CULLED) {
                    sb.append(": every vertex outside the ").append(VertexTable.planes(e.planes()))
                            .append(" plane; its part in front of the eye, projected, covers the pixel");
                } else if (e.outcome() == Outcome.CLIPPED) {
                    sb.append(e.primitive() == HistoryEntry.NO_NUMBER ? ": clipped away whole" : ": drawn, but not here")
                            .append(" (cut by ").append(VertexTable.planes(e.planes()))
                            .append("); its part in front of the eye, projected, covers the pixel");
                    double[] here = e.here();
                    if (here != null) {
                        sb.append(", and there it is at camera (").append(Json.number(here[0])).append(", ")
                                .append(Json.number(here[1])).append(", ").append(Json.number(here[2]))
                                .append("), outside the ").append(VertexTable.planes(e.herePlanes()))
                                .append(e.herePlanes() == Integer.lowestOneBit(e.herePlanes()) ? " plane" : " planes");
                    }
                }
                sb.append('\n');
            }
        }
        if (error != null) {
            sb.append("the scene stops with an error here, as the page does, so the history ends:\n  ")
                    .append(error.getMessage().replace("\n", "\n  ")).append('\n');
        }
        Terms explanation = explanation();
        if (withExplanation && explainsOther(explained)) {
            HistoryEntry e = attemptOf(explained);
            sb.append("explain (primitive ").append(shown(explained));
            if (e == null) {
                sb.append("): it made no write at this pixel (its vertices show whether it covers it, and why)\n");
            } else {
                sb.append(", ").append(e.outcome().word()).append(" here").append(owner == null ? ""
                        : ", under primitive " + shown(owner.primitive()) + ", the pixel's");
                if (e.explanation() == null) {
                    sb.append("): ").append(unexplained(e)).append('\n');
                } else {
                    sb.append("):\n");
                    e.explanation().appendText(sb, "  ");
                }
            }
        } else if (withExplanation) {
            if (explanation == null) {
                sb.append("explain: the background, nothing was drawn here\n");
            } else {
                sb.append("explain (primitive ").append(shown(owner.primitive())).append("):\n");
                explanation.appendText(sb, "  ");
            }
        }
        if (vertices != HistoryEntry.NO_NUMBER) {
            Terms table = vertices(vertices);
            if (table == null) {
                sb.append("vertices: primitive ").append(shown(vertices)).append(" is not in this scene\n");
            } else {
                sb.append("vertices of primitive ").append(shown(vertices)).append(":\n");
                table.appendText(sb, "  ");
            }
        }
        return sb.toString();
    }

    /**
     * The report as one JSON object, as {@code simpview inspect --json} prints it.
     *
     * @param withHistory with the writes attempted at the pixel
     * @param withExplanation with how the owner's colour was made
     */
    public String json(boolean withHistory, boolean withExplanation) {
        return json(withHistory, withExplanation, HistoryEntry.NO_NUMBER);
    }

    /** The report as one JSON object; with "vertices" for primitive {@code vertices} unless that is NO_NUMBER. */
    public String json(boolean withHistory, boolean withExplanation, int vertices) {
        return json(withHistory, withExplanation, vertices, HistoryEntry.NO_NUMBER);
    }

    /**
     * The same, with "explain" for primitive {@code explained}'s write at the
     * pixel unless that is NO_NUMBER, and then "explained": its number and
     * what became of the write (null: it made none here).
     */
    public String json(boolean withHistory, boolean withExplanation, int vertices, int explained) {
        StringBuilder sb = new StringBuilder("{\"pixel\": {\"x\": ").append(x).append(", \"y\": ").append(y)
                .append(", \"image_x\": ").append(x + PageCanvas.MARGIN)
                .append(", \"image_row\": ").append(PageCanvas.MARGIN + PageCanvas.PANEL - 1 - y)
                .append(", \"rgb\": [").append(argb >>> 16 & 0xFF).append(", ").append(argb >>> 8 & 0xFF)
                .append(", ").append(argb & 0xFF).append("], \"depth\": ");
        Json.number(sb, depth);
        HistoryEntry owner = lastWritten();
        sb.append(", \"owner\": ").append(owner == null ? "null" : String.valueOf(shown(owner.primitive())));
        sb.append("}, \"lit\": ").append(drawn.lit()).append(", \"error\": ");
        if (error == null) {
            sb.append("null");
        } else {
            Json.string(sb, error.getMessage());
        }
        if (withHistory) {
            sb.append(", \"history\": [");
            for (int k = 0; k < history.size(); k++) {
                HistoryEntry e = history.get(k);
                sb.append(k == 0 ? "" : ", ").append("{\"primitive\": ")
                        .append(e.primitive() == HistoryEntry.NO_NUMBER ? "null" : String.valueOf(shown(e.primitive())))
                        .append(", \"kind\": ");
                Json.string(sb, e.kind() == Painter.LINE ? "line" : e.kind() == Painter.WIRE ? "wire" : "filled");
                sb.append(", \"chain\": [");
                List<SourcePlace> chain = e.chain();
                for (int j = 0; j < chain.size(); j++) {
                    sb.append(j == 0 ? "" : ", ");
                    Json.string(sb, chain.get(j).toString());
                }
                sb.append("], \"command\": ");
                Json.string(sb, chain.isEmpty() ? "" : text.line(chain.get(chain.size() - 1)));
                sb.append(", \"z\": ");
                Json.number(sb, e.z());
                int c = e.argb();
                sb.append(", \"rgb\": ").append(Double.isNaN(e.z()) ? "null"
                        : "[" + (c >>> 16 & 0xFF) + ", " + (c >>> 8 & 0xFF) + ", " + (c & 0xFF) + "]");
                sb.append(", \"outcome\": ");
                Json.string(sb, e.outcome().word());
                if (e.outcome() == Outcome.DEPTH_FAILED) {
                    sb.append(", \"stored_depth\": ");
                    Json.number(sb, e.storedDepth());
                    sb.append(", \"stored_owner\": ").append(e.storedOwner() == HistoryEntry.NO_NUMBER ? "null"
                            : String.valueOf(shown(e.storedOwner())));
                }
                if (e.outcome() == Outcome.CULLED || e.outcome() == Outcome.CLIPPED) {
                    sb.append(e.outcome() == Outcome.CULLED ? ", \"culled_by\": " : ", \"cut_by\": ");
                    planeList(sb, e.planes());
                    double[] here = e.here();
                    if (here != null) {
                        sb.append(", \"here\": {\"camera\": [");
                        for (int axis = 0; axis < 3; axis++) {
                            sb.append(axis == 0 ? "" : ", ");
                            Json.number(sb, here[axis]);
                        }
                        sb.append("], \"outside\": ");
                        planeList(sb, e.herePlanes());
                        sb.append('}');
                    }
                }
                sb.append('}');
            }
            sb.append(']');
        }
        if (withExplanation && explainsOther(explained)) {
            HistoryEntry e = attemptOf(explained);
            sb.append(", \"explained\": {\"primitive\": ").append(shown(explained)).append(", \"outcome\": ");
            if (e == null) {
                sb.append("null}");
            } else {
                Json.string(sb, e.outcome().word());
                sb.append('}');
            }
            sb.append(", \"explain\": ");
            if (e == null || e.explanation() == null) {
                sb.append("null");
            } else {
                e.explanation().appendJson(sb);
            }
        } else if (withExplanation) {
            sb.append(", \"explain\": ");
            Terms explanation = explanation();
            if (explanation == null) {
                sb.append("{\"final_rgb\": [").append(argb >>> 16 & 0xFF).append(", ").append(argb >>> 8 & 0xFF)
                        .append(", ").append(argb & 0xFF).append("], \"background\": true");
                String outside = outsideTheWindow();
                if (outside != null) {
                    sb.append(", \"outside_window\": ");
                    Json.string(sb, outside);
                }
                sb.append('}');
            } else {
                explanation.appendJson(sb);
            }
        }
        if (vertices != HistoryEntry.NO_NUMBER) {
            sb.append(", \"vertices\": ");
            Terms table = vertices(vertices);
            if (table == null) {
                sb.append("null");
            } else {
                table.appendJson(sb);
            }
        }
        return sb.append('}').toString();
    }
}
