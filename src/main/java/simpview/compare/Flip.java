package simpview.compare;

import java.util.Arrays;

/**
 * LDR-FLIP, the perceptual difference of two pictures of the same size as
 * Andersson, Nilsson, Akenine-M&ouml;ller, Oskarsson, &Aring;str&ouml;m and
 * Fairchild describe it ("FLIP: A Difference Evaluator for Alternating
 * Images", Proc. ACM Comput. Graph. Interact. Tech. 3(2), 2020), written
 * here from the paper's description: one value per pixel from 0 (no visible
 * difference when the two are flipped between) to 1.
 *
 * <p>Colour: each picture's sRGB goes to linear RGB and on to YyCxCz (the
 * opponent space that is CIELAB without its cube root, white = RGB 1,1,1).
 * Each of its three channels is filtered by the contrast sensitivity of the
 * eye for that channel at {@code ppd} pixels per degree of visual angle: a
 * sum of Gaussians a&middot;&radic;(&pi;/b)&middot;exp(&minus;&pi;&sup2;x&sup2;/b), x in degrees,
 * with (a, b) = (1, 0.0047) for the achromatic channel, (1, 0.0053) for
 * red-green, and (34.1, 0.04) plus (13.5, 0.025) for blue-yellow, normalised
 * to sum 1 over a square of radius &lceil;3&middot;&radic;(0.04/(2&pi;&sup2;))&middot;ppd&rceil; pixels.
 * Back in linear RGB (clamped to [0, 1]), then CIELAB, the Hunt effect is
 * modelled by scaling a* and b* by 0.01&middot;L*. Two pixels' colour difference is
 * the HyAB distance, |&Delta;L| + &radic;(&Delta;a&sup2; + &Delta;b&sup2;), raised to q<sub>c</sub> = 0.7, and
 * mapped onto [0, 1] by the largest such distance, c<sub>max</sub>, that between
 * pure green and pure blue: linearly onto [0, p<sub>t</sub> = 0.95] below
 * p<sub>c</sub>&middot;c<sub>max</sub> (p<sub>c</sub> = 0.4), and from p<sub>t</sub> to 1 above it.
 *
 * <p>Features: on the achromatic channel of each picture as it is, Y/Y<sub>n</sub>
 * in [0, 1], edges are found with the first derivative of a Gaussian and
 * points with its second, of standard deviation 0.5&middot;0.082&middot;ppd pixels
 * (0.082&deg; is the width of the eye's edge detectors), each kernel with its
 * positive weights summing to 1 and its negative ones to &minus;1. Two pixels'
 * feature difference is (max(|&Vert;edge&Vert; &minus; &Vert;edge'&Vert;|, |&Vert;point&Vert; &minus; &Vert;point'&Vert;|) / &radic;2)<sup>q<sub>f</sub></sup>,
 * q<sub>f</sub> = 0.5, in [0, 1].
 *
 * <p>The FLIP value is the colour difference raised to (1 &minus; feature
 * difference): a feature that differs raises a small colour difference
 * towards 1, while a colour difference where the features agree (another
 * antialiasing of the same edge, its grey levels spread by the filters)
 * stays small. It is symmetric in the two pictures. Pictures' borders are
 * extended by repeating their edge pixels. Float arithmetic, the same on
 * every run.
 */
public final class Flip {

    /**
     * The paper's default viewing: a 0.7 m wide monitor of 3840 pixels across seen from 0.7 m,
     * 0.7 &middot; 3840 / 0.7 &middot; &pi; / 180 = 67.0 pixels per degree.
     */
    public static final double DEFAULT_PPD = 67;

    private static final double QC = 0.7;
    private static final double QF = 0.5;
    private static final double PC = 0.4;
    private static final double PT = 0.95;
    private static final double EDGE_WIDTH = 0.082;
    private static final double B_MAX = 0.04;

