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
 * ({@link FilePlaces}: the including file's folder, then the working
 * directory). Files that cannot be read are passed over here: the drawing
 * reports them properly.
 *
 * @param lit true when the scene is drawn by the lit rules
 * @param reason where the first lit command stands, "pageA.simp:3 camera"; null when depth-cued
 */
public record SceneRules(boolean lit, String reason) {

    public static final SceneRules DEPTH_CUED = new SceneRules(false, null);

    /**
     * Every file the scene in {@code top} can read, what the window watches
     * for a save: itself and, in the order first met, each .simp file it
     * includes and each .obj model its files draw, found as the reader finds
     * them ({@link FilePlaces}). A name found in neither place is listed at
     * both, and one found only in the working directory also at the place
     * that would take it over, so that a file appearing is seen too. Empty
     * when {@code top} does not exist.
     */
    public static List<Path> reached(Path top) {
        return reached(top, Path.of("").toAbsolutePath());
    }

    /** As {@link #reached(Path)}, with {@code workingDir} (absolute) as the working directory. */
    static List<Path> reached(Path top, Path workingDir) {
        WatchList list = new WatchList(workingDir);
        if (!list.add(top)) {
            return List.of();
        }
        list.toScan.add(top);
        while (!list.toScan.isEmpty()) {
            Path file = list.toScan.poll();
            scan(file, (kind, argument) -> list.named(file, kind, argument), false);
        }
        return List.copyOf(list.paths);
    }

    /** Looks through {@code top} and the files it includes for a lit command. */
    public static SceneRules of(Path top) {
        Set<Path> seen = new HashSet<>();
        Set<Named> followed = new HashSet<>();
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
                String reason = scan(file, (kind, argument) -> include(file, kind, argument, followed, toRead), true);
                if (reason != null) {
                    return new SceneRules(true, reason);
                }
            }
        }
        return DEPTH_CUED;
    }

    /** A command that names a file ({@code file}, {@code obj}), met while scanning. */
    private interface Names {
        void named(Kind kind, String argument);
    }

    /**
     * Reads one file's lines; returns where its first lit command is, and
     * hands the commands naming a file to {@code names} (all of them, or with
     * {@code stopAtLit} those before its first lit command).
     */
    private static String scan(Path file, Names names, boolean stopAtLit) {
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
                if (kind == Kind.FILE || kind == Kind.OBJ) {
                    names.named(kind, words.rest());
                }
            }
        } catch (IOException | SecurityException e) {
            return first;
        }
        return first;
    }

    /**
     * Queues the .simp file a {@code file} command of {@code from} leads to,
     * if it is one to read and its name was not followed from that folder
     * before.
     */
    private static void include(Path from, Kind kind, String argument, Set<Named> followed, Deque<Path> toRead) {
        String name = kind == Kind.FILE ? name(argument) : null;
        if (name == null || !followed.add(new Named(from.getParent(), kind, name))) {
            return;
        }
        try {
            Path found = FilePlaces.of(from, name, ".simp").found();
            if (found != null && Files.isRegularFile(found)) {
                toRead.add(found);
            }
        } catch (InvalidPathException | SecurityException e) {
            // the reader reports it
        }
    }

    /**
     * The name a {@code file} or {@code obj} command gives, read as the reader
     * reads it: after at least one blank, a quoted name to its closing quote
     * or a bare one to the next blank; null when there is none.
     */
    static String name(String argument) {
        int end = argument.length();
        while (end > 0 && argument.charAt(end - 1) == '\r') {
            end--;
        }
        int i = 0;
        while (i < end && isBlank(argument.charAt(i))) {
            i++;
        }
        if (i == 0 || i == end) {
            return null;
        }
        int nameEnd;
        int nameStart = i;
        if (argument.charAt(i) == '"') {
            nameStart = i + 1;
            nameEnd = argument.indexOf('"', nameStart);
            if (nameEnd < 0 || nameEnd >= end) {
                return null;
            }
        } else {
            nameEnd = i;
            while (nameEnd < end && !isBlank(argument.charAt(nameEnd))) {
                nameEnd++;
            }
        }
        return nameEnd > nameStart ? argument.substring(nameStart, nameEnd) : null;
    }

    private static boolean isBlank(char c) {
        return c == ' ' || c == '\t';
    }

    /** A name as a command of a file in folder {@code dir} (null for the working directory) gives it. */
    private record Named(Path dir, Kind kind, String name) {
    }

    /** The files to watch, each once, and the .simp files still to look through. */
    private static final class WatchList {
        private final Path workingDir;
        private final Set<Path> keys = new HashSet<>();
        /** The names already followed, with the folder they were named in: scenes name a cube hundreds of times. */
        private final Set<Named> followed = new HashSet<>();
        final List<Path> paths = new ArrayList<>();
        final Deque<Path> toScan = new ArrayDeque<>();

        WatchList(Path workingDir) {
            this.workingDir = workingDir;
        }

        /** Lists {@code file} unless it is already; true when it is new and exists. */
        boolean add(Path file) {
            Path key;
            boolean exists;
            try {
                key = file.toRealPath();
                exists = true;
            } catch (IOException | SecurityException e) {
                key = file.toAbsolutePath().normalize();
                exists = false;
            }
            if (!keys.add(key)) {
                return false;
            }
            paths.add(file);
            return exists;
        }

        /** Lists the file a {@code file} or {@code obj} command of {@code from} names; queues a .simp one. */
        void named(Path from, Kind kind, String argument) {
            String name = name(argument);
            if (name == null || !followed.add(new Named(from.getParent(), kind, name))) {
                return;
            }
            FilePlaces places;
            try {
                places = FilePlaces.of(from, name, kind == Kind.FILE ? ".simp" : ".obj", workingDir);
            } catch (InvalidPathException e) {
                return;
            }
            Path found = places.found();
            if (found == null || !Files.exists(found)) {
                add(places.here());
                add(places.working());
                return;
            }
            if (add(found) && kind == Kind.FILE && Files.isRegularFile(found)) {
                toScan.add(found);
            }
            if (!places.hereIsWorking() && found.equals(places.working())) {
                add(places.here());
            }
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
