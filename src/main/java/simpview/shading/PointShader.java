package simpview.shading;

/**
 * Lights one point for phong shading, at every pixel: from its camera-space
 * position P, its normal N (any length; zero gives the ambient term alone) and
 * its kd, the colour clamped to [0, 1], into out[0..3).
 */
public interface PointShader {

    void shade(double px, double py, double pz, double nx, double ny, double nz,
            double kr, double kg, double kb, double[] out);
}
