package simpview.pages;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class PageStepperTest {

    @Test
    void withoutScenesPositionsArePageNumbers() {
        PageStepper s = new PageStepper();
        assertEquals(2, s.next());
        assertEquals(8, s.jump(8));
        assertEquals(1, s.next(), "after 8 comes 1");
        assertEquals(8, s.previous());
        assertEquals(3, s.pageAt(3));
        assertEquals(-1, s.sceneAt(3));
    }

    @Test
    void scenesComeFirstAndTheEightPagesStayReachable() {
        PageStepper s = new PageStepper(3);
        assertEquals(11, s.count());
        assertEquals(0, s.sceneAt(s.current()));
        assertEquals(2, s.next());
        assertEquals(1, s.sceneAt(2));
        assertEquals(4, s.jump(1), "page 1 comes after the three scenes");
        assertEquals(1, s.pageAt(4));
        assertEquals(-1, s.sceneAt(4));
        assertEquals(11, s.last());
        assertEquals(8, s.pageAt(11));
        assertEquals(1, s.next(), "after page 8 comes the first scene");
        assertEquals(11, s.previous());
        assertEquals(5, s.moveTo(5));
        assertEquals(5, s.moveTo(12), "no position 12");
    }
}
