package simpview.compare;

/**
 * Shares of the panel's pixels, from 0 to 1: identical, within 1/255 and
 * within 8/255 in every channel.
 */
public record Shares(double identical, double within1, double within8) {
}
