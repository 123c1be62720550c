package simpview.bench;

import static simpview.geometry.Vertex.B;
import static simpview.geometry.Vertex.G;
import static simpview.geometry.Vertex.R;
import static simpview.geometry.Vertex.X;
import static simpview.geometry.Vertex.Y;
import static simpview.geometry.Vertex.Z;

import simpview.geometry.Vertex;
import simpview.pages.A1Layout;
import simpview.pages.A1Lines;
import simpview.pages.A1Polygons;
import simpview.pages.Assignment1;
import simpview.pages.LineTestPage;
import simpview.pages.PageContext;
import simpview.pages.PolygonTestPage;
import simpview.raster.FilledPolygonRenderer;
import simpview.raster.LineRenderer;
import simpview.surface.Colors;
import simpview.surface.Drawable;
import simpview.surface.DrawableDecorator;
import simpview.surface.PageCanvas;
import simpview.surface.Span;

/**
 * The first assignment's pages as they were drawn before they were made fast
 * (issue 23, commit 7b7289a), for {@link Assignment1Pages#drawBefore}: old
 * against new in one run. Frozen copies of what changed, and only that: the
 * antialiased line (a {@code Math.acos} per cap, per pixel; its colour lerped
 * and packed per pixel), its coverage blend (dividing by 255 per channel) and
 * the ghost (a span pixel by pixel). Not used by simpview. Its pixels are
 * simpview's: compared once, pages 1 to 5 with 40 seeds each for 3 to 5
 * (docs/performance-log.md, "The first assignment's pages made fast").
 */
final class A1Before {

    private A1Before() {
    }

    /** Page n drawn the old way. */
    static void draw(int page, PageCanvas canvas, PageContext context) {
        Drawable[] panels = A1Layout.paint(canvas);
        if (page <= 3) {
            LineTestPage test = (LineTestPage) Assignment1.page(page);
            A1Lines set = test.lines(context.seed());
            double[] n = set.numbers();
            for (int k = 1; k <= A1Layout.PANELS; k++) {
                LineRenderer drawer = k == 4 ? new Antialiased() : LineTestPage.drawer(k, context.a1Rule());
                for (int i = 0; i < set.count(); i++) {
                    drawer.drawLine(n, A1Lines.from(i), A1Lines.to(i), panels[k - 1]);
                }
            }
            return;
        }
        boolean ghost = ((PolygonTestPage) Assignment1.page(page)).ghost();
        A1Polygons scenes = new A1Polygons(context.seed(), context.a1Rule());
        FilledPolygonRenderer fill = new FilledPolygonRenderer();
        for (int k = 1; k <= A1Polygons.SCENES; k++) {
            Drawable target = ghost ? new Ghost(panels[k - 1]) : panels[k - 1];
            double[] n = scenes.scene(k);
            for (int i = 0; i < scenes.count(k); i++) {
                fill.drawPolygon(n, A1Polygons.at(i), target);
            }
        }
    }

    /** The old mix: each channel over 255, blended, back to a byte. */
    static int mix(int colour, int old, double c) {
        double keep = 1 - c;
        return Colors.pack(c * Colors.red(colour) / 255.0 + keep * Colors.red(old) / 255.0,
                c * Colors.green(colour) / 255.0 + keep * Colors.green(old) / 255.0,
                c * Colors.blue(colour) / 255.0 + keep * Colors.blue(old) / 255.0);
    }

    static final class Coverage extends DrawableDecorator {
        private double coverage = 1;

        Coverage(Drawable delegate) {
            super(delegate);
        }

        void cover(double c) {
            coverage = c;
        }

        @Override
        public void setPixel(int x, int y, double z, int argb) {
            delegate.setPixel(x, y, z, coverage >= 1 ? argb : mix(argb, delegate.getPixel(x, y), coverage));
        }
    }

    static final class Ghost extends DrawableDecorator {
        private static final int[] AFTER = new int[256];

        static {
            for (int level = 0; level < 256; level++) {
                AFTER[level] = Colors.red(mix(Colors.WHITE, level << 16, 0.14));
            }
        }

        Ghost(Drawable delegate) {
            super(delegate);
        }

