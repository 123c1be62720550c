package simpview.cli;

import java.util.ArrayList;
import java.util.List;

/**
 * One line of arguments split as a POSIX shell would, without expansions:
 * blanks separate words (any number of them), 'single quotes' keep
 * everything inside, "double quotes" keep everything but a backslash before
 * " or \, and a backslash outside quotes keeps the next character. This is
 * how {@code gradle run -PappArgs="..."} reaches simpview whole.
 */
public final class ArgumentLine {

    private ArgumentLine() {
    }

    /**
     * {@code word} as a shell (and {@link #split}) reads it back whole: as it is when it holds only letters, digits
     * and {@code _ . / , : = + -}, else in single quotes, each of its own single quotes written {@code '\''}.
     */
    static String shellWord(String word) {
        boolean plain = word.chars()
                .allMatch(c -> c < 128 && (Character.isLetterOrDigit(c) || "_./,:=+-".indexOf(c) >= 0));
        if (!word.isEmpty() && plain) {
            return word;
        }
        return "'" + word.replace("'", "'\\''") + "'";
    }

    /** @throws IllegalArgumentException naming the quote that is never closed */
    static List<String> split(String line) {
        List<String> words = new ArrayList<>();
        StringBuilder word = new StringBuilder();
        boolean inWord = false;
        int i = 0;
        while (i < line.length()) {
            char c = line.charAt(i);
            if (Character.isWhitespace(c)) {
                if (inWord) {
                    words.add(word.toString());
                    word.setLength(0);
                    inWord = false;
                }
                i++;
                continue;
            }
            inWord = true;
            if (c == '\'') {
                i = single(line, i, word);
            } else if (c == '"') {
                i = doubled(line, i, word);
            } else if (c == '\\' && i + 1 < line.length()) {
                word.append(line.charAt(i + 1));
                i += 2;
            } else {
                word.append(c);
                i++;
            }
        }
        if (inWord) {
            words.add(word.toString());
        }
        return words;
    }

    private static int single(String line, int open, StringBuilder word) {
        int close = line.indexOf('\'', open + 1);
        if (close < 0) {
            throw unclosed('\'', line, open);
        }
        word.append(line, open + 1, close);
        return close + 1;
    }

    private static int doubled(String line, int open, StringBuilder word) {
        for (int i = open + 1; i < line.length(); i++) {
            char c = line.charAt(i);
            if (c == '"') {
                return i + 1;
            }
            if (c == '\\' && i + 1 < line.length() && (line.charAt(i + 1) == '"' || line.charAt(i + 1) == '\\')) {
                i++;
                c = line.charAt(i);
            }
            word.append(c);
        }
        throw unclosed('"', line, open);
    }

    private static IllegalArgumentException unclosed(char quote, String line, int at) {
        return new IllegalArgumentException("the " + quote + " at column " + (at + 1) + " is never closed in: " + line);
    }
}
