package simpview.geometry;

/**
 * The world-space view volume and its mapping onto the 650x650 panel.
 * Parallel projection: x and y map linearly, z is kept only for depth.
 */
public final class ViewVolume {

    public static final double MIN_X = -100;
    public static final double MAX_X = 100;
    public static final double MIN_Y = -100;
    public static final double MAX_Y = 100;
    /** The near plane: nothing with z above it is seen. */
    public static final double NEAR_Z = 0;
    /** The far plane: nothing with z below it is seen. */
    public static final double FAR_Z = -200;

    public static final int PANEL_SIZE = 650;

    private ViewVolume() {
    }

    /** World x or y in [-100, 100] to panel pixels in [0, 650], as SPEC writes it. */
    public static double toPanel(double world) {
        return (world + 100) * PANEL_SIZE / 200;
    }

    /** A world-space vertex in panel space: x and y mapped, z and colour kept. */
    public static Vertex toPanel(Vertex world) {
        return world.withPosition(toPanel(world.x()), toPanel(world.y()), world.z());
    }

    /**
     * 0 at the far plane, 1 at the near plane: how far toward the viewer a depth
     * lies, the weight of the near colour in depth cueing.
     */
    public static double nearness(double z) {
        return (z - FAR_Z) / (NEAR_Z - FAR_Z);
    }
}