    // sRGB's linear RGB to XYZ (D65) and back.
    private static final double[] RGB_TO_XYZ = {
        0.4124564, 0.3575761, 0.1804375,
        0.2126729, 0.7151522, 0.0721750,
        0.0193339, 0.1191920, 0.9503041};
    private static final double[] XYZ_TO_RGB = invert(RGB_TO_XYZ);
    private static final double XN = RGB_TO_XYZ[0] + RGB_TO_XYZ[1] + RGB_TO_XYZ[2];
    private static final double YN = RGB_TO_XYZ[3] + RGB_TO_XYZ[4] + RGB_TO_XYZ[5];
    private static final double ZN = RGB_TO_XYZ[6] + RGB_TO_XYZ[7] + RGB_TO_XYZ[8];

    private static final float[] LINEAR = new float[256];

    static {
        for (int v = 0; v < 256; v++) {
            double c = v / 255.0;
            LINEAR[v] = (float) (c <= 0.04045 ? c / 12.92 : Math.pow((c + 0.055) / 1.055, 2.4));
        }
    }

    private final int width;
    private final int height;
    private final double ppd;
    private final float[][] csf;
    private final int csfRadius;
    private final float[] gauss;
    private final float[] first;
    private final float[] second;
    private final double cmax;

    private Flip(int width, int height, double ppd) {
        this.width = width;
        this.height = height;
        this.ppd = ppd;
        this.csfRadius = (int) Math.ceil(3 * Math.sqrt(B_MAX / (2 * Math.PI * Math.PI)) * ppd);
        this.csf = csfKernels();
        double sigma = 0.5 * EDGE_WIDTH * ppd;
        int r = (int) Math.ceil(3 * sigma);
        this.gauss = new float[2 * r + 1];
        this.first = new float[2 * r + 1];
        this.second = new float[2 * r + 1];
        featureKernels(sigma, r);
        double[] green = huntLab(0, 1, 0);
        double[] blue = huntLab(0, 0, 1);
        this.cmax = Math.pow(hyab(green[0], green[1], green[2], blue[0], blue[1], blue[2]), QC);
    }

    /** The FLIP value of each pixel of two pictures of 0xRRGGBB pixels, row by row from the top, at 67 ppd. */
    public static float[] of(int[] reference, int[] test, int width, int height) {
        return of(reference, test, width, height, DEFAULT_PPD);
    }

    /** The same at {@code ppd} pixels per degree. */
    public static float[] of(int[] reference, int[] test, int width, int height, double ppd) {
        if (reference.length != width * height || test.length != width * height) {
            throw new IllegalArgumentException("both pictures must be " + width + "x" + height);
        }
        if (!(ppd > 0 && ppd < 1000)) {
            throw new IllegalArgumentException("pixels per degree must be above 0, not " + ppd);
        }
        return new Flip(width, height, ppd).compute(reference, test);
    }

    /**
     * The colour part alone of two flat colours (no edges, so no feature difference, and the
     * filters leave a flat colour as it is): what FLIP gives inside a large patch of each.
     */
    public static double flat(int reference, int test) {
        Flip f = new Flip(1, 1, DEFAULT_PPD);
        double[] a = f.huntLabOfSrgb(reference);
        double[] b = f.huntLabOfSrgb(test);
        return f.remap(Math.pow(hyab(a[0], a[1], a[2], b[0], b[1], b[2]), QC));
    }

    private double[] huntLabOfSrgb(int rgb) {
        return huntLab(LINEAR[rgb >> 16 & 0xFF], LINEAR[rgb >> 8 & 0xFF], LINEAR[rgb & 0xFF]);
    }

