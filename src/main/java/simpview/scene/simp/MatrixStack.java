package simpview.scene.simp;

import java.util.Arrays;
import simpview.geometry.Matrix4;

/**
 * The stack that '{' pushes the CTM on and '}' pops it from: an explicit
 * array, so nesting depth costs heap, never Java call stack. Matrices are
 * immutable, so pushing a reference is pushing a copy.
 */
public final class MatrixStack {

    private Matrix4[] items = new Matrix4[16];
    private int size;

    public void push(Matrix4 m) {
        if (size == items.length) {
            items = Arrays.copyOf(items, size * 2);
        }
        items[size++] = m;
    }

    /** The top matrix, removed; call only when not {@link #isEmpty()}. */
    public Matrix4 pop() {
        if (size == 0) {
            throw new IllegalStateException("pop of an empty matrix stack");
        }
        Matrix4 m = items[--size];
        items[size] = null;
        return m;
    }

    public boolean isEmpty() {
        return size == 0;
    }

    public int depth() {
        return size;
    }
}
