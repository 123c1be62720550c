/**
 * The pages simpview draws, and {@link simpview.pages.PageRenderer}, which draws them: a page of the eight
 * (pages 1 to 3 drawn by the program, 4 to 8 from scene files) or any scene file as a page, on one reused
 * canvas, by the threads it is given. {@link simpview.pages.PageContext} says what a page needs besides its
 * canvas: the seed of the random pages and where their scene files are. {@link simpview.pages.Assignment1}
 * draws the first assignment's five pages, {@link simpview.pages.Assignment2} lists the eight.
 */
package simpview.pages;
