package simpview.window;

import java.awt.event.KeyAdapter;
import java.awt.event.KeyEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import javax.swing.JDialog;
import javax.swing.JFrame;
import javax.swing.JOptionPane;
import javax.swing.JTextField;

/**
 * The window's question for a number or two, asked by a key (G: a primitive,
 * Shift+G: a pixel), answered in a one-line field. On the EDT.
 */
final class QuestionAfterKey {

    private QuestionAfterKey() {
    }

    /**
     * Asks for a line of text in a dialog opened by the key {@code key}: the
     * dialog opens on the key's press, and the letter that key types comes
     * after, into the dialog's field; the field lets that first letter go by
     * (an answer here never starts with it). The dialog is {@code owner}'s:
     * Enter answers, Escape cancels, and either gives the keys back to it.
     * Null when cancelled.
     */
    static String ask(JFrame owner, String question, char key) {
        JTextField field = new JTextField(12);
        field.setName("answer");
        field.getAccessibleContext().setAccessibleName(question);
        field.getAccessibleContext().setAccessibleDescription("Enter answers, Escape cancels");
        field.addKeyListener(new KeyAdapter() {
            private boolean first = true;

            @Override
            public void keyTyped(KeyEvent e) {
                if (first && Character.toLowerCase(e.getKeyChar()) == key && field.getText().isEmpty()) {
                    e.consume();
                }
                first = false;
            }
        });
        JOptionPane pane = new JOptionPane(new Object[] {question, field},
                JOptionPane.QUESTION_MESSAGE, JOptionPane.OK_CANCEL_OPTION);
        JDialog dialog = pane.createDialog(owner, "simpview");
        dialog.addWindowFocusListener(new WindowAdapter() {
            @Override
            public void windowGainedFocus(WindowEvent e) {
                field.requestFocusInWindow();
            }
        });
        field.addActionListener(e -> pane.setValue(JOptionPane.OK_OPTION));
        dialog.setVisible(true);
        dialog.dispose();
        // the keys go back to the page, answered or cancelled (with no window manager to give them back, nothing
        // would have them, and every key would do nothing)
        owner.requestFocus();
        Object chosen = pane.getValue();
        return chosen instanceof Integer option && option == JOptionPane.OK_OPTION ? field.getText() : null;
    }
}
