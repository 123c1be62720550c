package simpview.stage;

import java.util.function.IntConsumer;

/**
 * What a band's drawer does to its own rows once a picture, before it first
 * draws there (its rows of the z-buffer reset, say): at most once a band, on
 * the thread drawing that band; the picture's end prepares the bands no
 * drawer reached, once every band is drawn. A band's flag is touched only by
 * whoever draws that band, in the band queue's order, so it needs no lock.
 */
final class BandPreparation {

    private final boolean[] prepared;
    private final IntConsumer prepare;

    /** For {@code bands} bands; {@code prepare} is given the number of the band to prepare. */
    BandPreparation(int bands, IntConsumer prepare) {
        this.prepared = new boolean[bands];
        this.prepare = prepare;
    }

    /** Band b prepared, if it is not yet. */
    void band(int b) {
        if (!prepared[b]) {
            prepare.accept(b);
            prepared[b] = true;
        }
    }

    /** Every band prepared, those not yet. */
    void everyBand() {
        for (int b = 0; b < prepared.length; b++) {
            band(b);
        }
    }
}
