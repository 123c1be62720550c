package simpview.window;

import java.awt.event.ActionEvent;
import java.util.function.Consumer;
import java.util.function.Predicate;
import javax.swing.AbstractAction;
import javax.swing.Box;
import javax.swing.InputMap;
import javax.swing.JCheckBoxMenuItem;
import javax.swing.JComponent;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.KeyStroke;
import javax.swing.event.MenuEvent;
import javax.swing.event.MenuListener;

/**
 * The window's keys and menu bar, both made from {@link WindowAction}'s
 * table: each key and each menu entry hands its entry to the window's
 * {@code perform}, and each toggle's tick is what the window's {@code isOn}
 * says as its menu opens. On the EDT.
 */
final class MenusAndKeys {

    private MenusAndKeys() {
    }

    /** Every key of the table on the root pane, whichever component has the keyboard. */
    static void bindKeys(JComponent root, Consumer<WindowAction> perform) {
        InputMap keys = root.getInputMap(JComponent.WHEN_IN_FOCUSED_WINDOW);
        for (WindowAction action : WindowAction.values()) {
            for (KeyStroke stroke : action.strokes()) {
                keys.put(stroke, action);
            }
            root.getActionMap().put(action, new AbstractAction() {
                private static final long serialVersionUID = 1L;

                @Override
                public void actionPerformed(ActionEvent e) {
                    perform.accept(action);
                }
            });
        }
    }

    /**
     * The menu bar, from the same table as the keys: each entry shows its
     * accelerator and does what its key does (the key itself is handled by
     * the root pane's binding, which consumes it, so it acts once); with the
     * legend strip at its right end.
     */
    static JMenuBar menuBar(LegendStrip legendStrip, Predicate<WindowAction> isOn, Consumer<WindowAction> perform) {
        JMenuBar bar = new JMenuBar();
        bar.setName("menu bar");
        JMenu menu = null;
        for (WindowAction action : WindowAction.values()) {
            if (menu == null || !menu.getName().equals(action.menu().name())) {
                menu = new JMenu(action.menu().title());
                menu.setName(action.menu().name());
                menu.setMnemonic(action.menu().mnemonic());
                bar.add(menu);
            }
            if (action.firstOfGroup()) {
                menu.addSeparator();
            }
            JMenuItem item;
            if (action.toggle()) {
                isOn.test(action); // a toggle isOn does not know fails here, as the window opens
                item = new JCheckBoxMenuItem(action.label());
            } else {
                item = new JMenuItem(action.label());
            }
            item.setName(action.name());
            item.setAccelerator(action.accelerator());
            item.addActionListener(e -> perform.accept(action));
            menu.add(item);
        }
        // What an overlay's colours mean, at the bar's right end: it takes no height from the page.
        bar.add(Box.createHorizontalGlue());
        bar.add(legendStrip);
        for (int m = 0; m < bar.getMenuCount(); m++) {
            JMenu shown = bar.getMenu(m);
            if (shown == null) {
                continue;
            }
            shown.addMenuListener(new MenuListener() {
                @Override
                public void menuSelected(MenuEvent e) {
                    tick(shown, isOn);
                }

                @Override
                public void menuDeselected(MenuEvent e) {
                }

                @Override
                public void menuCanceled(MenuEvent e) {
                }
            });
        }
        return bar;
    }

    /** Ticks a menu's toggles that are on, as it opens. */
    private static void tick(JMenu menu, Predicate<WindowAction> isOn) {
        for (int k = 0; k < menu.getItemCount(); k++) {
            if (menu.getItem(k) instanceof JCheckBoxMenuItem toggle) {
                toggle.setSelected(isOn.test(WindowAction.valueOf(toggle.getName())));
            }
        }
    }
}
