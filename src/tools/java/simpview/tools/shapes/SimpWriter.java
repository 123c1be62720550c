package simpview.tools.shapes;

/**
 * Builds the text of a SIMP file. Numbers are written with at most five
 * decimals and no exponent, the same on every machine, so regenerating a
 * shape gives the same bytes.
 */
final class SimpWriter {

    private static final double SCALE = 100_000;
    private static final int DECIMALS = 5;

    private final StringBuilder text = new StringBuilder();
    private int indent;

    SimpWriter comment(String line) {
        return line("# " + line);
    }

    SimpWriter blank() {
        text.append('\n');
        return this;
    }

    SimpWriter push() {
        line("{");
        indent++;
        return this;
    }

    SimpWriter pop() {
        indent--;
        return line("}");
    }

    SimpWriter translate(double x, double y, double z) {
        return line("translate " + number(x) + " " + number(y) + " " + number(z));
    }

    SimpWriter scale(double x, double y, double z) {
        return line("scale " + number(x) + " " + number(y) + " " + number(z));
    }

    SimpWriter file(String name) {
        return line("file \"" + name + "\"");
    }

    SimpWriter polygon(double[] a, double[] b, double[] c) {
        return line("polygon " + point(a) + " " + point(b) + " " + point(c));
    }

    private SimpWriter line(String command) {
        text.append("\t".repeat(indent)).append(command).append('\n');
        return this;
    }

    static String point(double[] p) {
        return "(" + number(p[0]) + ", " + number(p[1]) + ", " + number(p[2]) + ")";
    }

    /** v rounded to five decimals, trailing zeros dropped: 0.5, -1, 0.70711. */
    static String number(double v) {
        long q = Math.round(v * SCALE);
        if (q == 0) {
            return "0";
        }
        StringBuilder sb = new StringBuilder(q < 0 ? "-" : "");
        long a = Math.abs(q);
        sb.append(a / (long) SCALE);
        long fraction = a % (long) SCALE;
        if (fraction != 0) {
            String digits = Long.toString(fraction);
            String padded = "0".repeat(DECIMALS - digits.length()) + digits;
            int keep = padded.length();
            while (padded.charAt(keep - 1) == '0') {
                keep--;
            }
            sb.append('.').append(padded, 0, keep);
        }
        return sb.toString();
    }

    @Override
    public String toString() {
        return text.toString();
    }
}
