package simpview.window.instruments;

import simpview.window.render.RenderedView;
import simpview.window.render.View;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalInt;
import java.util.function.BiConsumer;
import java.util.function.Consumer;
import java.util.concurrent.Executor;
import java.util.function.Supplier;
import javax.swing.JFileChooser;
import javax.swing.JFrame;
import javax.swing.SwingUtilities;
import javax.swing.filechooser.FileNameExtensionFilter;
import simpview.compare.CompareException;
import simpview.compare.Comparison;
import simpview.compare.ComparisonReport;
import simpview.compare.DiffRegion;
import simpview.compare.DiffRegions;
import simpview.compare.HeatMap;
import simpview.compare.PanelGridComparison;
import simpview.compare.Percent;
import simpview.compare.Picture;
import simpview.compare.Shares;
import simpview.compare.SubmissionNames;
import simpview.compare.SystematicError;
import simpview.compare.WorstPixel;
import simpview.pages.A1Layout;
import simpview.pages.A1Rule;
import simpview.pages.Assignment1;
import simpview.pages.PageContext;
import simpview.surface.PageCanvas;

/**
 * Compare mode in the window (issue 15). A picture dropped on a page, or
 * opened with Ctrl+Shift+O (the dialog opens in the scene's folder), is compared with the view on screen and stays
 * with that view (stepping away and back keeps it). B flips between ours and
 * theirs, H shows the heat map, Backspace stops comparing; the status line
 * gives the shares. Everything here runs on the EDT but the comparisons
 * themselves: the picture read, compared, and searched for a mistake of the
 * whole panel on a thread the window hands over (its render thread), each
 * shown when it is done if its view is still on screen.
 */
public final class ComparisonLayer {

    /** What the page view shows while comparing. */
    public enum Showing { OURS, THEIRS, HEAT }

    private static final int TOLERANCE = Comparison.DEFAULT_TOLERANCE;

    private final JFrame owner;
    /** Puts a picture (and the error to show over it, or null) on the screen. */
    private final BiConsumer<BufferedImage, String> pageView;
    private final Consumer<String> say;
    private final Map<View, Picture> theirs = new HashMap<>();
    private RenderedView shown;
    private Comparison comparison;
    /** The mistake that changes their whole panel the same way, or null (made once a comparison is). */
    private SystematicError systematic;
    /**
     * Of a picture that fails and no such mistake explains, the pixel to look at first (the one that differs most
     * in its largest patch), else null.
     */
    private WorstPixel look;
    private Showing showing = Showing.OURS;
    private String text = "";

    /** The heat map's legend while it is shown, else null. */
    private final Consumer<Legend> legend;
    /** How the window draws its pages now: the seed and the first assignment's rule a page asked for is drawn with. */
    private final Supplier<PageContext> drawing;
    /** Where the comparisons are made, off the EDT, one after another. */
    private final Executor offEdt;

    public ComparisonLayer(JFrame owner, BiConsumer<BufferedImage, String> pageView, Consumer<String> say,
            Consumer<Legend> legend, Supplier<PageContext> drawing, Executor offEdt) {
        this.owner = owner;
        this.pageView = pageView;
        this.say = say;
        this.legend = legend;
        this.drawing = drawing;
        this.offEdt = offEdt;
    }

    /**
     * A comparison made off the EDT: the mistake that changes their whole panel the same way, or else the pixel
     * to look at first, with it.
     */
    private record Found(Comparison comparison, SystematicError systematic, WorstPixel look) {

        static Found of(RenderedView ours, Picture theirs) {
            Comparison comparison = Comparison.of(Picture.ofPage(ours.image(), "simpview").panel(), theirs.panel());
            SystematicError systematic = SystematicError.find(comparison, TOLERANCE);
            return new Found(comparison, systematic, systematic != null ? null : lookAt(comparison));
        }
    }

    /**
     * Compares a picture with the view on screen, off the EDT; a picture that cannot be compared is said why.
     * Its outcome is shown when it is done, if the view is still on screen (else when the view is shown again).
     */
    public void compareWith(Path file) {
        if (shown == null) {
            say.accept("Wait for the page to be drawn, then drop the picture again.");
            return;
        }
        RenderedView ours = shown;
        PageContext context = drawing.get();
        say.accept("Comparing with " + file.getFileName() + " ...");
        compareOffEdt(() -> {
            boolean firstAssignment = PanelGridComparison.holds(file, firstAssignmentPanels());
            if (ours.view() instanceof View.OfAssignment1Page || firstAssignment) {
                // compared here, a page of four panels would be taken for one 650x650 panel with a pixel of
                // slack: an answer that is not compare's, which judges each panel without slack
                String words = firstAssignmentElsewhere(file, firstAssignment, ours, context);
                return () -> say.accept(words);
            }
            Picture picture = Picture.read(file);
            Found found = Found.of(ours, picture);
            return () -> compared(ours, picture, found);
        });
    }

