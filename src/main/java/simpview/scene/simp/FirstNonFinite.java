package simpview.scene.simp;

import simpview.stage.GeometryStage;

/**
 * Where a scene's first primitive stands that its geometry stage did not draw
 * because a vertex came out infinite or NaN ("ovf.simp:3 polygon"), for the
 * scene's warning. Asked after every primitive at the cost of one test; the
 * place is put into words only for the first such primitive.
 */
final class FirstNonFinite {

    private final GeometryStage geometry;
    private String place;

    FirstNonFinite(GeometryStage geometry) {
        this.geometry = geometry;
    }

    /** Whether the primitive just given to the geometry stage is the first it did not draw so. */
    boolean justCounted() {
        return place == null && geometry.nonFiniteCount() > 0;
    }

    /** After a primitive of command {@code kind} ("line") at the files' place: notes it when it is the first. */
    void note(FileStack files, String kind) {
        if (justCounted()) {
            place = files.place() + " " + kind;
        }
    }

    /** Notes the first as {@code where}, put into words by the caller (once {@link #justCounted} said so). */
    void noteAs(String where) {
        place = where;
    }

    /** The place noted, or null while there is none. */
    String place() {
        return place;
    }
}
