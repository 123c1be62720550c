package simpview.window;

import java.util.Locale;
import simpview.geometry.Axis;
import simpview.geometry.Matrix4;

/**
 * Turning a scene's view with the pointer: a turn about the vertical axis
 * (yaw, from a sideways drag), then about the horizontal one (pitch, from an
 * up-and-down drag), both through a centre, and a move along the line of
 * sight (the wheel with Ctrl or Alt). All of it is in camera space: a
 * depth-cued scene's world turns about the centre of the view volume,
 * (0, 0, -100), before the depth cue, so the cue still reads depth; a lit
 * scene's camera moves about the centre of what its view showed. Unturned
 * the matrix is null, and the scene is drawn exactly as without an orbit.
 */
public final class Orbit {

    /** Degrees turned per screen pixel dragged. */
    static final double DEGREES_PER_PIXEL = 0.5;
    /** Each notch nearer goes this share of the way from the centre to the eye (along z); farther undoes one. */
    static final double NEARER_PER_NOTCH = 0.1;
    /** Notches farther than this are not taken (the scene would be some 67 times as far). */
    static final int FARTHEST = 40;
    /** What a depth-cued scene turns about: the centre of the view volume. Never written: each orbit takes a copy. */
    private static final double[] VIEW_VOLUME_CENTRE = {0, 0, -100};

    private double yaw;
    private double pitch;
    /** Wheel notches nearer (negative: farther). */
    private int nearer;
    private double[] centre = VIEW_VOLUME_CENTRE.clone();

    /**
     * What the turns from now on are about, in camera space; taken only
     * while the view is unturned, so one orbit keeps one centre.
     */
    public void about(double[] xyz) {
        if (!turned()) {
            centre = xyz.clone();
        }
    }

    /** A drag of (dx, dy) screen pixels: right turns the scene's front to the right, down tips it toward the viewer. */
    public void drag(int dx, int dy) {
        yaw = normalise(yaw + dx * DEGREES_PER_PIXEL);
        pitch = Math.max(-90, Math.min(90, pitch + dy * DEGREES_PER_PIXEL));
    }

    /** The wheel's notches, as the wheel gives them: up (negative) moves nearer, down farther. */
    public void wheel(int notches) {
        nearer = Math.max(-FARTHEST, nearer - notches);
    }

    public void reset() {
        yaw = 0;
        pitch = 0;
        nearer = 0;
        centre = VIEW_VOLUME_CENTRE.clone();
    }

    public boolean turned() {
        return yaw != 0 || pitch != 0 || nearer != 0;
    }

    public double yaw() {
        return yaw;
    }

    public double pitch() {
        return pitch;
    }

    /**
     * The view's turn, T(0, 0, d) T(c) Rx(pitch) Ry(yaw) T(-c) for the centre
     * c and the move d toward the eye, or null when not turned.
     */
    public Matrix4 matrix() {
        if (!turned()) {
            return null;
        }
        Matrix4 turn = Matrix4.translation(centre[0], centre[1], centre[2])
                .times(Matrix4.rotation(Axis.X, pitch))
                .times(Matrix4.rotation(Axis.Y, yaw))
                .times(Matrix4.translation(-centre[0], -centre[1], -centre[2]));
        double move = -centre[2] * (1 - Math.pow(1 - NEARER_PER_NOTCH, nearer));
        return move == 0 ? turn : Matrix4.translation(0, 0, move).times(turn);
    }

    /** "turned 30° about y, 10° about x, 2 steps nearer (O resets)", for the status line. */
    public String describe() {
        String distance = nearer == 0 ? "" : String.format(Locale.ROOT, ", %d step%s %s", Math.abs(nearer),
                Math.abs(nearer) == 1 ? "" : "s", nearer > 0 ? "nearer" : "farther");
        return String.format(Locale.ROOT, "turned %.0f° about y, %.0f° about x%s (O resets)", yaw, pitch, distance);
    }

    private static double normalise(double degrees) {
        double d = degrees % 360;
        return d > 180 ? d - 360 : d <= -180 ? d + 360 : d;
    }
}
