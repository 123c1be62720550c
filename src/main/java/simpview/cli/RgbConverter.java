package simpview.cli;

import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;
import simpview.surface.Rgb;

/** Reads a colour option written {@code r,g,b}, each channel from 0 to 1 as in SIMP files. */
public final class RgbConverter implements ITypeConverter<Rgb> {

    @Override
    public Rgb convert(String text) {
        String[] parts = text.split(",", -1);
        if (parts.length != 3) {
            throw invalid(text);
        }
        double[] channels = new double[3];
        for (int i = 0; i < 3; i++) {
            channels[i] = channel(parts[i].trim(), text);
        }
        return new Rgb(channels[0], channels[1], channels[2]);
    }

    private static double channel(String part, String whole) {
        double value;
        try {
            value = Double.parseDouble(part);
        } catch (NumberFormatException e) {
            throw invalid(whole);
        }
        // The negated test also turns NaN away.
        if (!(value >= 0 && value <= 1)) {
            throw invalid(whole);
        }
        return value;
    }

    private static TypeConversionException invalid(String text) {
        return new TypeConversionException(
                "'" + text + "' is not a colour: expected r,g,b with each channel from 0 to 1, e.g. 0,1,0.5");
    }
}
