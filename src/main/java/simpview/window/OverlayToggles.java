package simpview.window;

import java.util.ArrayList;
import java.util.List;
import java.util.function.BiConsumer;
import java.util.function.Consumer;
import simpview.inspect.InspectedScene;
import simpview.inspect.Overdraw;
import simpview.inspect.SkippedPrimitives;
import simpview.window.instruments.BackFacePicture;
import simpview.window.instruments.DepthPicture;
import simpview.window.instruments.Inspector;
import simpview.window.instruments.InspectorPanel;
import simpview.window.instruments.Legend;
import simpview.window.instruments.OverdrawPicture;
import simpview.window.instruments.Outlines;
import simpview.window.render.PageFacts;
import simpview.window.render.RenderedView;
import simpview.window.render.View;

/**
 * The overlays the view menu turns on and off over the finished picture:
 * overdraw and depth-test failures (V, Shift+V) and back faces (K) in the
 * picture's place, the culled and clipped-away outlines (U) and wire over
 * fill (W) over it; and the picture itself, or its depths, shown again
 * without them. The overlays that need a replay of the scene have it made
 * on the inspector's thread. All methods run on the EDT.
 */
final class OverlayToggles {

    private final PageView pageView;
    private final LegendStrip legendStrip;
    private final StatusStrip status;
    private final InspectorPanel inspectorPanel;
    private final OnScreen onScreen;
    private boolean overdrawShown;
    /** The overdraw overlay shows the depth-test failures (Shift+V), not every write (V). */
    private boolean overdrawFailures;
    private boolean backFacesShown;
    private int backFaces = -1;
    private int overdrawMax = -1;
    /** What the culled and clipped-away overlay last found: for the tests. */
    private SkippedPrimitives.Found skippedFound;

    /** The overlays of the view {@code onScreen}, drawn on {@code pageView} with their legends and words. */
    OverlayToggles(PageView pageView, LegendStrip legendStrip, StatusStrip status, InspectorPanel inspectorPanel,
            OnScreen onScreen) {
        this.pageView = pageView;
        this.legendStrip = legendStrip;
        this.status = status;
        this.inspectorPanel = inspectorPanel;
        this.onScreen = onScreen;
    }

    /** Whether the overdraw overlay is shown, counting the depth-test failures ({@code failures}) or every write. */
    boolean overdrawShown(boolean failures) {
        return overdrawShown && overdrawFailures == failures;
    }

    boolean backFacesShown() {
        return backFacesShown;
    }

    /**
     * The overdraw overlay (V): each pixel by how many writes reached its
     * depth test, with its scale; or (Shift+V) by how many of them lost it.
     * Again: the page.
     */
    void toggleOverdraw(boolean failures) {
        if (overdrawShown) {
            boolean same = overdrawFailures == failures;
            showPicture();
            if (same) {
                status.sayHints();
                return;
            }
            // the other count asked for while one is shown: it takes the place of the one shown
        }
        replayForOverlay("Counting the writes of every pixel ...",
                "The overdraw could not be counted: the scene could not be read.", inspectorPanel::overdraw, counts -> {
            int[] shownCounts = failures ? counts.failed() : counts.reached();
            overdrawShown = true;
            overdrawFailures = failures;
            overdrawMax = Overdraw.max(shownCounts);
            pageView.show(failures
                    ? OverdrawPicture.of(shownCounts,
                            "depth-test failures: writes that lost each pixel's depth test")
                    : OverdrawPicture.of(shownCounts), null, true);
            String writes = overdrawMax == 1 ? " write" : " writes";
            status.say((failures ? "Depth-test failures: up to " + overdrawMax + " lost" + writes + " at a pixel"
                    : "Overdraw: up to " + overdrawMax + writes + " at a pixel") + asFarAsTheError()
                    + " (the scale is above the panel) · " + (failures ? "Shift+V" : "V") + ": the page again");
        });
    }

    /** What an overlay of a scene with an error says it covers: the drawing up to the error, as the page shows. */
    private String asFarAsTheError() {
        RenderedView view = onScreen.picture();
        return view != null && view.error() != null ? ", as far as the scene's error" : "";
    }

    /**
     * An overlay made by replaying the shown scene on the inspector's thread:
     * says {@code working} meanwhile, then gives the answer to {@code show}
     * on the EDT, unless the picture changed first (then nothing) or
     * nothing of the scene could be read (then {@code failed} is said).
     */
    private <T> void replayForOverlay(String working, String failed,
            BiConsumer<InspectedScene, Consumer<T>> replay, Consumer<T> show) {
        if (onScreen.picture() == null) {
            return;
        }
        InspectedScene scene = onScreen.inspectedScene(status::say);
        if (scene == null) {
            return;
        }
        RenderedView of = onScreen.picture();
        status.say(working);
        replay.accept(scene, answer -> {
            if (onScreen.picture() != of || answer == null) {
                status.say(answer == null ? failed : "");
                return;
            }
            show.accept(answer);
        });
    }