    /** What a comparison made off the EDT does there once it is done. */
    private interface Outcome {
        Runnable made() throws CompareException;
    }

    /**
     * Makes {@code work}'s outcome on the thread the window handed over, then runs it on the EDT; a picture that
     * cannot be compared (unreadable, or failing in the comparison) is said why there instead.
     */
    private void compareOffEdt(Outcome work) {
        offEdt.execute(() -> {
            Runnable outcome;
            try {
                outcome = work.made();
            } catch (CompareException | RuntimeException e) {
                String why = "Cannot compare: " + e.getMessage();
                outcome = () -> say.accept(why);
            }
            SwingUtilities.invokeLater(outcome);
        });
    }

    /** A picture dropped is compared with {@code ours}: it stays with ours's view, shown now if ours is on screen. */
    private void compared(RenderedView ours, Picture picture, Found found) {
        theirs.put(ours.view(), picture);
        // on another view, its own comparison, and what it shows of it, stay as they are
        if (shown.view().equals(ours.view())) {
            showing = Showing.OURS;
            if (shown == ours) {
                show(found);
            } else {
                viewShown(shown); // the same view drawn again meanwhile: compared again
            }
        }
    }

    /**
     * Why a first assignment's picture (or any picture, on its pages) is not compared in the window, and the
     * command that compares it panel by panel as the window would have drawn it: the page its file name names, as
     * check reads names (a1-page3.png, page3.png: page 3), else the first assignment's page on screen, else "N";
     * the window's seed when the page is drawn from it (or may be: "N"), and its rule when it is not SPEC's (the
     * default).
     */
    private static String firstAssignmentElsewhere(Path file, boolean firstAssignment, RenderedView shown,
            PageContext context) {
        String path = file.toString();
        // as a shell takes it: a path of plain characters as it is, any other in single quotes
        String name = path.matches("[A-Za-z0-9_./,:=+-]+") ? path : "'" + path.replace("'", "'\\''") + "'";
        OptionalInt named = SubmissionNames.pageNumber(file.getFileName().toString());
        int number = named.isPresent() && named.getAsInt() <= Assignment1.COUNT ? named.getAsInt()
                : shown.view() instanceof View.OfAssignment1Page a1 ? a1.number() : 0;
        // the window's seed and rule (context), not those of the picture on screen: one of the eight pages that does
        // not use the seed, or any of them, is not drawn again when they change
        boolean seeded = number == 0 || Assignment1.page(number).usesSeed();
        String page = (number == 0 ? "N" : String.valueOf(number)) + (seeded ? " --seed " + context.seed() : "")
                + (context.a1Rule() == A1Rule.SPEC ? "" : " --a1-rule " + context.a1Rule().key());
        String what = firstAssignment ? file.getFileName() + " is a page of the first assignment (four 300x300 "
                + "panels), not a page of one 650x650 panel" : "The first assignment's pages are not compared here";
        return what + ": its panels are compared one by one, without slack, by simpview compare " + name
                + " --assignment 1 --page " + page;
    }

    /** The first assignment's four panels on its page. */
    private static PanelGridComparison.Panel[] firstAssignmentPanels() {
        PanelGridComparison.Panel[] panels = new PanelGridComparison.Panel[A1Layout.PANELS];
        for (int k = 1; k <= A1Layout.PANELS; k++) {
            panels[k - 1] = new PanelGridComparison.Panel(A1Layout.left(k), A1Layout.top(k), A1Layout.PANEL);
        }
        return panels;
    }

    /**
     * The window calls this when a new picture is on screen: a picture dropped on its view is compared with it off
     * the EDT, and shown compared (as ours, theirs or the heat map, as before) when that is done, if it is still on
     * screen and the picture still compared with.
     */
    public void viewShown(RenderedView view) {
        shown = view;
        comparison = null;
        systematic = null;
        look = null;
        Picture picture = theirs.get(view.view());
        if (picture == null) {
            showing = Showing.OURS;
            text = "";
            return;
        }
        compareOffEdt(() -> {
            Found found = Found.of(view, picture);
            return () -> {
                if (shown == view && theirs.get(view.view()) == picture) {
                    show(found);
                }
            };
        });
    }

