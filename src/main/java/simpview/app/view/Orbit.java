package simpview.app.view;

import simpview.geometry.Axis;
import simpview.geometry.Matrix4;

/**
 * Turning a depth-cued scene with the pointer: a turn about the vertical
 * axis (yaw, from a sideways drag) and then about the horizontal one (pitch,
 * from an up-and-down drag), both through the centre of the view volume,
 * (0, 0, -100). Its matrix is applied to the world before the scene's own
 * CTM, so the depth cue still reads the turned depth; unturned it is null,
 * and the scene is drawn exactly as without an orbit.
 */
public final class Orbit {

    /** Degrees turned per screen pixel dragged. */
    static final double DEGREES_PER_PIXEL = 0.5;
    /** The centre of the view volume, what the world turns about. */
    static final double CENTRE_Z = -100;

    private double yaw;
    private double pitch;

    /** A drag of (dx, dy) screen pixels: right turns the scene's front to the right, down tips it toward the viewer. */
    public void drag(int dx, int dy) {
        yaw = normalise(yaw + dx * DEGREES_PER_PIXEL);
        pitch = Math.max(-90, Math.min(90, pitch + dy * DEGREES_PER_PIXEL));
    }

    public void reset() {
        yaw = 0;
        pitch = 0;
    }

    public boolean turned() {
        return yaw != 0 || pitch != 0;
    }

    public double yaw() {
        return yaw;
    }

    public double pitch() {
        return pitch;
    }

    /** The world's turn, T(0,0,-100) Rx(pitch) Ry(yaw) T(0,0,100), or null when not turned. */
    public Matrix4 matrix() {
        if (!turned()) {
            return null;
        }
        return Matrix4.translation(0, 0, CENTRE_Z)
                .times(Matrix4.rotation(Axis.X, pitch))
                .times(Matrix4.rotation(Axis.Y, yaw))
                .times(Matrix4.translation(0, 0, -CENTRE_Z));
    }

    /** "turned 30° right, 10° down", for the status line. */
    public String describe() {
        return String.format(java.util.Locale.ROOT, "turned %.0f° about y, %.0f° about x (O resets)", yaw, pitch);
    }

    private static double normalise(double degrees) {
        double d = degrees % 360;
        return d > 180 ? d - 360 : d <= -180 ? d + 360 : d;
    }
}
