package simpview.window;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Rectangle;
import java.nio.file.Path;
import java.util.Optional;
import javax.swing.JComponent;
import javax.swing.JLabel;
import org.junit.jupiter.api.Test;

/**
 * The status line in a window as narrow as it goes (320 pixels): each line
 * of text, what is being drawn and the bar's words are either whole or cut
 * with their whole text on hovering them; the bar and Cancel keep their room,
 * covered by nothing, and Cancel is clicked where it is seen.
 */
public class NarrowStatusLineWindowTest extends WindowTestCase {

    @Test
    void atThreeHundredTwentyPixelsEveryWordIsShownOrOnHoverAndCancelIsWholeAndClickable() throws Exception {
        driver = WindowDriver.open(new WindowOptions(361, dir, Optional.empty()), StandInDrawers.UNTIL_CANCELLED);
        SimpviewWindow window = driver.window();
        StatusStrip status = window.status();
        driver.onEdt(() -> {
            window.frame().setSize(320, 600);
            window.frame().validate();
        });
        driver.awaitEdt(() -> status.component().getWidth() > 0 && status.component().getWidth() <= 320,
                "the status line laid out at the window's width");
        driver.settle();
        assertEveryLineShownOrWholeOnHover(status);

        Path scene = StandInDrawers.sceneFile(dir, "a-scene-whose-name-is-far-too-long-for-a-narrow-window.simp");
        driver.onEdt(() -> window.openScene(scene));
        driver.awaitEdt(() -> status.showingProgress() && status.progressBar().getString().contains("lines"),
                "the progress bar of the scene being drawn");
        driver.settle();
        driver.onEdt(() -> {
            JLabel working = status.workingLabel();
            Rectangle row = status.cancelButton().getParent().getBounds();
            Rectangle label = working.getBounds();
            Rectangle bar = status.progressBar().getBounds();
            Rectangle cancel = status.cancelButton().getBounds();
            assertTrue(bar.width >= 100, "the bar is " + bar.width + " pixels wide");
            assertTrue(label.x + label.width <= bar.x, "the words " + label + " run into the bar " + bar);
            assertTrue(bar.x + bar.width <= cancel.x, "the bar " + bar + " runs into Cancel " + cancel);
            assertTrue(cancel.x + cancel.width <= row.width, "Cancel " + cancel + " is cut off the row " + row);
            assertEquals(cancel.getSize(), status.cancelButton().getPreferredSize(), "Cancel at its whole size");
            shownOrWholeOnHover(working, "Drawing a-scene-whose-name-is-far-too-long-for-a-narrow-window.simp…");
            String words = status.progressBar().getToolTipText();
            assertTrue(words != null && words.matches("[0-9,]+ lines read.*"), "the bar's words on hover: " + words);
            int room = bar.width - status.progressBar().getInsets().left - status.progressBar().getInsets().right;
            String shown = status.progressBar().getString();
            assertTrue(status.progressBar().getFontMetrics(status.progressBar().getFont()).stringWidth(shown) <= room,
                    "the bar says '" + shown + "' (" + status.progressBar().getFontMetrics(status.progressBar().getFont())
                            .stringWidth(shown) + " pixels) in " + room + " pixels, " + bar + " "
                            + status.progressBar().getInsets());
            return null;
        });

        driver.click(status.cancelButton());
        driver.awaitEdt(() -> !window.busy() && status.messageText().startsWith("Cancelled"), "the drawing cancelled");
        driver.settle();
        assertEveryLineShownOrWholeOnHover(status);
    }

    /** Each line of text at the window's width: whole, or cut with its whole text on hovering it. */
    private void assertEveryLineShownOrWholeOnHover(StatusStrip status) throws Exception {
        driver.onEdt(() -> {
            for (JLabel line : status.textLines()) {
                assertTrue(line.getWidth() > 0, "the line '" + line.getText() + "' is not laid out");
                shownOrWholeOnHover(line, line.getText());
            }
            return null;
        });
    }

    private static void shownOrWholeOnHover(JComponent label, String whole) {
        boolean fits = label.getPreferredSize().width <= label.getWidth();
        assertTrue(fits || whole.equals(label.getToolTipText()), "'" + whole + "' is cut to " + label.getWidth()
                + " pixels and hovering it shows " + label.getToolTipText());
    }
}
