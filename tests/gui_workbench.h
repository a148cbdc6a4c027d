#pragma once
// The main window opened on a lesson, shown and active, for the GUI tests
// that drive it like a student: mouse events with their own clock, and the
// window's controller and balls at hand.

#include "gui_settle.h"
#include "ui/canvas/simulation_controller.h"
#include "ui/window/main_window.h"

#include <QApplication>
#include <QMouseEvent>
#include <QTest>

namespace forcelab::test {

/// A mouse event sent straight to `w`, stamped `afterMs` after the last one
/// (the canvas measures a throw's speed from the stamps, not the wall clock).
inline void sendMouse(QWidget* w, QEvent::Type type, QPointF pos, Qt::MouseButton button, Qt::MouseButtons buttons,
                      Qt::KeyboardModifiers modifiers = Qt::NoModifier, int afterMs = 20)
{
    static quint64 ms = 1000;
    ms += static_cast<quint64>(afterMs);
    QMouseEvent event(type, pos, w->mapToGlobal(pos), button, buttons, modifiers);
    event.setTimestamp(ms);
    QApplication::sendEvent(w, &event);
}

struct Workbench {
    explicit Workbench(const QString& lesson)
        : window(lesson)
    {
        window.resize(1280, 800);
        window.show();
    }
    /// Shown, active and laid out.
    bool ready()
    {
        if (!QTest::qWaitForWindowExposed(&window))
            return false;
        window.activateWindow();
        return QTest::qWaitForWindowActive(&window) && waitForSettledLayout(&window);
    }
    SimulationController* controller() { return window.controller(); }
    const sim::BallState& balls() { return window.controller()->world().balls(); }
    MainWindow window;
};

} // namespace forcelab::test
