package simpview.window.instruments;

import simpview.pages.A1Rule;
import java.awt.Container;
import java.awt.Dimension;
import java.awt.Font;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import javax.swing.BorderFactory;
import javax.swing.JComponent;
import javax.swing.JScrollPane;
import javax.swing.JTextArea;
import javax.swing.ScrollPaneConstants;
import javax.swing.SwingUtilities;
import javax.swing.Timer;
import simpview.inspect.A1Inspector;
import simpview.inspect.HistoryEntry;
import simpview.inspect.InspectedScene;
import simpview.inspect.PixelInspector;
import simpview.inspect.PixelReport;
import simpview.scene.SceneException;
import simpview.scene.simp.SceneLibrary;
import simpview.scene.simp.SceneMonitor;
import java.awt.Cursor;
import java.awt.Point;
import java.awt.Toolkit;
import java.awt.datatransfer.StringSelection;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Consumer;
import java.util.function.Supplier;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import simpview.inspect.Overdraw;
import simpview.inspect.SkippedPrimitives;
import simpview.scene.simp.SourcePlace;

/**
 * The inspector's side panel: for the pinned pixel, its whole history, how
 * its colour was made and the vertices of the primitive that drew it, as
 * {@code simpview inspect} prints them. The text wraps and scrolls; nothing
 * is cut off. The replay behind it runs on the panel's own thread
 * ("simpview-inspector"), one at a time; a newer request overtakes an older
 * one: only the newest waiting request is replayed (the pointer's moves do
 * not queue up), and an answer for an older one is dropped. Each part of an
 * include chain in the text ("cube.simp:7") is a link: a click copies the
 * file's whole path and line to the clipboard. Methods other than the
 * worker's run on the EDT.
 */
public final class InspectorPanel {

    /** The panel's width beside the page, where the window is at least twice as wide. */
    public static final int WIDTH = 420;
    /** How long a replay may take before the panel says it is drawing again, in place of the last answer. */
    private static final int WAITING_WORDS_AFTER_MILLIS = 250;

