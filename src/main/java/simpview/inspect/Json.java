package simpview.inspect;

/** The little JSON and text formatting the inspector's reports need: numbers, strings, arrays. */
final class Json {

    private Json() {
    }

    static void string(StringBuilder out, String s) {
        out.append('"');
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            switch (c) {
                case '"' -> out.append("\\\"");
                case '\\' -> out.append("\\\\");
                case '\n' -> out.append("\\n");
                case '\r' -> out.append("\\r");
                case '\t' -> out.append("\\t");
                default -> {
                    if (c < 0x20) {
                        out.append(String.format("\\u%04x", (int) c));
                    } else {
                        out.append(c);
                    }
                }
            }
        }
        out.append('"');
    }

    /** A finite number as Java prints it (shortest round trip); NaN and infinities, which JSON lacks, as null. */
    static void number(StringBuilder out, double v) {
        if (!Double.isFinite(v)) {
            out.append("null");
        } else if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            out.append((long) v);
        } else {
            out.append(v);
        }
    }

    static void value(StringBuilder out, Object v) {
        if (v == null) {
            out.append("null");
        } else if (v instanceof Double d) {
            number(out, d);
        } else if (v instanceof Integer i) {
            out.append(i);
        } else if (v instanceof Boolean b) {
            out.append(b);
        } else if (v instanceof String s) {
            string(out, s);
        } else if (v instanceof double[] a) {
            out.append('[');
            for (int k = 0; k < a.length; k++) {
                out.append(k == 0 ? "" : ", ");
                number(out, a[k]);
            }
            out.append(']');
        } else if (v instanceof int[] a) {
            out.append('[');
            for (int k = 0; k < a.length; k++) {
                out.append(k == 0 ? "" : ", ").append(a[k]);
            }
            out.append(']');
        } else {
            string(out, String.valueOf(v));
        }
    }

    /** A value for the text report: vectors in parentheses, numbers as Java prints them. */
    static String text(Object v) {
        if (v instanceof double[] a) {
            StringBuilder sb = new StringBuilder("(");
            for (int k = 0; k < a.length; k++) {
                sb.append(k == 0 ? "" : ", ").append(number(a[k]));
            }
            return sb.append(')').toString();
        }
        if (v instanceof int[] a) {
            StringBuilder sb = new StringBuilder("(");
            for (int k = 0; k < a.length; k++) {
                sb.append(k == 0 ? "" : ", ").append(a[k]);
            }
            return sb.append(')').toString();
        }
        if (v instanceof Double d) {
            return number(d);
        }
        return String.valueOf(v);
    }

    static String number(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            return Long.toString((long) v);
        }
        return Double.toString(v);
    }
}
