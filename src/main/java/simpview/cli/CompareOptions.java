package simpview.cli;

import java.util.BitSet;
import java.util.Locale;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;
import simpview.compare.Comparison;
import simpview.compare.Percent;
import simpview.pages.Assignment1;
import simpview.pages.Assignment2;

/** The values {@code simpview compare} reads from its options: tolerances, shares, page ranges. */
public final class CompareOptions {

    private CompareOptions() {
    }

    /** A tolerance in 1/255 steps: {@code 8} or {@code 8/255}, 0 to 255. */
    static final class Tolerance implements ITypeConverter<Integer> {
        @Override
        public Integer convert(String text) {
            String steps = text.trim().endsWith("/255") ? text.trim().substring(0, text.trim().length() - 4) : text.trim();
            try {
                int value = Integer.parseInt(steps.trim());
                if (value >= 0 && value <= 255) {
                    return value;
                }
            } catch (NumberFormatException e) {
                // said below
            }
            throw new TypeConversionException("'" + text + "' is not a tolerance: expected a whole number of 1/255 "
                    + "steps from 0 to 255, e.g. 8 or 8/255");
        }
    }

    /**
     * A share in percent: {@code 99}, {@code 99.5} or {@code 99.5%}, 0 to 100; one between 0 and 1 only with its
     * sign ({@code 0.5%}), since {@code 0.99} is a fraction meant as 99 % ({@link Percent#fractionInstead}).
     */
    static final class Share implements ITypeConverter<Double> {
        @Override
        public Double convert(String text) {
            boolean signed = text.trim().endsWith("%");
            String number = signed ? text.trim().substring(0, text.trim().length() - 1) : text.trim();
            try {
                double value = Double.parseDouble(number.trim());
                String fraction = Percent.fractionInstead(value, "'" + text + "'");
                if (fraction != null && !signed) {
                    throw new TypeConversionException(fraction + " (or " + number.trim() + "% for " + number.trim()
                            + " %)");
                }
                if (value >= 0 && value <= 100) {
                    return value;
                }
            } catch (NumberFormatException e) {
                // said below
            }
            throw new TypeConversionException("'" + text + "' is not a share: expected a percentage from 0 to 100, "
                    + "e.g. 99 or 99.5%");
        }
    }

    /** A FLIP value, 0 to 1: {@code 0.13}. */
    static final class FlipThreshold implements ITypeConverter<Double> {
        @Override
        public Double convert(String text) {
            try {
                double value = Double.parseDouble(text.trim());
                if (value >= 0 && value <= 1) {
                    return value;
                }
            } catch (NumberFormatException e) {
                // said below
            }
            throw new TypeConversionException("'" + text + "' is not a FLIP threshold: expected a value from 0 to 1, "
                    + "e.g. 0.13");
        }
    }

    /** A position deviation in pixels: 0, 1 or 2. */
    static final class Deviation implements ITypeConverter<Integer> {
        @Override
        public Integer convert(String text) {
            String px = text.trim().endsWith("px") ? text.trim().substring(0, text.trim().length() - 2) : text.trim();
            try {
                int value = Integer.parseInt(px.trim());
                if (value >= 0 && value <= Comparison.MAX_DEVIATION) {
                    return value;
                }
            } catch (NumberFormatException e) {
                // said below
            }
            throw new TypeConversionException("'" + text + "' is not a position deviation: expected 0, 1 or 2 (pixels)");
        }
    }

    /** Which pictures of a batch get a diff image: all, failing or none. */
    static final class DiffImagesConverter implements ITypeConverter<CompareBatch.DiffImages> {
        @Override
        public CompareBatch.DiffImages convert(String text) {
            return switch (text.trim().toLowerCase(Locale.ROOT)) {
                case "all" -> CompareBatch.DiffImages.ALL;
                case "failing" -> CompareBatch.DiffImages.FAILING;
                case "none" -> CompareBatch.DiffImages.NONE;
                default -> throw new TypeConversionException("'" + text + "' is not a choice of diff images: expected "
                        + "all, failing or none");
            };
        }
    }

    /** The metric: exact, blur or flip. */
    static final class MetricConverter implements ITypeConverter<Comparison.Metric> {
        @Override
        public Comparison.Metric convert(String text) {
            return switch (text.trim().toLowerCase(Locale.ROOT)) {
                case "exact" -> Comparison.Metric.EXACT;
                case "blur" -> Comparison.Metric.BLUR;
                case "flip" -> Comparison.Metric.FLIP;
                default -> throw new TypeConversionException("'" + text + "' is not a metric: expected exact, blur or flip");
            };
        }
    }

    /** The first assignment's five pages: what --pages is with --assignment 1 when it is not given. */
    static final PageRange FIRST_ASSIGNMENT_PAGES = new PageRangeConverter().convert("1-" + Assignment1.COUNT);

    /** Pages, e.g. {@code 1-8}, {@code 6} or {@code 1,3,6-8}. */
    record PageRange(BitSet pages, String text) {

        boolean contains(int page) {
            return page >= 1 && pages.get(page);
        }

        /** The highest page it names. */
        int last() {
            return pages.length() - 1;
        }

        @Override
        public String toString() {
            return text;
        }
    }

    static final class PageRangeConverter implements ITypeConverter<PageRange> {
        @Override
        public PageRange convert(String text) {
            BitSet pages = new BitSet();
            for (String part : text.split(",", -1)) {
                String[] ends = part.trim().split("-", -1);
                if (ends.length > 2) {
                    throw invalid(text);
                }
                int from = page(ends[0], text);
                int to = ends.length == 2 ? page(ends[1], text) : from;
                if (to < from) {
                    // as a rubric's "match" says it: the range named, and how to write it
                    throw new TypeConversionException(String.format(Locale.ROOT, "'%s' is not a set of pages: the "
                            + "range %d-%d runs backwards, so it fits no page: write it %d-%d", text, from, to, to, from));
                }
                pages.set(from, to + 1);
            }
            return new PageRange(pages, text.trim());
        }

        private static int page(String number, String whole) {
            try {
                int page = Integer.parseInt(number.trim());
                if (page >= 1 && page <= Assignment2.COUNT) {
                    return page;
                }
            } catch (NumberFormatException e) {
                // said below
            }
            throw invalid(whole);
        }

        private static TypeConversionException invalid(String text) {
            return new TypeConversionException(String.format(Locale.ROOT,
                    "'%s' is not a set of pages: expected pages 1 to %d like 1-8, 6 or 1,3,6-8", text, Assignment2.COUNT));
        }
    }
}
