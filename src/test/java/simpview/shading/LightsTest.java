package simpview.shading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

class LightsTest {

    @Test
    void lightsAccumulateInOrderPastAnyInitialCapacity() {
        Lights lights = new Lights();
        assertEquals(0, lights.count());
        for (int i = 0; i < 1000; i++) {
            lights.add(i, i + 0.5, -i, i * 1e-3, 2, 3, 1 + i, 0.25);
            assertEquals(i + 1, lights.count());
        }
        for (int i = 0; i < 1000; i++) {
            assertEquals(i, lights.x(i));
            assertEquals(i + 0.5, lights.y(i));
            assertEquals(-i, lights.z(i));
            assertEquals(i * 1e-3, lights.red(i));
            assertEquals(2, lights.green(i));
            assertEquals(3, lights.blue(i));
            assertEquals(1 + i, lights.a(i));
            assertEquals(0.25, lights.b(i));
        }
    }

    @Test
    void aLightMovesAndTheListClears() {
        Lights lights = new Lights();
        lights.add(1, 2, 3, 1, 1, 1, 1, 0);
        lights.moveTo(0, -4, 5, -6);
        assertEquals(-4, lights.x(0));
        assertEquals(5, lights.y(0));
        assertEquals(-6, lights.z(0));
        assertEquals(1, lights.a(0));
        lights.clear();
        assertEquals(0, lights.count());
        assertThrows(IndexOutOfBoundsException.class, () -> lights.x(0));
        assertThrows(IndexOutOfBoundsException.class, () -> lights.moveTo(-1, 0, 0, 0));
    }

    @Test
    void theSurfaceStartsAsSpecSaysAndItsShortFormKeepsKsAndP() {
        Material start = Material.START;
        assertEquals(new Material(1, 1, 1, 0.3, 8), start);
        Material shiny = new Material(0.2, 0.3, 0.4, 0.9, 128);
        assertEquals(new Material(0.5, 0.6, 0.7, 0.9, 128), shiny.withColour(0.5, 0.6, 0.7));
        assertEquals(new Material(0, 0, 1, 0.3, 8), start.withColour(0, 0, 1));
    }
}
