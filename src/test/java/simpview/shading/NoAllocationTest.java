package simpview.shading;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import org.junit.jupiter.api.Test;

/** The per-pixel calls allocate nothing: 200,000 shade and fog calls add less than 1 KB to this thread's total. */
class NoAllocationTest {

    @Test
    void shadingAndFoggingAllocateNothing() {
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        Lights lights = new Lights();
        lights.add(0, 0, 0, 1, 1, 1, 1, 0);
        lights.add(-80, 60, -60, 0.8, 0.6, 0.5, 1, 0.01);
        Lighting lighting = new Lighting(lights);
        Fog fog = new Fog(-100, -200, 0, 0, 0);
        double[] c = new double[3];
        double sum = run(lighting, fog, c, 1000); // loads and links everything first
        long before = threads.getThreadAllocatedBytes(Thread.currentThread().getId());
        sum += run(lighting, fog, c, 200_000);
        long allocated = threads.getThreadAllocatedBytes(Thread.currentThread().getId()) - before;
        assertTrue(allocated < 1024, allocated + " bytes allocated");
        assertTrue(sum > 0);
    }

    private static double run(Lighting lighting, Fog fog, double[] c, int calls) {
        double sum = 0;
        for (int i = 0; i < calls; i++) {
            double u = (i % 640) / 320.0 - 1;
            double v = (i / 640 % 640) / 320.0 - 1;
            lighting.prepare(0.1, 0.1, 0.1, 0.8, (i & 1) == 0 ? 8 : 7.5, 2, (i & 2) == 0);
            lighting.shade(50 * u, 50 * v, -125 + 25 * v, 0.3 * u, 0.5, 1.5, 0.5, 0.5 + 0.5 * v, 0.5, c, 0);
            fog.apply(-125 + 25 * v, c, 0);
            sum += c[0] + c[1] + c[2];
        }
        return sum;
    }
}
