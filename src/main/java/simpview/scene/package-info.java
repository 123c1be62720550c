/**
 * What the scene readers share: {@link simpview.scene.SceneException}, bad input in a scene (its file, line and
 * column, the line as written and what was expected there: a message complete on its own), and
 * {@link simpview.scene.FileProblem}, why a file could not be read, in words; the looks at files
 * ({@link simpview.scene.FileStamp}, {@link simpview.scene.FileLook}) by which what is made from them is kept
 * while they are unchanged ({@link simpview.scene.KeptFiles}); and a file as it was read
 * ({@link simpview.scene.FileVersion}: its stamp and the {@link simpview.scene.FileChecksum} of the bytes read),
 * what a window holds a save against.
 */
package simpview.scene;
