package simpview.scene.simp;

import java.util.List;
import java.util.function.Supplier;
import simpview.raster.FragmentSink;
import simpview.shading.FragmentStage;
import simpview.shading.LitState;
import simpview.surface.Drawable;
import simpview.surface.PageCanvas;
import simpview.surface.Rgb;

/**
 * What the inspector's replay ({@code simpview.inspect}) sets into a scene
 * being drawn by {@link ScenePipeline#draw}: the decorators a depth-cued
 * scene draws on (with its probes between them), what the lit rasterizers
 * hand their fragments to (a probe before the fragment stage), and where to
 * ask, while a primitive is drawn, for the include chain and the lit state.
 * Given by {@link SceneMonitor#watch}; without one (null, the default) the
 * pipeline draws as always and none of this costs anything.
 */
public interface DrawingWatch {

    /**
     * The panel a depth-cued scene draws on: the canvas's scissor, z-buffer
     * and depth cue (or, with {@code ownColours}, no cue), in that order,
     * which the watch may build with probes between them.
     */
    Drawable depthCued(PageCanvas canvas, Rgb near, Rgb far, boolean ownColours);

    /** Where the lit rasterizers hand their fragments: something that passes them on to {@code stage}. */
    FragmentSink fragments(FragmentStage stage);

    /**
     * The scene's rules began (once, or a second time when it turns lit and
     * is drawn again): {@code chain} says, while a primitive is drawn, where
     * its command stands with every {@code file} command that led to it (the
     * top file's line first); {@code lit} is the lit state, null for the
     * depth-cued rules.
     */
    void began(Supplier<List<SourcePlace>> chain, LitState lit);
}