    private final JTextArea text = new JTextArea();
    private final JScrollPane scroll;
    private final ExecutorService worker = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "simpview-inspector");
        t.setDaemon(true);
        return t;
    });
    /** Where the replays' scene files and models come from: the window's, shared with its render thread. */
    private final SceneLibrary library;
    /** The replay's inspector: used on the worker thread only. */
    private final PixelInspector inspector;
    /** Counts requests; an answer for an older one is not shown. */
    private int request;
    private boolean answered = true;
    /** What the panel says of the newest request while its answer is slow to come. */
    private String waitingWords = "";
    /**
     * Shows {@link #waitingWords} {@link #WAITING_WORDS_AFTER_MILLIS} after
     * the newest request, unless it was answered (or a message said) by then;
     * each request starts it again. On the EDT, as Swing's timers run.
     */
    private final Timer slowReplay = new Timer(WAITING_WORDS_AFTER_MILLIS, e -> {
        if (!answered) {
            text.setText(waitingWords);
        }
    });
    /** The newest request waiting for the worker, or null: taken by the worker, set on the EDT. */
    private final AtomicReference<Runnable> waiting = new AtomicReference<>();
    /** The places the text's chains name, by the text's spelling ("cube.simp:7"), for the links. */
    private Map<String, SourcePlace> places = Map.of();
    /** The inspected pixel's owner's chain, whole, for Copy chain; empty when there is none. */
    private List<SourcePlace> ownerChain = List.of();
    /** What a click on a chain's part says (the window's status line). */
    private Consumer<String> toldOfCopy = message -> { };
    /** A part of a chain as the text spells it: a file name, a colon, a line number. */
    private static final Pattern PART = Pattern.compile("[^\\s›()\"]+\\.(simp|obj):\\d+");

    /** A panel whose replays read their files through {@code library} (thread safe: the window's render thread's). */
    public InspectorPanel(SceneLibrary library) {
        this.library = library;
        this.inspector = new PixelInspector(library, SceneMonitor.NONE);
        slowReplay.setRepeats(false);
        text.setEditable(false);
        text.setLineWrap(true);
        text.setWrapStyleWord(true);
        text.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 12));
        text.setBorder(BorderFactory.createEmptyBorder(6, 6, 6, 6));
        text.setName("inspector text");
        // Keys belong to the page (a focused text would take the arrows and Ctrl+C): the mouse still selects.
        text.setFocusable(false);
        text.getAccessibleContext().setAccessibleName("inspector panel");
        text.getAccessibleContext().setAccessibleDescription("the inspected pixel's writes, its colour explained and "
                + "its primitive's vertices");
        scroll = new JScrollPane(text, ScrollPaneConstants.VERTICAL_SCROLLBAR_AS_NEEDED,
                ScrollPaneConstants.HORIZONTAL_SCROLLBAR_NEVER) {
            private static final long serialVersionUID = 1L;

            /** WIDTH, but never more than half the window's: in a narrow window the page beside it keeps the rest. */
            @Override
            public Dimension getPreferredSize() {
                Dimension wanted = super.getPreferredSize();
                Container beside = getParent();
                return beside == null || beside.getWidth() <= 0 ? wanted
                        : new Dimension(Math.min(wanted.width, beside.getWidth() / 2), wanted.height);
            }
        };
        scroll.setPreferredSize(new Dimension(WIDTH, 400));
        scroll.setName("inspector panel");
        scroll.setVisible(false);
        say("Pin a pixel (P) to see every write it received, how its colour was made, and its primitive's vertices.");
        MouseAdapter links = new MouseAdapter() {
            @Override
            public void mouseClicked(MouseEvent e) {
                String part = partAt(e.getPoint());
                if (part != null) {
                    copyPart(part);
                }
            }

            @Override
            public void mouseMoved(MouseEvent e) {
                text.setCursor(Cursor.getPredefinedCursor(partAt(e.getPoint()) != null
                        ? Cursor.HAND_CURSOR : Cursor.TEXT_CURSOR));
            }
        };
        text.addMouseListener(links);
        text.addMouseMotionListener(links);
    }

    /** Where a click on a chain's part is told ("Copied ..."). */
    public void onCopy(Consumer<String> message) {
        toldOfCopy = message;
    }

    /** The chain's part ("cube.simp:7") under a point of the text, or null. */
    String partAt(Point point) {
        int at = text.viewToModel2D(point);
        if (at < 0) {
            return null;
        }
        String all = text.getText();
        int lineStart = all.lastIndexOf('\n', Math.max(0, at - 1)) + 1;
        int lineEnd = all.indexOf('\n', at);
        String line = all.substring(lineStart, lineEnd < 0 ? all.length() : lineEnd);
        Matcher m = PART.matcher(line);
        while (m.find()) {
            if (lineStart + m.start() <= at && at <= lineStart + m.end()) {
                return m.group();
            }
        }
        return null;
    }

    /** Copies a chain's part as its whole path and line ("/.../cube.simp:7"), or as spelt when its file is not known. */
    public String copyPart(String part) {
        SourcePlace place = places.get(part);
        String copied = place == null ? part : place.file().toAbsolutePath() + ":" + place.line();
        Toolkit.getDefaultToolkit().getSystemClipboard()
                .setContents(new StringSelection(copied), null);
        toldOfCopy.accept("Copied " + copied);
        return copied;
    }

    /** The inspected pixel's owner's include chain, whole paths, " › " between the parts; "" when none. */
    public String ownerChainText() {
        StringBuilder chain = new StringBuilder();
        for (SourcePlace place : ownerChain) {
            chain.append(chain.length() == 0 ? "" : " › ").append(place.file().toAbsolutePath()).append(':')
                    .append(place.line());
        }
        return chain.toString();
    }

    public JComponent component() {
        return scroll;
    }

    public boolean isShown() {
        return scroll.isVisible();
    }

    /** Shows or hides the panel; returns whether it is shown now. */
    public boolean toggle() {
        scroll.setVisible(!scroll.isVisible());
        scroll.revalidate();
        return scroll.isVisible();
    }

    /** A message in place of a report (nothing pinned, a page that is not a scene, ...). */
    public void say(String message) {
        request++;
        answered = true;
        places = Map.of();
        ownerChain = List.of();
        text.setText(message);
        text.setCaretPosition(0);
    }

    /**
     * Replays {@code scene} for panel pixel (x, y) and shows the report when
     * it is ready, after {@code before} (the other picture's values while
     * comparing, or null) and {@code note} (or null).
     */
    public void inspect(InspectedScene scene, int x, int y, String note) {
        inspect(scene, x, y, note, null);
    }

    public void inspect(InspectedScene scene, int x, int y, String note, String before) {
        inspect(scene, x, y, note, before, HistoryEntry.NO_NUMBER);
    }

    /**
     * The same, with the vertices of primitive {@code vertices} (0, 1, ...:
     * the one stepped to) instead of the owner's, and a sentence after
     * {@code note} saying so, unless that is NO_NUMBER or the scene has no
     * such primitive.
     */
    public void inspect(InspectedScene scene, int x, int y, String note, String before, int vertices) {
        replay(before, "Replaying the scene for pixel (" + x + ", " + y + ") ...", () -> {
            Map<String, SourcePlace> named = new HashMap<>();
            PixelReport r;
            try {
                // a scene with an error is inspected as far as the error, which the report names
                r = inspector.inspect(scene, x, y, vertices);
            } catch (SceneException e) {
                return new Answer("The scene cannot be read:\n" + e.getMessage(), named, List.of());
            }
            HistoryEntry owner = r.lastWritten();
            for (HistoryEntry entry : r.history()) {
                for (SourcePlace place : entry.chain()) {
                    named.put(place.file().getFileName() + ":" + place.line(), place);
                }
            }
            int table = vertices != HistoryEntry.NO_NUMBER && r.vertices(vertices) != null ? vertices
                    : owner == null ? HistoryEntry.NO_NUMBER : owner.primitive();
            // said only once the scene is known to have it (an empty scene, or one saved shorter, has not)
            String said = table != HistoryEntry.NO_NUMBER && table == vertices
                    ? (note == null ? "" : note + " ") + "The vertices below are primitive " + (vertices + 1)
                            + "'s, the one stepped to."
                    : note;
            return new Answer((said == null ? "" : said + "\n\n") + r.text(true, true, table),
                    named, owner == null ? List.of() : owner.chain());
        });
    }

    /**
     * The same for page pixel (x, y) of the first assignment's page {@code
     * page} drawn with {@code seed} under {@code rule} (page coordinates: x right, y up from the
     * page's bottom-left pixel): its panel drawn again through a one-pixel
     * probe, every write with its coverage, as {@code simpview inspect
     * --assignment 1} prints it.
     */
    public void inspectFirstAssignment(int page, long seed, A1Rule rule, int x, int y, String before) {
        replay(before, "Drawing the panel again for page pixel (" + x + ", " + y + ") ...",
                () -> new Answer(A1Inspector.inspect(page, seed, rule, x, y).text(true, true), Map.of(), List.of()));
    }

    /** A replay's text, the places its chains name, and the owner's chain. */
    private record Answer(String report, Map<String, SourcePlace> named, List<SourcePlace> ownerChain) {
    }

    /**
     * Shows {@code work}'s answer (after {@code before}, or nothing) once the
     * worker has it, unless a newer request came first; until then the last
     * answer stays, and {@code waitingText} takes its place if the answer
     * takes longer than {@link #WAITING_WORDS_AFTER_MILLIS}.
     */
    private void replay(String before, String waitingText, Supplier<Answer> work) {
        int mine = ++request;
        answered = false;
        String heading = before == null ? "" : before + "\n\n";
        // The last answer stays until this one's comes: said at once, the waiting words flashed in the panel at
        // every move of the pointer, most replays taking a few milliseconds. A slow one says it is coming.
        waitingWords = heading + waitingText;
        slowReplay.restart();
        Runnable job = () -> {
            Answer answer;
            try {
                answer = work.get();
            } catch (RuntimeException e) {
                answer = new Answer("Could not replay the scene: " + e, Map.of(), List.of());
            }
            Answer shown = answer;
            SwingUtilities.invokeLater(() -> {
                if (mine == request) {
                    answered = true;
                    places = shown.named();
                    ownerChain = shown.ownerChain();
                    text.setText(heading + shown.report());
                    text.setCaretPosition(0);
                }
            });
        };
        if (waiting.getAndSet(job) == null) {
            worker.submit(() -> {
                Runnable newest = waiting.getAndSet(null);
                if (newest != null) {
                    newest.run();
                }
            });
        }
    }

    /**
     * The overdraw of {@code scene}, counted on the inspector's thread, then
     * given to {@code show} on the EDT (null when the scene has an error).
     */
    public void overdraw(InspectedScene scene, Consumer<Overdraw.Counts> show) {
        onWorker(() -> Overdraw.counts(scene, library), show);
    }

    /**
     * The primitives of {@code scene} culled or clipped away whole, found on
     * the inspector's thread, then given to {@code show} on the EDT (null when
     * the scene has an error).
     */
    public void skipped(InspectedScene scene, Consumer<SkippedPrimitives.Found> show) {
        onWorker(() -> SkippedPrimitives.of(scene, library), show);
    }

    /** A replay of a whole scene for an overlay, run on the inspector's thread. */
    private interface SceneWork<T> {
        T run() throws SceneException;
    }

    /** Runs {@code work} on the inspector's thread and gives its answer (null on an error) to {@code show} on the EDT. */
    private <T> void onWorker(SceneWork<T> work, Consumer<T> show) {
        worker.submit(() -> {
            T answer;
            try {
                answer = work.run();
            } catch (SceneException | RuntimeException e) {
                answer = null;
            }
            T shown = answer;
            SwingUtilities.invokeLater(() -> show.accept(shown));
        });
    }

    /** The text selected in the panel with the mouse, or "" (Ctrl+C copies it). */
    public String selectedText() {
        String selected = text.getSelectedText();
        return selected == null ? "" : selected;
    }

    /** The panel's text, whole (for copying and for tests). */
    public String text() {
        return text.getText();
    }

    /** How many times the panel has been asked to show something: a replay, or words of its own. */
    public int requests() {
        return request;
    }

    /** True when the last request has its answer on screen. */
    public boolean answered() {
        return answered;
    }

    /** The next replays read every file from disk again: the kept ones are dropped on the inspector's thread, before them. */
    public void forgetFiles() {
        worker.submit(library::clear);
    }

    public void shutdown() {
        slowReplay.stop();
        worker.shutdownNow();
    }
}
