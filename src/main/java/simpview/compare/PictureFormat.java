package simpview.compare;

import java.nio.file.Path;
import java.util.Locale;

/**
 * A picture's file format, known by its name's ending or by the bytes it was decoded from, and what it does to a
 * page's colours: the one place that says which of two pictures of a page is the truer copy ({@link OnePerPage},
 * by their names) and what a picture that fails is told of its format ({@code compare} and {@code check} alike,
 * by the format its bytes were decoded as: a JPEG saved as x.png lost its colours all the same, and PNG bytes
 * named x.jpg lost none).
 *
 * <p>The order is how exactly a page saved so keeps the colours it was drawn in: a PNG keeps every one, and it
 * is what simpview asks students to hand in; a BMP keeps them too (24 bits a pixel) but is not what was asked
 * for; a GIF keeps at most 256 colours, so an antialiased or shaded page loses (or is dithered in) the others;
 * a JPEG changes colours near every edge, even at high quality.
 */
public enum PictureFormat {
    PNG("a PNG", true),
    BMP("a BMP", true),
    GIF("a GIF", false),
    JPEG("a JPEG", false),
    /** Any other ending: simpview reads none, so it comes last. */
    OTHER("", false);

    private final String article;
    private final boolean exact;

    PictureFormat(String article, boolean exact) {
        this.article = article;
        this.exact = exact;
    }

    /** The format of a file by its name (or path), whatever the ending's case. */
    public static PictureFormat of(String name) {
        String lower = name.toLowerCase(Locale.ROOT);
        if (lower.endsWith(".png")) {
            return PNG;
        }
        if (lower.endsWith(".bmp")) {
            return BMP;
        }
        if (lower.endsWith(".gif")) {
            return GIF;
        }
        if (lower.endsWith(".jpg") || lower.endsWith(".jpeg")) {
            return JPEG;
        }
        return OTHER;
    }

    /** The format of an ImageIO reader's format name ("png", "JPEG", "gif", "bmp"); OTHER for any other. */
    public static PictureFormat ofFormatName(String formatName) {
        return switch (formatName.toLowerCase(Locale.ROOT)) {
            case "png" -> PNG;
            case "bmp" -> BMP;
            case "gif" -> GIF;
            case "jpeg", "jpg" -> JPEG;
            default -> OTHER;
        };
    }

    /** Whether a picture of this format is a truer copy of a page than one of {@code other}'s. */
    public boolean truerThan(PictureFormat other) {
        return ordinal() < other.ordinal();
    }

    /**
     * Why a picture of this format counts over one of {@code other}'s, a format it is {@link #truerThan}: "a PNG
     * is exact, a JPEG is not".
     */
    public String whyOver(PictureFormat other) {
        if (other == OTHER) {
            return "simpview reads " + article + " and not the other";
        }
        if (exact && other.exact) {
            return article + " is what simpview asks for (" + other.article + " is exact too)";
        }
        if (exact) {
            return article + " is exact, " + other.article + " is not";
        }
        // a GIF over a JPEG: neither is exact, but the GIF loses colours only past 256 of them
        return article + " changes only colours past 256 of them, " + other.article + " changes those near every edge";
    }

    /**
     * What a picture that fails is told of its format: a JPEG's or a GIF's colours are not those it was drawn in,
     * so a right page so saved can fail, and the student would look for the fault in their renderer. "" for a PNG
     * or a BMP. {@code counted}: whether it is the picture of its page that counts; one that does not (a PNG of
     * the page counts over it) is not told to hand in a PNG, which is handed in already.
     */
    public String failingAdvice(boolean counted) {
        String handIn = counted ? "; save it as PNG and hand that in" : "";
        if (this == JPEG) {
            return "JPEG is lossy: saving a page as JPEG changes its colours near every edge, so even a right page "
                    + "can fail" + handIn;
        }
        if (this == GIF) {
            return "GIF holds at most 256 colours: saving a page as GIF changes (or dithers) the others, so even a "
                    + "right page can fail" + handIn;
        }
        return "";
    }

    /**
     * The same of a file, by the format its bytes were decoded as ({@code decoded}; null when it was not read:
     * its name's), and saying so where its name says another: "x.png holds a JPEG picture: JPEG is lossy: ...".
     * A name that says PNG over JPEG bytes is no PNG, and the student who renamed the file would not know why.
     */
    public static String failingAdvice(String file, PictureFormat decoded, boolean counted) {
        PictureFormat named = of(file);
        PictureFormat format = decoded == null ? named : decoded;
        String advice = format.failingAdvice(counted);
        if (advice.isEmpty() || format == named) {
            return advice;
        }
        String name = Path.of(file).getFileName() == null ? file
                : Path.of(file).getFileName().toString();
        return name + " holds " + format.article + " picture: " + advice;
    }
}
