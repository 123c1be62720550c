package simpview.inspect;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Named values in the order they are explained: numbers, vectors (double[]),
 * byte triples (int[]), words, nested terms and lists of terms. Printed as
 * indented text or as JSON, from the same tree.
 */
public final class Terms {

    private final Map<String, Object> values = new LinkedHashMap<>();

    public Terms put(String name, double value) {
        values.put(name, value);
        return this;
    }

    public Terms put(String name, double... vector) {
        values.put(name, vector.clone());
        return this;
    }

    public Terms put(String name, int... bytes) {
        values.put(name, bytes.clone());
        return this;
    }

    public Terms put(String name, String word) {
        values.put(name, word);
        return this;
    }

    public Terms put(String name, boolean flag) {
        values.put(name, flag);
        return this;
    }

    public Terms put(String name, Terms nested) {
        values.put(name, nested);
        return this;
    }

    public Terms put(String name, List<Terms> list) {
        values.put(name, new ArrayList<>(list));
        return this;
    }

    /** The value of {@code name}: Double, double[], int[], String, Boolean, Terms or List of Terms; null if absent. */
    public Object get(String name) {
        return values.get(name);
    }

    public double number(String name) {
        return (Double) values.get(name);
    }

    public double[] vector(String name) {
        return ((double[]) values.get(name)).clone();
    }

    public int[] bytes(String name) {
        return ((int[]) values.get(name)).clone();
    }

    public Terms terms(String name) {
        return (Terms) values.get(name);
    }

    @SuppressWarnings("unchecked")
    public List<Terms> list(String name) {
        return Collections.unmodifiableList((List<Terms>) values.get(name));
    }

    public Map<String, Object> asMap() {
        return Collections.unmodifiableMap(values);
    }

    /** As indented lines, "name: value", nested terms one level deeper. */
    public void appendText(StringBuilder out, String indent) {
        for (Map.Entry<String, Object> e : values.entrySet()) {
            Object v = e.getValue();
            if (v instanceof Terms t) {
                out.append(indent).append(e.getKey()).append(":\n");
                t.appendText(out, indent + "  ");
            } else if (v instanceof List<?> list) {
                out.append(indent).append(e.getKey()).append(": ").append(list.size()).append('\n');
                int k = 0;
                for (Object item : list) {
                    out.append(indent).append("  [").append(k++).append("]\n");
                    ((Terms) item).appendText(out, indent + "    ");
                }
            } else {
                out.append(indent).append(e.getKey()).append(": ").append(Json.text(v)).append('\n');
            }
        }
    }

    public void appendJson(StringBuilder out) {
        out.append('{');
        boolean first = true;
        for (Map.Entry<String, Object> e : values.entrySet()) {
            if (!first) {
                out.append(", ");
            }
            first = false;
            Json.string(out, e.getKey());
            out.append(": ");
            Object v = e.getValue();
            if (v instanceof Terms t) {
                t.appendJson(out);
            } else if (v instanceof List<?> list) {
                out.append('[');
                for (int k = 0; k < list.size(); k++) {
                    out.append(k == 0 ? "" : ", ");
                    ((Terms) list.get(k)).appendJson(out);
                }
                out.append(']');
            } else {
                Json.value(out, v);
            }
        }
        out.append('}');
    }
}