    /** The back-face overlay (K): pixels of clockwise polygons tinted magenta; again: the page. */
    void toggleBackFaces() {
        if (backFacesShown) {
            showPicture();
            status.sayHints();
            return;
        }
        RenderedView view = onScreen.picture();
        if (view == null) {
            return;
        }
        if (view.view() instanceof View.OfAssignment1Page) {
            status.say("Back faces are a scene's (pages 4-8, opened scenes): the first assignment's triangles are "
                    + "filled whichever way round they are given.");
            return;
        }
        BackFacePicture.Tinted tinted =
                BackFacePicture.of(view.image(), view.facts());
        if (tinted == null) {
            status.say("Who drew each pixel was not recorded for this picture: no back faces to show.");
            return;
        }
        showPicture();
        backFacesShown = true;
        backFaces = tinted.backFacing();
        pageView.show(tinted.image(), null, true);
        legendStrip.show("back faces", new Legend("back faces", List.of(
                new Legend.Entry(0xFF00FF, "clockwise on the panel (facing away)"))));
        status.say("Back faces tinted magenta: " + tinted.backFacing() + " of " + tinted.polygons()
                + " polygons are clockwise on the panel · K: the page again");
    }

    /**
     * The culled and clipped-away outlines (U): found by a replay on the
     * inspector's thread that writes no pixel, drawn over the page with a
     * legend; again: off. A new picture takes them away.
     */
    void toggleSkipped() {
        if (pageView.skippedShown()) {
            pageView.skipped(null, null);
            legendStrip.show("skipped", null);
            status.sayHints();
            return;
        }
        replayForOverlay("Finding the primitives culled and clipped away ...",
                "The scene could not be read: no outlines.", inspectorPanel::skipped, found -> {
            List<double[]> culled = new ArrayList<>();
            List<double[]> clipped = new ArrayList<>();
            for (SkippedPrimitives.Skipped s : found.outlined()) {
                (s.culled() ? culled : clipped).add(Inspector.toImage(s.outline()));
            }
            skippedFound = found;
            pageView.skipped(culled, clipped);
            legendStrip.show("skipped", new Legend("never rasterized", List.of(
                    new Legend.Entry(PageView.CULLED.getRGB() & 0xFFFFFF, culled.size() + " culled"),
                    new Legend.Entry(PageView.CLIPPED.getRGB() & 0xFFFFFF, clipped.size() + " clipped away"))));
            long outside = found.outsideThePanel();
            status.say(culled.size() + " culled and " + clipped.size() + " clipped-away primitives outlined"
                    + (outside == 0 ? "" : "; " + outside + " of them " + (outside == 1 ? "lies" : "lie")
                    + " wholly outside the panel, where the outlines are cut away")
                    + asFarAsTheError() + (found.unprojectable() > 0 ? "; " + found.unprojectable() + " more lie wholly at or behind "
                    + "the eye and have no outline" : "") + " · U: off");
        });
    }

    /** Wire over fill (W): every primitive's edges over the page; again: off. */
    void toggleWire() {
        if (pageView.wireShown()) {
            pageView.wire(null);
            legendStrip.show("wire", null);
            status.sayHints();
            return;
        }
        showWire();
    }

    private void showWire() {
        RenderedView view = onScreen.picture();
        List<double[]> outlines = Outlines.wire(view == null ? null : view.facts().primitives());
        if (outlines.isEmpty()) {
            pageView.wire(null);
            legendStrip.show("wire", null);
            status.say("Wire over fill needs a scene's record of its primitives: pages 4-8 and opened scenes.");
            return;
        }
        pageView.wire(outlines);
        legendStrip.show("wire", new Legend("wire over fill", List.of(
                new Legend.Entry(0x00FF80, "the edges of all " + outlines.size() + " primitives"))));
    }

    /** Shows the picture, or its depths, of the finished view. */
    void showPicture() {
        overdrawShown = false;
        backFacesShown = false;
        RenderedView view = onScreen.picture();
        if (view != null) {
            PageFacts facts = view.facts();
            boolean depths = onScreen.settings().depthView() && facts.depths() != null
                    && !(view.view() instanceof View.OfAssignment1Page);
            pageView.show(depths ? DepthPicture.of(facts.depths(), facts.depthStart()) : view.image(), view.error(),
                    facts.drewSomething());
        }
        legendStrip.clear();
        pageView.skipped(null, null);
        if (pageView.wireShown()) {
            showWire();
        }
    }

    // For tests: what the overlays show.

    /** What the culled and clipped-away overlay shows, or null while it is off. */
    SkippedPrimitives.Found skippedShown() {
        return pageView.skippedShown() ? skippedFound : null;
    }

    /** How many polygons the back-face overlay tints while it is shown, else -1. */
    int backFacesShownCount() {
        return backFacesShown ? backFaces : -1;
    }

    /** The overdraw overlay's largest count while it is shown, else -1. */
    int overdrawShownMax() {
        return overdrawShown ? overdrawMax : -1;
    }
}
