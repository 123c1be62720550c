package simpview.geometry;

/** The three coordinate axes, spelled as SIMP spells them. */
public enum Axis { X, Y, Z }
