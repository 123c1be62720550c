package simpview.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

class NearestTest {

    private static final List<String> OPTIONS = List.of("--page", "--all", "--scene", "--out", "--out-dir", "--seed");

    @Test
    void findsTheNearestWithinAFewEdits() {
        assertEquals(Optional.of("--page"), Nearest.to("--pge", OPTIONS));
        assertEquals(Optional.of("--scene"), Nearest.to("--secne", OPTIONS));
        assertEquals(Optional.of("--out-dir"), Nearest.to("--outdir", OPTIONS));
        assertEquals(Optional.of("--seed"), Nearest.to("--SEED", OPTIONS));
    }

    @Test
    void suggestsNothingForAFarOffWord() {
        assertEquals(Optional.empty(), Nearest.to("--frobnicate", OPTIONS));
    }
}
