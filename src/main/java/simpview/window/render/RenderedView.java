package simpview.window.render;

import java.awt.image.BufferedImage;
import java.util.List;
import simpview.pages.A1Rule;
import simpview.pages.Assignment1;
import simpview.pages.Assignment2;
import simpview.pages.Page;

/**
 * A finished picture, ready for the screen.
 *
 * @param view what was drawn
 * @param seed the seed it was drawn with
 * @param a1Rule the first assignment's rule it was drawn with (its Bresenham panels and fills)
 * @param image the page, handed off by the canvas, which draws on another image from then on; a window gives a
 *     turning drag's frame back once it shows another ({@link BackgroundRenderer#giveBack}), and a later
 *     picture is drawn on it
 * @param error the scene error's message, or null; the image then holds what was drawn before it
 * @param warnings what the scene reported that is not an error
 * @param facts depths, who drew what, the files read: what the instruments show
 */
public record RenderedView(View view, long seed, A1Rule a1Rule, BufferedImage image, String error, List<String> warnings,
        PageFacts facts) {

    RenderedView(View view, long seed, A1Rule a1Rule, BufferedImage image, String error, List<String> warnings) {
        this(view, seed, a1Rule, image, error, warnings, PageFacts.NONE);
    }

    /** What every window title starts with, before what the window shows. */
    public static final String TITLE_START = "simpview — ";

    /** The window title, e.g. "simpview — page 3/8: Z-buffer — seed 361". */
    public String title() {
        return TITLE_START + shows();
    }

    /** What the picture shows, as the window's title names it after {@link #TITLE_START}: "page 3/8: Z-buffer — seed 361". */
    public String shows() {
        if (view instanceof View.OfPage page) {
            String shows = "page " + page.number() + "/" + Assignment2.COUNT + ": " + Assignment2.page(page.number()).title();
            shows = Assignment2.page(page.number()).usesSeed() ? shows + " — seed " + seed : shows;
            return error == null ? shows : shows + " — error";
        }
        if (view instanceof View.OfAssignment1Page page) {
            Page shownPage = Assignment1.page(page.number());
            String shows = "assignment 1, page " + page.number() + "/" + Assignment1.COUNT + ": "
                    + shownPage.title() + (shownPage.usesSeed() ? " — seed " + seed : "")
                    + (a1Rule == A1Rule.SPEC ? "" : " — " + a1Rule.label());
            return error == null ? shows : shows + " — error";
        }
        String shows = "scene: " + ((View.OfScene) view).file().getFileName();
        return error == null ? shows : shows + " — error";
    }

    /** A file name to offer when saving, e.g. "page3-seed361.png" or "house.png". */
    public String suggestedFileName() {
        if (view instanceof View.OfPage page) {
            return "page" + page.number() + (Assignment2.page(page.number()).usesSeed() ? "-seed" + seed : "") + ".png";
        }
        if (view instanceof View.OfAssignment1Page page) {
            return "a1-page" + page.number() + (Assignment1.page(page.number()).usesSeed() ? "-seed" + seed : "")
                    + (a1Rule == A1Rule.SPEC ? "" : "-" + a1Rule.key()) + ".png";
        }
        String name = ((View.OfScene) view).file().getFileName().toString();
        return name.replaceFirst("\\.simp$", "") + ".png";
    }
}
