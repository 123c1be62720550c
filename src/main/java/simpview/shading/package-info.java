/**
 * Lighting and fog of lit scenes (SPEC Part 2, "Colour"), in camera space
 * with the eye at the origin. Nothing here allocates per point.
 *
 * <ul>
 * <li>{@link simpview.shading.Lights}: the point lights so far, in command
 * order; {@code add(x, y, z, red, green, blue, a, b)}, {@code count()}. A
 * primitive is lit by the first {@code count()} lights at its command.</li>
 * <li>{@link simpview.shading.Material}: the {@code surface} state (kd, ks, p),
 * {@code Material.START} and the 3-number form {@code withColour}.</li>
 * <li>{@link simpview.shading.Lighting}: the formula. Per primitive
 * {@code prepare(iaR, iaG, iaB, ks, p, lightCount, perspective)}; per point
 * {@code shade(px, py, pz, nx, ny, nz, kdR, kdG, kdB, out, at)} writes the
 * clamped colour to out[at..at+2]. N need not be unit; a zero N gives the
 * ambient term; no channel is ever NaN.</li>
 * <li>{@link simpview.shading.Fog}: {@code depth near far r g b};
 * {@code apply(z, colour, at)} in place on the clamped colour, then
 * {@code simpview.surface.Colors.pack} rounds each channel once.</li>
 * <li>{@link simpview.shading.LitState}: what the commands set (camera, W,
 * ambient, surface, fog, shading mode, lights), read by the geometry stage
 * at each primitive's command.</li>
 * <li>{@link simpview.shading.FragmentStage}: per pixel, in order: depth
 * test, attributes resolved, the phong colour, fog, round(c * 255) written
 * once; a phong pixel where a light is may wait to be lit once, at the
 * picture's end.</li>
 * <li>{@link simpview.shading.LitPoints}: a batch of points waiting to be lit
 * together (a phong span's visible pixels), and
 * {@link simpview.shading.BatchLighting}: {@code Lighting.shade(LitPoints)},
 * each point to the same bits as when lit alone.</li>
 * </ul>
 *
 * Per phong pixel: {@code lighting.shade(...); fog.apply(z, c, 0);
 * pixel = Colors.pack(c[0], c[1], c[2]);}
 */
package simpview.shading;