    private float[] compute(int[] reference, int[] test) {
        int n = width * height;
        float[][] ref = opponent(reference);
        float[][] tst = opponent(test);
        float[] refFeatures = features(ref[3]);
        float[] tstFeatures = features(tst[3]);
        filter(ref);
        filter(tst);
        float[] out = new float[n];
        double[] a = new double[3];
        double[] b = new double[3];
        for (int i = 0; i < n; i++) {
            if (ref[0][i] == tst[0][i] && ref[1][i] == tst[1][i] && ref[2][i] == tst[2][i]) {
                // The same filtered colour: no colour difference, whatever the features (0 to any power is 0).
                continue;
            }
            huntLabOfOpponent(ref[0][i], ref[1][i], ref[2][i], a);
            huntLabOfOpponent(tst[0][i], tst[1][i], tst[2][i], b);
            double colour = remap(Math.pow(hyab(a[0], a[1], a[2], b[0], b[1], b[2]), QC));
            double feature = Math.pow(Math.max(Math.abs(refFeatures[2 * i] - tstFeatures[2 * i]),
                    Math.abs(refFeatures[2 * i + 1] - tstFeatures[2 * i + 1])) / Math.sqrt(2), QF);
            out[i] = (float) (colour == 0 ? 0 : Math.pow(colour, 1 - feature));
            // (colour 0 with feature 1 would be 0 to the 0th power; no colour difference is no difference)
        }
        return out;
    }

    /** The colour difference onto [0, 1]: linear up to pc * cmax (to pt), then compressed towards 1. */
    private double remap(double e) {
        double knee = PC * cmax;
        if (e < knee) {
            return PT / knee * e;
        }
        return Math.min(1, PT + (e - knee) / (cmax - knee) * (1 - PT));
    }

    /** Planes Yy, Cx, Cz, and the achromatic Y/Yn, of a picture's sRGB pixels. */
    private float[][] opponent(int[] rgb) {
        int n = width * height;
        float[] yy = new float[n];
        float[] cx = new float[n];
        float[] cz = new float[n];
        float[] lum = new float[n];
        for (int i = 0; i < n; i++) {
            double r = LINEAR[rgb[i] >> 16 & 0xFF];
            double g = LINEAR[rgb[i] >> 8 & 0xFF];
            double b = LINEAR[rgb[i] & 0xFF];
            double x = (RGB_TO_XYZ[0] * r + RGB_TO_XYZ[1] * g + RGB_TO_XYZ[2] * b) / XN;
            double y = (RGB_TO_XYZ[3] * r + RGB_TO_XYZ[4] * g + RGB_TO_XYZ[5] * b) / YN;
            double z = (RGB_TO_XYZ[6] * r + RGB_TO_XYZ[7] * g + RGB_TO_XYZ[8] * b) / ZN;
            yy[i] = (float) (116 * y - 16);
            cx[i] = (float) (500 * (x - y));
            cz[i] = (float) (200 * (y - z));
            lum[i] = (float) y;
        }
        return new float[][] {yy, cx, cz, lum};
    }

    /** A filtered YyCxCz colour back to linear RGB (clamped), then to CIELAB with the Hunt adjustment. */
    private static void huntLabOfOpponent(float yy, float cx, float cz, double[] lab) {
        double y = (yy + 16) / 116.0;
        double x = cx / 500.0 + y;
        double z = y - cz / 200.0;
        double bigX = x * XN;
        double bigY = y * YN;
        double bigZ = z * ZN;
        double r = clamp(XYZ_TO_RGB[0] * bigX + XYZ_TO_RGB[1] * bigY + XYZ_TO_RGB[2] * bigZ);
        double g = clamp(XYZ_TO_RGB[3] * bigX + XYZ_TO_RGB[4] * bigY + XYZ_TO_RGB[5] * bigZ);
        double b = clamp(XYZ_TO_RGB[6] * bigX + XYZ_TO_RGB[7] * bigY + XYZ_TO_RGB[8] * bigZ);
        huntLab(r, g, b, lab);
    }

    /** Linear RGB to CIELAB (white: RGB 1,1,1), a* and b* scaled by 0.01 L* (the Hunt effect). */
    private static double[] huntLab(double r, double g, double b) {
        double[] lab = new double[3];
        huntLab(r, g, b, lab);
        return lab;
    }

