package simpview.reference;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * The reference's answer for any scene file, by SPEC's "Which rules a scene
 * is drawn by": lit when any .simp file it reads uses a lit command (drawn
 * by {@link LitReferenceRenderer}), otherwise depth-cued white to black (by
 * {@link ReferenceRenderer}).
 */
final class ReferencePage {

    static final List<String> LIT_COMMANDS =
            List.of("camera", "ambient", "surface", "depth", "light", "obj", "flat", "gouraud", "phong");

    private ReferencePage() {
    }

    static BufferedImage render(Path scene) throws IOException {
        if (isLit(scene)) {
            return LitReferenceRenderer.render(scene);
        }
        ReferenceRenderer depthCued = new ReferenceRenderer(new double[] {1, 1, 1}, new double[] {0, 0, 0});
        depthCued.render(scene);
        RefRaster page = new RefRaster();
        System.arraycopy(depthCued.panel, 0, page.panel, 0, depthCued.panel.length);
        return page.page();
    }

    static boolean isLit(Path scene) throws IOException {
        return usesLitCommand(scene, new HashSet<>());
    }

    private static boolean usesLitCommand(Path file, Set<Path> seen) throws IOException {
        if (!seen.add(file.toAbsolutePath().normalize())) {
            return false;
        }
        for (String raw : Files.readAllLines(file)) {
            String line = raw.strip();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            String word = line.split("[\\s,()]+")[0];
            if (LIT_COMMANDS.contains(word)) {
                return true;
            }
            if (word.equals("file")
                    && usesLitCommand(LitReferenceRenderer.find(file, line.substring(4).strip().replace("\"", ""),
                            ".simp"), seen)) {
                return true;
            }
        }
        return false;
    }
}