    private void show(Found found) {
        comparison = found.comparison();
        systematic = found.systematic();
        look = found.look();
        repaint();
    }

    public void flip() {
        if (comparison != null) {
            showing = showing == Showing.THEIRS ? Showing.OURS : Showing.THEIRS;
            repaint();
        }
    }

    public void heat() {
        if (comparison != null) {
            showing = showing == Showing.HEAT ? Showing.OURS : Showing.HEAT;
            repaint();
        }
    }

    public void stop() {
        if (shown != null && theirs.containsKey(shown.view())) {
            theirs.remove(shown.view()); // a comparison still being made for it is not shown
            comparison = null;
            showing = Showing.OURS;
            text = "";
            legend.accept(null);
            pageView.accept(shown.image(), shown.error());
            say.accept("Stopped comparing.");
        }
    }

    /** Asks for a picture to compare with, starting in {@code folder} (the shown scene's, or the pages'). */
    public void choosePicture(Path folder) {
        JFileChooser chooser = new JFileChooser(folder == null ? null : folder.toFile());
        chooser.setDialogTitle("Compare the page with a picture");
        chooser.setFileFilter(new FileNameExtensionFilter("Pictures (*.png, *.jpg, *.gif, *.bmp)", "png", "jpg", "jpeg", "gif", "bmp"));
        int chosen = chooser.showOpenDialog(owner);
        owner.requestFocus(); // the keys back to the page, which no window manager may give it
        if (chosen == JFileChooser.APPROVE_OPTION) {
            compareWith(chooser.getSelectedFile().toPath());
        }
    }

    private void repaint() {
        BufferedImage image = switch (showing) {
            case OURS -> shown.image();
            case THEIRS -> HeatMap.asPage(comparison.theirs());
            case HEAT -> heatPage();
        };
        pageView.accept(image, showing == Showing.OURS ? shown.error() : null);
        legend.accept(showing == Showing.HEAT ? Legend.heatMap(TOLERANCE) : null);
        Shares slack = comparison.withSlack();
        text = String.format("vs %s: identical %s, ≤1/255 %s, ≤8/255 %s (1 px slack)%s · showing %s · B flip · H heat · ⌫ stop",
                theirs.get(shown.view()).name().replaceFirst(".*[/\\\\]", ""), Percent.of(slack.identical()),
                Percent.of(slack.within1()), Percent.of(slack.within8()),
                systematic == null ? look == null ? "" : " · look at x " + look.x() + ", y " + look.y()
                        : " · looks " + systematic.brief(), showing.name().toLowerCase(Locale.ROOT));
        say.accept(text);
    }

    /** The pixel to look at first in a comparison that fails by compare's defaults, or null when it passes. */
    private static WorstPixel lookAt(Comparison comparison) {
        if (comparison.verdictShare(TOLERANCE) * 100 >= ComparisonReport.DEFAULT_MINIMUM) {
            return null;
        }
        List<DiffRegion> largest = DiffRegions.of(comparison, TOLERANCE, 1).largest();
        return largest.isEmpty() ? null : WorstPixel.in(comparison, largest.get(0), TOLERANCE);
    }

    private BufferedImage heatPage() {
        int[] heat = new int[Comparison.N * Comparison.N];
        HeatMap.fill(comparison, TOLERANCE, heat);
        return HeatMap.asPage(heat);
    }

    /** For an inspector: their pixel at page pixel (x, y down from the top-left), or empty when not comparing. */
    public Optional<Integer> theirsAt(int x, int y) {
        int px = x - PageCanvas.MARGIN;
        int py = y - PageCanvas.MARGIN;
        if (comparison == null || px < 0 || py < 0 || px >= Comparison.N || py >= Comparison.N) {
            return Optional.empty();
        }
        return Optional.of(comparison.theirs()[py * Comparison.N + px]);
    }

    public Showing showing() {
        return showing;
    }

    /** The status line while comparing, or "" when not. */
    public String statusText() {
        return text;
    }

    /** The name of the picture compared with, or null when not comparing. */
    public String theirName() {
        return comparison == null ? null : theirs.get(shown.view()).name().replaceFirst(".*[/\\\\]", "");
    }

    public Comparison comparison() {
        return comparison;
    }
}
