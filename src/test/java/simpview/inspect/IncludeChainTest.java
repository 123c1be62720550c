package simpview.inspect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import simpview.scene.simp.SourcePlace;

/** Each write names the whole include chain that led to its command, obj faces included; culled primitives are listed. */
class IncludeChainTest {

    @TempDir
    Path dir;

    @Test
    void threeDeep() throws Exception {
        Files.writeString(dir.resolve("top.simp"), "# top\n\nfile \"mid\"\n");
        Files.writeString(dir.resolve("mid.simp"), "{\nfile leaf\n}\n");
        Files.writeString(dir.resolve("leaf.simp"), "# leaf\nscale 1 1 1\n\npolygon (-50, -50, -10) (50, -50, -10) (0, 50, -10)\n");
        PixelReport report = new PixelInspector().inspect(InspectedScene.of(dir.resolve("top.simp")), 325, 325);
        HistoryEntry owner = report.lastWritten();
        assertNotNull(owner);
        assertEquals(List.of("top.simp:3", "mid.simp:2", "leaf.simp:4"),
                owner.chain().stream().map(SourcePlace::toString).toList());
        assertEquals("top.simp:3 › mid.simp:2 › leaf.simp:4 polygon (-50, -50, -10) (50, -50, -10) (0, 50, -10)",
                report.describe(owner));
    }

    @Test
    void anObjFace() throws Exception {
        Files.writeString(dir.resolve("tri.obj"), "# a triangle\nv -1 -1 -5\nv 1 -1 -5\nv 0 1 -5\nf 1 2 3\n");
        Files.writeString(dir.resolve("scene.simp"), "camera -1 -1 1 1 -1 -100\nambient 1 1 1\nobj \"tri\"\n");
        PixelReport report = new PixelInspector().inspect(InspectedScene.of(dir.resolve("scene.simp")), 325, 300);
        HistoryEntry owner = report.lastWritten();
        assertNotNull(owner);
        assertEquals(List.of("scene.simp:3", "tri.obj:5"), owner.chain().stream().map(SourcePlace::toString).toList());
        assertEquals("scene.simp:3 obj \"tri\" › tri.obj:5 f 1 2 3", report.describe(owner));
    }

    @Test
    void culledPrimitivesAreListed() throws Exception {
        // In front of the near plane (z > 0) wholly: culled, though its projection covers the centre.
        Files.writeString(dir.resolve("cull.simp"), "polygon (-50, -50, 10) (50, -50, 10) (0, 50, 10)\n"
                + "polygon (-50, -50, -10) (50, -50, -10) (0, 50, -10)\n");
        PixelReport report = new PixelInspector().inspect(InspectedScene.of(dir.resolve("cull.simp")), 325, 325);
        assertEquals(2, report.history().size());
        assertEquals(Outcome.CULLED, report.history().get(0).outcome());
        assertEquals(HistoryEntry.NO_NUMBER, report.history().get(0).primitive());
        assertEquals("cull.simp:1", report.history().get(0).chain().get(0).toString());
        assertEquals(Outcome.WRITTEN, report.history().get(1).outcome());
        assertEquals(0, report.history().get(1).primitive());
    }

    @Test
    void scissoredAndDepthFailedWrites() throws Exception {
        // Reaching z = 0 at the top vertex and -240 at the bottom ones: part of it is beyond the far plane.
        Files.writeString(dir.resolve("cut.simp"), "polygon (-90, -90, -240) (90, -90, -240) (0, 90, 0)\n"
                + "polygon (-90, -90, -250) (90, -90, -250) (0, 90, -150)\n"
                + "polygon (-90, 90, -150) (90, 90, -150) (0, -90, -5)\n");
        PixelReport report = new PixelInspector().inspect(InspectedScene.of(dir.resolve("cut.simp")), 325, 40);
        List<HistoryEntry> h = report.history();
        assertEquals(Outcome.SCISSORED, h.get(0).outcome());
        assertEquals(Outcome.SCISSORED, h.get(1).outcome());
        assertEquals(Outcome.WRITTEN, h.get(2).outcome());
        PixelReport upper = new PixelInspector().inspect(InspectedScene.of(dir.resolve("cut.simp")), 325, 500);
        List<HistoryEntry> u = upper.history();
        assertEquals(Outcome.WRITTEN, u.get(0).outcome());
        assertEquals(Outcome.DEPTH_FAILED, u.get(1).outcome(), upper.text(true, false));
        assertEquals(Outcome.DEPTH_FAILED, u.get(2).outcome(), upper.text(true, false));
        assertEquals(0, u.get(2).storedOwner());
        assertEquals(u.get(0).z(), u.get(2).storedDepth(), 0);
    }

    @Test
    void aSceneThatTurnsLitAfterDrawingIsReplayedLitFromTheStart() throws Exception {
        Files.writeString(dir.resolve("late.simp"), "polygon (-50, -50, -10) (50, -50, -10) (0, 50, -10)\n"
                + "ambient 0.5 0.5 0.5\n");
        PixelReport report = new PixelInspector().inspect(InspectedScene.of(dir.resolve("late.simp")), 325, 325);
        assertEquals(true, report.lit());
        assertEquals(1, report.history().size(), report.text(true, false));
        HistoryEntry e = report.history().get(0);
        assertEquals(Outcome.WRITTEN, e.outcome());
        assertEquals(0, e.primitive());
        // Lit with what stood before its command: Ia still (0, 0, 0), no lights, so black (depth-cued it was near white).
        assertEquals(0xFF000000, e.argb());
        assertEquals(0xFF000000, report.argb());
        assertEquals(-10, e.z(), 1e-12);
    }
}