        @Override
        public void setPixel(int x, int y, double z, int argb) {
            int old = delegate.getPixel(x, y);
            delegate.setPixel(x, y, z, 0xFF000000 | AFTER[Colors.red(old)] << 16 | AFTER[Colors.green(old)] << 8
                    | AFTER[Colors.blue(old)]);
        }

        @Override
        public void fillSpan(Span span) {
            for (int x = span.x0; x < span.x1; x++) {
                setPixel(x, span.y, span.zAt(x), span.argbAt(x));
            }
        }
    }

    static final class Antialiased implements LineRenderer {
        private static final double RADIUS = Math.sqrt(2) / 2;
        private static final double DISC = Math.PI * RADIUS * RADIUS;
        private static final double REACH = 0.5 + RADIUS;
        private final double[] ends = new double[2 * Vertex.NUMBERS];
        private Drawable wrapped;
        private Coverage blend;

        static double coverage(double distance) {
            double d = Math.abs(distance);
            double c = 1 - (cap(0.5 - d) + cap(0.5 + d)) / DISC;
            return c <= 0 ? 0 : Math.min(c, 1);
        }

        private static double cap(double h) {
            if (h >= RADIUS) {
                return 0;
            }
            if (h <= -RADIUS) {
                return DISC;
            }
            return RADIUS * RADIUS * Math.acos(h / RADIUS) - h * Math.sqrt(RADIUS * RADIUS - h * h);
        }

        @Override
        public void drawLine(Vertex p, Vertex q, Drawable drawable) {
            p.writeTo(ends, 0);
            q.writeTo(ends, Vertex.NUMBERS);
            drawLine(ends, 0, Vertex.NUMBERS, drawable);
        }

        @Override
        public void drawLine(double[] v, int from, int to, Drawable drawable) {
            if (drawable != wrapped) {
                wrapped = drawable;
                blend = new Coverage(drawable);
            }
            Coverage target = blend;
            double ax = Math.floor(v[from + X] + 0.5);
            double ay = Math.floor(v[from + Y] + 0.5);
            double bx = Math.floor(v[to + X] + 0.5);
            double by = Math.floor(v[to + Y] + 0.5);
            double dx = bx - ax;
            double dy = by - ay;
            double length = Math.hypot(dx, dy);
            double ux = length == 0 ? 1 : dx / length;
            double uy = length == 0 ? 0 : dy / length;
            boolean xMajor = Math.abs(dx) >= Math.abs(dy);
            double major0 = xMajor ? Math.min(ax, bx) : Math.min(ay, by);
            double major1 = xMajor ? Math.max(ax, bx) : Math.max(ay, by);
            int majorLimit = xMajor ? drawable.width() : drawable.height();
            int minorLimit = xMajor ? drawable.height() : drawable.width();
            double lo = Math.max(major0 - 2, 0);
            double hi = Math.min(major1 + 2, majorLimit - 1);
            double slope = xMajor ? (dx == 0 ? 0 : dy / dx) : dx / dy;
            double majorA = xMajor ? ax : ay;
            double minorA = xMajor ? ay : ax;
            double minorReach = REACH / Math.abs(xMajor ? ux : uy);
            for (double m = lo; m <= hi; m++) {
                double centre = minorA + (m - majorA) * slope;
                double first = Math.max(Math.ceil(centre - minorReach), 0);
                double last = Math.min(Math.floor(centre + minorReach), minorLimit - 1);
                for (double n = first; n <= last; n++) {
                    double px = xMajor ? m : n;
                    double py = xMajor ? n : m;
                    double ox = px - ax;
                    double oy = py - ay;
                    double s = ox * ux + oy * uy;
                    if (s < -0.5 || s > length + 0.5) {
                        continue;
                    }
                    double distance = ox * uy - oy * ux;
                    if (Math.abs(distance) >= REACH) {
                        continue;
                    }
                    double c = coverage(distance);
                    if (c <= 0) {
                        continue;
                    }
                    double t = length == 0 ? 0 : Math.min(Math.max(s / length, 0), 1);
                    double k = 1 - t;
                    target.cover(c);
                    target.setPixel((int) px, (int) py, k * v[from + Z] + t * v[to + Z], Colors.pack(
                            k * v[from + R] + t * v[to + R], k * v[from + G] + t * v[to + G], k * v[from + B] + t * v[to + B]));
                }
            }
            target.cover(1);
        }
    }
}
