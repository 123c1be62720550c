/**
 * Pictures and how close they are to simpview's own: {@link simpview.compare.Picture} (a page or a capture, its
 * 650x650 panel found), {@link simpview.compare.Comparison} (two panels pixel by pixel, with slack) and
 * {@link simpview.compare.ComparisonReport} (the verdict and the report {@code simpview compare} prints);
 * {@link simpview.compare.PngFiles} writes a page as a PNG. Grading a class: {@link simpview.compare.Rubric},
 * {@link simpview.compare.GradescopeResults}, {@link simpview.compare.JUnitResults},
 * {@link simpview.compare.HtmlReport}.
 */
package simpview.compare;
