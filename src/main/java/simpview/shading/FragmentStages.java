package simpview.shading;

import java.util.ArrayList;
import java.util.List;
import simpview.surface.Drawable;
import simpview.surface.DrawingThreads;
import simpview.surface.ZBuffer;

/**
 * The fragment stages one lit picture draws with (the reading thread's, and
 * one per band when several threads draw it), taken from those its drawing
 * threads kept from their last picture and given back to them at its end
 * ({@link DrawingThreads#keep}). A stage's arrays (its batch, the phong
 * spans it keeps, which grow to a page's thousands) are then made and grown
 * once, not at every picture: a picture on two threads had sixteen bands
 * and seventeen new stages.
 *
 * <p>Each stage handed out is as a new one ({@link FragmentStage#startPicture}),
 * so what a picture draws does not depend on what the stages drew before
 * (only how a stage's one-light short spans wait does, which draws the
 * same: {@link FragmentStage#PIXELS_TO_KEEP_SHORT_SPANS}).
 * Used by the thread that reads the picture's scene, never by two pictures
 * at once: the threads hand what they keep to one picture at a time.
 */
public final class FragmentStages {

    private final DrawingThreads threads;
    private final ZBuffer zbuffer;
    /** Kept stages not yet handed out this picture. */
    private final List<FragmentStage> spare;
    /** Every stage handed out this picture, in the order handed out. */
    private final List<FragmentStage> used = new ArrayList<>();

    private FragmentStages(DrawingThreads threads, ZBuffer zbuffer, List<FragmentStage> spare) {
        this.threads = threads;
        this.zbuffer = zbuffer;
        this.spare = spare;
    }

    /** The stages {@code threads} kept, for a picture depth-tested against {@code zbuffer}. */
    public static FragmentStages keptBy(DrawingThreads threads, ZBuffer zbuffer) {
        List<FragmentStage> kept = threads.takeKept(FragmentStage.class);
        List<FragmentStage> spare = new ArrayList<>();
        if (kept != null) {
            for (FragmentStage s : kept) {
                if (s.drawsOn(zbuffer)) {
                    spare.add(s);
                }
            }
        }
        return new FragmentStages(threads, zbuffer, spare);
    }

    /** A stage for this picture writing to {@code panel}: a kept one made as new, or a new one. */
    public FragmentStage next(Drawable panel) {
        FragmentStage s;
        if (spare.isEmpty()) {
            s = new FragmentStage(zbuffer, panel);
        } else {
            s = spare.remove(0); // in the order handed out last time: each stage's arrays fit the same role
            s.startPicture(zbuffer, panel);
        }
        used.add(s);
        return s;
    }

    /**
     * Gives every stage of this picture back to the threads for the next
     * one: once the picture is drawn and no thread draws with them any more.
     * A second call gives nothing back (and keeps what the first gave).
     */
    public void keep() {
        if (used.isEmpty() && spare.isEmpty()) {
            return;
        }
        List<FragmentStage> all = new ArrayList<>(used.size() + spare.size());
        all.addAll(used);
        all.addAll(spare);
        used.clear();
        spare.clear();
        threads.keep(FragmentStage.class, all);
    }
}
