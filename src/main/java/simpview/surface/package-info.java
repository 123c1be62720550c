/**
 * What every stage draws on: {@link simpview.surface.Drawable} and its decorators (scissor, z-buffer, depth cue,
 * panel), and {@link simpview.surface.PageCanvas}, one page's 750x750 image, its panel and its z-buffer. A
 * picture is drawn by the caller's thread alone or, in bands of rows, by {@link simpview.surface.DrawingThreads}
 * (to the same bits at any count), which whoever makes them closes ({@link AutoCloseable}).
 */
package simpview.surface;
