/**
 * The command line ({@link simpview.cli.Main}) and, for calling simpview from Java instead, the public types that
 * do each command's work (README.md's "Using simpview from Java" has examples, which its tests compile and run).
 *
 * <ul>
 * <li>{@code render --page N}: {@link simpview.pages.PageRenderer#render} or
 *     {@link simpview.pages.PageRenderer#renderImage}, with a {@link simpview.pages.PageContext} (the seed, where
 *     the scenes of pages 4 to 8 are; {@link simpview.pages.UnpackedScenes#fromSimpviewJar} gives one whose pages 4
 *     and 5 are drawn from the scenes simpview.jar carries, as the jar's own command line finds them);
 *     {@code render --scene F.simp}:
 *     {@link simpview.pages.PageRenderer#renderScene(java.nio.file.Path)}, lit or depth-cued as the scene's
 *     commands say; {@code render --assignment 1}: {@link simpview.pages.Assignment1#render}.</li>
 * <li>{@code --threads N}: {@link simpview.surface.DrawingThreads#of}, given to the
 *     {@link simpview.pages.PageRenderer} and closed by whoever made it (they are {@link AutoCloseable}); the
 *     picture is the same to the bit at any count.</li>
 * <li>{@code --out F.png}: {@link simpview.compare.PngFiles#write}.</li>
 * <li>{@code compare PICTURE --page N}: {@link simpview.compare.Picture#read} (the panel found),
 *     {@link simpview.compare.Picture#ofPage} for simpview's page,
 *     {@link simpview.compare.Comparison#of(int[], int[])} and {@link simpview.compare.ComparisonReport}, judged by
 *     {@link simpview.compare.Comparison#DEFAULT_TOLERANCE} and
 *     {@link simpview.compare.ComparisonReport#DEFAULT_MINIMUM} unless told otherwise.</li>
 * <li>{@code inspect}: {@link simpview.inspect.PixelInspector} with an {@link simpview.inspect.InspectedScene}
 *     (a scene file, or a page's), its answer a {@link simpview.inspect.PixelReport};
 *     {@code inspect --assignment 1}: {@link simpview.inspect.A1Inspector}.</li>
 * <li>anything else: {@link simpview.cli.Main#run}, in-process, the exit code returned.</li>
 * </ul>
 *
 * A mistake in a scene is a checked {@link simpview.scene.SceneException} saying where (file, line, column, the
 * line and what was expected), a picture that cannot be compared a checked
 * {@link simpview.compare.CompareException} saying why; a page or pixel that does not exist is an
 * {@link IllegalArgumentException}.
 */
package simpview.cli;