    private static void huntLab(double r, double g, double b, double[] lab) {
        double fx = labF((RGB_TO_XYZ[0] * r + RGB_TO_XYZ[1] * g + RGB_TO_XYZ[2] * b) / XN);
        double fy = labF((RGB_TO_XYZ[3] * r + RGB_TO_XYZ[4] * g + RGB_TO_XYZ[5] * b) / YN);
        double fz = labF((RGB_TO_XYZ[6] * r + RGB_TO_XYZ[7] * g + RGB_TO_XYZ[8] * b) / ZN);
        double l = 116 * fy - 16;
        lab[0] = l;
        lab[1] = 0.01 * l * 500 * (fx - fy);
        lab[2] = 0.01 * l * 200 * (fy - fz);
    }

    private static double labF(double t) {
        double delta = 6.0 / 29;
        return t > delta * delta * delta ? Math.cbrt(t) : t / (3 * delta * delta) + 4.0 / 29;
    }

    private static double hyab(double l1, double a1, double b1, double l2, double a2, double b2) {
        double da = a1 - a2;
        double db = b1 - b2;
        return Math.abs(l1 - l2) + Math.sqrt(da * da + db * db);
    }

    private static double clamp(double v) {
        return v < 0 ? 0 : v > 1 ? 1 : v;
    }

    /**
     * The 1-D factors of the three channels' filters: for each channel, pairs of (weight, kernel) whose
     * separable products, summed, make the 2-D filter, normalised to sum 1.
     */
    private float[][] csfKernels() {
        double[][] terms = {{1, 0.0047}, {1, 0.0053}, {34.1, 0.04, 13.5, 0.025}};
        float[][] out = new float[4][];
        // out[0]: achromatic, out[1]: red-green, out[2] and out[3]: blue-yellow's two terms (weights folded in).
        int r = csfRadius;
        double[] weights = new double[2];
        double[][] kernels = new double[2][];
        for (int channel = 0; channel < 3; channel++) {
            double[] t = terms[channel];
            double total = 0;
            for (int k = 0; k < t.length / 2; k++) {
                double a = t[2 * k];
                double b = t[2 * k + 1];
                double[] e = new double[2 * r + 1];
                double sum = 0;
                for (int i = -r; i <= r; i++) {
                    double x = i / ppd;
                    e[i + r] = Math.exp(-Math.PI * Math.PI * x * x / b);
                    sum += e[i + r];
                }
                for (int i = 0; i < e.length; i++) {
                    e[i] /= sum;
                }
                kernels[k] = e;
                weights[k] = a * Math.sqrt(Math.PI / b) * sum * sum;
                total += weights[k];
            }
            for (int k = 0; k < t.length / 2; k++) {
                // the weight goes into the horizontal factor only: w * e(x) * e(y)
                float[] f = new float[2 * r + 1];
                double w = Math.sqrt(weights[k] / total);
                for (int i = 0; i < f.length; i++) {
                    f[i] = (float) (w * kernels[k][i]);
                }
                out[channel + k] = f;
            }
        }
        return out;
    }

    private void featureKernels(double sigma, int r) {
        double gSum = 0;
        double[] g = new double[2 * r + 1];
        for (int i = -r; i <= r; i++) {
            g[i + r] = Math.exp(-(i * i) / (2 * sigma * sigma));
            gSum += g[i + r];
        }
        double firstPositive = 0;
        double secondPositive = 0;
        double secondNegative = 0;
        double[] d1 = new double[2 * r + 1];
        double[] d2 = new double[2 * r + 1];
        for (int i = -r; i <= r; i++) {
            d1[i + r] = -i * g[i + r];
            d2[i + r] = (i * i / (sigma * sigma) - 1) * g[i + r];
            firstPositive += Math.max(0, d1[i + r]);
            secondPositive += Math.max(0, d2[i + r]);
            secondNegative += Math.min(0, d2[i + r]);
        }
        for (int i = 0; i < g.length; i++) {
            gauss[i] = (float) (g[i] / gSum);
            // d1 is odd: its negative weights mirror its positive ones.
            first[i] = (float) (d1[i] / firstPositive);
            second[i] = (float) (d2[i] > 0 ? d2[i] / secondPositive : -d2[i] / secondNegative);
        }
    }

