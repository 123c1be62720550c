/**
 * The .obj model reader (SPEC Part 2, ".obj files"): the faces of a model
 * handed, one at a time and in file order, to an {@link
 * simpview.scene.obj.ObjSink}, through one reused {@link
 * simpview.stage.ObjFace} view, so that nothing is allocated per face.
 *
 * <ul>
 * <li>{@link simpview.scene.obj.ObjReader#stream} reads a file in chunks and
 *     hands over each face as its line is read: any number of faces in
 *     bounded memory (only the vertices and normals are kept).</li>
 * <li>{@link simpview.scene.obj.ObjModel} is a parsed file kept in primitive
 *     arrays; {@link simpview.scene.obj.ObjModel#replay} hands over the same
 *     faces again, exactly as streaming did. Immutable, so shareable.</li>
 * <li>{@link simpview.scene.obj.ObjLibrary#draw} is what a scene's
 *     {@code obj} command calls: it replays the kept model while the file's
 *     real path, size and modification time are unchanged, and otherwise
 *     streams the file while recording it, keeping models within a memory
 *     budget (64 MB by default, least recently drawn dropped first). One
 *     library may be shared by several drawing threads.</li>
 * </ul>
 *
 * <p>A sink sees positions already divided by w, colours and normals as
 * written (the caller clamps colours and normalizes normals), the 0-based
 * vertex and normal indices (to do per-vertex work once per vertex), and the
 * face's line. Errors are {@link simpview.scene.SceneException}s with the
 * obj file, line and column; the faces before an error have been handed over.
 * Finding the file (the folder of the scene, then the working directory) is
 * the caller's part.
 *
 * <pre>{@code
 * ObjLibrary models = new ObjLibrary();              // one per window, shared
 * models.draw(objFile, face -> {
 *     for (int k = 0; k < face.size(); k++) {
 *         double x = face.x(k), y = face.y(k), z = face.z(k);
 *         // face.hasColor(k) ? face.r(k) ... : the surface colour
 *         // face.hasNormal(k) ? face.nx(k) ... : the face normal
 *     }
 * });
 * }</pre>
 */
package simpview.scene.obj;

import simpview.stage.ObjFace;
