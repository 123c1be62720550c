package simpview.compare;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * A relative file path written as a relative URL, for the reports' links and
 * image sources: each segment percent-encoded (its UTF-8 bytes), '/' between
 * them. A picture's name may hold '#' or '?' (which a browser takes for the
 * start of a fragment or a query), '%' (an escape), a space or ')' (the end of
 * a Markdown link's target), or letters outside ASCII.
 */
public final class UrlPath {

    private static final char[] HEX = "0123456789ABCDEF".toCharArray();

    private UrlPath() {
    }

    /** A path whose segments are separated by '/' (as the rows name their diff images), e.g. "diffs/a #2-diff.png". */
    public static String of(String slashed) {
        List<String> encoded = new ArrayList<>();
        for (String segment : slashed.split("/", -1)) {
            encoded.add(segment(segment));
        }
        return String.join("/", encoded);
    }

    /** A relative path of this file system, segment by segment (so a '\' in a Linux name is part of its segment). */
    public static String of(Path relative) {
        List<String> encoded = new ArrayList<>();
        for (Path name : relative) {
            encoded.add(segment(name.toString()));
        }
        return String.join("/", encoded);
    }

    /**
     * One segment: RFC 3986's unreserved characters (letters and digits of ASCII, '-', '.', '_', '~') as they
     * are, every other byte as %XX. Encoding more than a path needs ({@code ':' '&' '=' '(' ...}) is still the same
     * URL, and leaves nothing a Markdown link or an HTML attribute would read otherwise; ".." stays "..".
     */
    static String segment(String name) {
        StringBuilder out = new StringBuilder();
        for (byte b : name.getBytes(StandardCharsets.UTF_8)) {
            int c = b & 0xFF;
            if (c >= 'a' && c <= 'z' || c >= 'A' && c <= 'Z' || c >= '0' && c <= '9' || c == '-' || c == '.'
                    || c == '_' || c == '~') {
                out.append((char) c);
            } else {
                out.append('%').append(HEX[c >> 4]).append(HEX[c & 0xF]);
            }
        }
        return out.toString();
    }
}
