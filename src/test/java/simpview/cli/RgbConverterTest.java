package simpview.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import picocli.CommandLine.TypeConversionException;
import simpview.surface.Rgb;

public class RgbConverterTest {

    private final RgbConverter converter = new RgbConverter();

    @Test
    void readsThreeChannels() {
        assertEquals(new Rgb(0, 1, 0.5), converter.convert("0,1,0.5"));
        assertEquals(new Rgb(0.25, 0, 1), converter.convert(" .25 , 0 ,1 "));
    }

    @ParameterizedTest
    @ValueSource(strings = {"", "1,2", "1,1,1,1", "red,0,0", "2,0,0", "-0.1,0,0", "NaN,0,0", "0,0,Infinity", "1,,1"})
    void rejectsWhatIsNotAColour(String text) {
        TypeConversionException e = assertThrows(TypeConversionException.class, () -> converter.convert(text));
        assertEquals(true, e.getMessage().contains("r,g,b"), e.getMessage());
    }
}