    /** The three colour planes filtered in place by their channels' contrast sensitivity. */
    private void filter(float[][] planes) {
        int n = width * height;
        float[] across = new float[n];
        float[] sum = new float[n];
        // achromatic and red-green: one separable Gaussian each (its weight is 1 once normalised)
        for (int channel = 0; channel < 2; channel++) {
            rows(planes[channel], across, csf[channel]);
            columns(across, planes[channel], csf[channel]);
        }
        float[] down = new float[n];
        rows(planes[2], across, csf[2]);
        columns(across, sum, csf[2]);
        rows(planes[2], across, csf[3]);
        columns(across, down, csf[3]);
        for (int i = 0; i < n; i++) {
            planes[2][i] = sum[i] + down[i];
        }
    }

    /** Per pixel, the edge and point magnitudes of a luminance plane: out[2i] edge, out[2i + 1] point. */
    private float[] features(float[] lum) {
        int n = width * height;
        float[] g = new float[n];
        float[] d1 = new float[n];
        float[] d2 = new float[n];
        rows(lum, g, gauss);
        rows(lum, d1, first);
        rows(lum, d2, second);
        float[] edgeX = new float[n];
        float[] pointX = new float[n];
        float[] edgeY = new float[n];
        float[] pointY = new float[n];
        columns(d1, edgeX, gauss);
        columns(d2, pointX, gauss);
        columns(g, edgeY, first);
        columns(g, pointY, second);
        float[] out = new float[2 * n];
        for (int i = 0; i < n; i++) {
            out[2 * i] = (float) Math.sqrt(edgeX[i] * edgeX[i] + edgeY[i] * edgeY[i]);
            out[2 * i + 1] = (float) Math.sqrt(pointX[i] * pointX[i] + pointY[i] * pointY[i]);
        }
        return out;
    }

    /** Each row convolved with the kernel (centred), the row's ends repeated outward. */
    private void rows(float[] in, float[] out, float[] kernel) {
        int r = kernel.length / 2;
        float[] padded = new float[width + 2 * r];
        for (int y = 0; y < height; y++) {
            int row = y * width;
            for (int x = -r; x < width + r; x++) {
                padded[x + r] = in[row + Math.max(0, Math.min(width - 1, x))];
            }
            // tap by tap over the whole row: the inner loop is a plain multiply-add the JIT vectorises
            Arrays.fill(out, row, row + width, 0f);
            for (int k = 0; k < kernel.length; k++) {
                float w = kernel[k];
                for (int x = 0; x < width; x++) {
                    out[row + x] += w * padded[x + k];
                }
            }
        }
    }

    /** Each column convolved with the kernel (centred), the top and bottom rows repeated outward. */
    private void columns(float[] in, float[] out, float[] kernel) {
        int r = kernel.length / 2;
        for (int y = 0; y < height; y++) {
            int row = y * width;
            Arrays.fill(out, row, row + width, 0f);
            for (int k = 0; k < kernel.length; k++) {
                int from = Math.max(0, Math.min(height - 1, y + k - r)) * width;
                float w = kernel[k];
                for (int x = 0; x < width; x++) {
                    out[row + x] += w * in[from + x];
                }
            }
        }
    }

    private static double[] invert(double[] m) {
        double a = m[0], b = m[1], c = m[2], d = m[3], e = m[4], f = m[5], g = m[6], h = m[7], i = m[8];
        double det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
        return new double[] {
            (e * i - f * h) / det, (c * h - b * i) / det, (b * f - c * e) / det,
            (f * g - d * i) / det, (a * i - c * g) / det, (c * d - a * f) / det,
            (d * h - e * g) / det, (b * g - a * h) / det, (a * e - b * d) / det};
    }
}
