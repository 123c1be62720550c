/**
 * Why a pixel is the colour it is: {@link simpview.inspect.PixelInspector} replays an
 * {@link simpview.inspect.InspectedScene} (a scene file, or the scene of one of pages 4 to 8) for one panel pixel
 * and gives a {@link simpview.inspect.PixelReport}: every write at it, its colour explained term by term, its
 * primitive's vertices, as text or JSON. {@link simpview.inspect.A1Inspector} does the same for a pixel of the
 * first assignment's pages.
 */
package simpview.inspect;
