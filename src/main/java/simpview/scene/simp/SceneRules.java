package simpview.scene.simp;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import simpview.scene.simp.Command.Kind;

/**
 * Which rules a scene is drawn by (SPEC Part 2): it is lit when any .simp
 * file it reads, the top file or any file it includes, holds a command of the
 * lit rules ({@link Kind#lit}); otherwise it is depth-cued. Decided before
 * drawing, by a quick look at the first word of every line of every file the
 * scene can reach: {@code file} names are followed as the reader follows them
 * (the including file's folder, then the working directory). Files that
 * cannot be read are passed over here: the drawing reports them properly.
 *
 * @param lit true when the scene is drawn by the lit rules
 * @param reason where the first lit command stands, "pageA.simp:3 camera"; null when depth-cued
 */
public record SceneRules(boolean lit, String reason) {

    public static final SceneRules DEPTH_CUED = new SceneRules(false, null);

    /**
     * Every .simp file the scene in {@code top} can reach: itself and, in
     * the order first met, each file it includes, as the reader would find
     * them (what the window watches for a save). Files that do not exist yet
     * are left out.
     */
    public static List<Path> reached(Path top) {
        Set<Path> seen = new HashSet<>();
        List<Path> reached = new ArrayList<>();
        Deque<Path> toRead = new ArrayDeque<>();
        toRead.add(top);
        while (!toRead.isEmpty()) {
            Path file = toRead.poll();
            try {
                if (!seen.add(file.toRealPath())) {
                    continue;
                }
            } catch (IOException | SecurityException e) {
                continue;
            }
            reached.add(file);
            scan(file, toRead, false);
        }
        return reached;
    }

    /** Looks through {@code top} and the files it includes for a lit command. */
    public static SceneRules of(Path top) {
        Set<Path> seen = new HashSet<>();
        Deque<Path> toRead = new ArrayDeque<>();
        toRead.add(top);
        while (!toRead.isEmpty()) {
            Path file = toRead.poll();
            Path real;
            try {
                real = file.toRealPath();
            } catch (IOException | SecurityException e) {
                continue;
            }
            if (seen.add(real)) {
                String reason = scan(file, toRead, true);
                if (reason != null) {
                    return new SceneRules(true, reason);
                }
            }
        }
        return DEPTH_CUED;
    }

    /**
     * Reads one file's lines; returns where its first lit command is, and
     * queues the files it includes (all of them, or with {@code stopAtLit}
     * those before its first lit command).
     */
    private static String scan(Path file, Deque<Path> toRead, boolean stopAtLit) {
        String first = null;
        try (InputStream in = Files.newInputStream(file)) {
            LineWords words = new LineWords(in);
            while (words.next()) {
                Kind kind = words.kind();
                if (kind == null) {
                    continue;
                }
                if (kind.lit && first == null) {
                    first = file.getFileName() + ":" + words.line() + " " + kind.spelling;
                    if (stopAtLit) {
                        return first;
                    }
                }
                if (kind == Kind.FILE) {
                    Path included = include(file, words.rest());
                    if (included != null) {
                        toRead.add(included);
                    }
                }
            }
        } catch (IOException | SecurityException e) {
            return first;
        }
        return first;
    }

    /** Where a {@code file} command's argument leads, as the reader looks; null when nowhere. */
    private static Path include(Path from, String argument) {
        String name = argument.trim();
        if (name.startsWith("\"")) {
            int close = name.indexOf('"', 1);
            name = close < 0 ? "" : name.substring(1, close);
        } else {
            int blank = name.indexOf(' ');
            name = blank < 0 ? name : name.substring(0, blank);
        }
        if (name.isEmpty()) {
            return null;
        }
        try {
            Path dir = from.getParent();
            Path here = dir == null ? Path.of(name + ".simp") : dir.resolve(name + ".simp");
            if (Files.isRegularFile(here)) {
                return here;
            }
            Path working = Path.of(name + ".simp").toAbsolutePath();
            return Files.isRegularFile(working) ? working : null;
        } catch (InvalidPathException e) {
            return null;
        }
    }

    /** The first word of each line of a stream, without making a String per line. */
    private static final class LineWords {
        private final InputStream in;
        private final byte[] buffer = new byte[1 << 16];
        private int length;
        private int at;
        private byte[] line = new byte[256];
        private int lineLength;
        private int wordStart;
        private int wordEnd;
        private int lineNumber;

        LineWords(InputStream in) {
            this.in = in;
        }

        /** Reads the next line; false at the end. */
        boolean next() throws IOException {
            lineLength = 0;
            boolean any = false;
            while (true) {
                if (at == length) {
                    length = in.read(buffer);
                    at = 0;
                    if (length <= 0) {
                        length = 0;
                        if (!any) {
                            return false;
                        }
                        break;
                    }
                }
                any = true;
                byte c = buffer[at++];
                if (c == '\n') {
                    break;
                }
                if (lineLength < line.length) {
                    line[lineLength++] = c;
                }
            }
            lineNumber++;
            int i = 0;
            while (i < lineLength && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) {
                i++;
            }
            if (lineNumber == 1 && lineLength - i >= 3 && line[i] == (byte) 0xEF) {
                i += 3; // a UTF-8 byte order mark
            }
            wordStart = i;
            while (i < lineLength && line[i] != ' ' && line[i] != '\t' && line[i] != '(' && line[i] != ','
                    && line[i] != '\r') {
                i++;
            }
            wordEnd = i;
            return true;
        }

        /** The 1-based number of the line last read. */
        int line() {
            return lineNumber;
        }

        /** The command the line starts with, or null (blank, comment, brace, unknown word). */
        Kind kind() {
            return wordEnd > wordStart ? Keywords.kind(line, wordStart, wordEnd) : null;
        }

        /** The rest of the line after the word (at most its first 256 bytes). */
        String rest() {
            return new String(line, wordEnd, lineLength - wordEnd, StandardCharsets.UTF_8);
        }
    }
}
