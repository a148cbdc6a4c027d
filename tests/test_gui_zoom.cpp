// Zoom, pan and follow, through the real widgets: the wheel zooms about the
// pointer, a drag with the middle button or Ctrl moves the view, the keys and
// the stage bar's View menu zoom and fit, and the camera can follow a ball.
// Each test checks where world points land on the screen, to 1e-9 px, and
// that moving the view never touches the physics.

#include "gui_workbench.h"
#include "ui/canvas/canvas.h"
#include "ui/canvas/simulation_controller.h"
#include "ui/drawing/round_steps.h"
#include "ui/window/main_window.h"

#include <QAction>
#include <QApplication>
#include <QMenu>
#include <QMenuBar>
#include <QMouseEvent>
#include <QTest>
#include <QWheelEvent>

#include <cmath>

using namespace forcelab;
using forcelab::test::sendMouse;

namespace {

void dragWith(QWidget* w, QPointF from, QPointF to, Qt::MouseButton button, Qt::KeyboardModifiers modifiers = {})
{
    sendMouse(w, QEvent::MouseButtonPress, from, button, button, modifiers);
    for (int k = 1; k <= 4; ++k)
        sendMouse(w, QEvent::MouseMove, from + (to - from) * (k / 4.0), Qt::NoButton, button, modifiers);
    sendMouse(w, QEvent::MouseButtonRelease, to, button, Qt::NoButton, modifiers);
}

void wheel(QWidget* w, QPointF at, int angle)
{
    QWheelEvent event(at, w->mapToGlobal(at), QPoint(), QPoint(0, angle), Qt::NoButton, Qt::NoModifier,
                      Qt::NoScrollPhase, false);
    QApplication::sendEvent(w, &event);
}

double distance(const QPointF& a, const QPointF& b)
{
    return std::hypot(a.x() - b.x(), a.y() - b.y());
}

double distance(const sim::Vec2& a, const sim::Vec2& b)
{
    return (a - b).norm();
}

bool sameBalls(const sim::BallState& a, const sim::BallState& b)
{
    return a.size() == b.size() && a.position == b.position && a.velocity == b.velocity;
}

struct Workbench : test::Workbench {
    using test::Workbench::Workbench;
    Canvas* canvas() { return window.canvas(); }
    QAction* action(const char* name) { return window.findChild<QAction*>(QString::fromLatin1(name)); }
    // A frame painted with the camera as it is now.
    bool painted()
    {
        const qint64 before = canvas()->framesPainted();
        canvas()->update();
        return QTest::qWaitFor([&] { return canvas()->framesPainted() > before; });
    }
};

// The view's stage middle in widget px.
QPointF middle(const Canvas* canvas)
{
    return canvas->viewTransform().area().center();
}

} // namespace

class TestGuiZoom : public QObject {
    Q_OBJECT
private slots:
    void wheelZoomsAboutThePointer();
    void keysZoomAndFitTheBox();
    void dragsPanTheViewAndNotTheBalls();
    void fitAllBallsShowsBallsThatLeftTheBox();
    void followKeepsTheMoonInTheMiddle();
    void aZoomedClickSelectsAndDragsInWorldUnits();
    void gridAndScaleBarUseRoundWorldSteps();
    void theStageHasTheSameControls();
    void aNewLessonOpensOnTheWholeBox();
};

// One wheel notch zooms by 1.25; the world point under the pointer stays under it.
void TestGuiZoom::wheelZoomsAboutThePointer()
{
    Workbench w(QStringLiteral("elastic-collisions-in-1d"));
    QVERIFY(w.ready());
    Canvas* canvas = w.canvas();
    const double fitted = canvas->viewTransform().scale();
    const QPointF at = middle(canvas) + QPointF(-170.0, 55.0);
    const sim::Vec2 under = canvas->widgetToWorld(at);
    wheel(canvas, at, 120);
    QCOMPARE(canvas->camera().zoom, Canvas::kZoomStep);
    QVERIFY(std::abs(canvas->viewTransform().scale() / fitted - 1.25) < 1e-12);
    QVERIFY2(distance(canvas->worldToWidget(under), at) < 1e-9, "the point under the pointer moved");
    // Three notches back out in one event (a fast wheel): 1.25 · 1.25⁻³.
    wheel(canvas, at, -360);
    QVERIFY(std::abs(canvas->camera().zoom - std::pow(1.25, -2.0)) < 1e-12);
    QVERIFY(distance(canvas->worldToWidget(under), at) < 1e-9);
    // The picture says it is zoomed: a scale bar of a round length.
    QVERIFY(w.painted());
    QVERIFY(canvas->painter().lastFrame().scaleBarLength > 0.0);
    // The zoom stops at its limits and says so by greying the key's action.
    for (int k = 0; k < 40; ++k)
        wheel(canvas, at, 120);
    QCOMPARE(canvas->camera().zoom, Camera::kMaxZoom);
    QVERIFY(!w.action("zoomInAction")->isEnabled());
    QVERIFY(w.action("zoomOutAction")->isEnabled());
}

void TestGuiZoom::keysZoomAndFitTheBox()
{
    Workbench w(QStringLiteral("elastic-collisions-in-1d"));
    QVERIFY(w.ready());
    Canvas* canvas = w.canvas();
    canvas->setFocus();
    const QRectF fittedBox = canvas->viewTransform().boxRect();
    const sim::Vec2 centre = canvas->widgetToWorld(middle(canvas));
    QTest::keyClick(canvas, Qt::Key_Plus);
    QTRY_COMPARE(canvas->camera().zoom, 1.25);
    QTest::keyClick(canvas, Qt::Key_Equal); // + without Shift on most keyboards
    QTRY_VERIFY(std::abs(canvas->camera().zoom - 1.5625) < 1e-12);
    // The keys zoom about the middle, which stays put.
    QVERIFY(distance(canvas->widgetToWorld(middle(canvas)), centre) < 1e-9);
    QTest::keyClick(canvas, Qt::Key_Minus);
    QTest::keyClick(canvas, Qt::Key_Minus);
    QTest::keyClick(canvas, Qt::Key_Minus);
    QTRY_VERIFY(std::abs(canvas->camera().zoom - 0.8) < 1e-12);
    QVERIFY(canvas->viewTransform().moved());
    QTest::keyClick(canvas, Qt::Key_0);
    QTRY_VERIFY(canvas->camera().fitted());
    QCOMPARE(canvas->viewTransform().boxRect(), fittedBox);
}

// A drag with the middle button, or with Ctrl and the left button, carries
// the world with the pointer; no ball moves, even a ball under the pointer.
void TestGuiZoom::dragsPanTheViewAndNotTheBalls()
{
    Workbench w(QStringLiteral("elastic-collisions-in-1d"));
    QVERIFY(w.ready());
    Canvas* canvas = w.canvas();
    const sim::BallState before = w.balls();
    const QPointF from = middle(canvas) + QPointF(-100, 30);
    const sim::Vec2 grabbed = canvas->widgetToWorld(from);
    const QPointF to = from + QPointF(130, -45);
    dragWith(canvas, from, to, Qt::MiddleButton);
    QVERIFY2(distance(canvas->worldToWidget(grabbed), to) < 1e-9, "the world did not follow the pointer");
    // Ctrl + left drag, starting on a ball: the view moves, the ball does not.
    const QPointF onBall = canvas->worldToWidget(sim::Vec2(w.balls().position.col(1)));
    const sim::Vec2 ball = canvas->widgetToWorld(onBall);
    dragWith(canvas, onBall, onBall + QPointF(-60, 20), Qt::LeftButton, Qt::ControlModifier);
    QVERIFY(distance(canvas->worldToWidget(ball), onBall + QPointF(-60, 20)) < 1e-9);
    QVERIFY(sameBalls(w.balls(), before));
    QCOMPARE(canvas->draggedBall(), -1);
    QCOMPARE(w.controller()->world().pointer().inside, false); // no pointer force was sent while panning
}

// Lesson 27 after 4 s: the red ball is at x = −78.5, out of the box and off
// the screen. "Fit all balls" shows every ball whole, as large as fits.
void TestGuiZoom::fitAllBallsShowsBallsThatLeftTheBox()
{
    Workbench w(QStringLiteral("elastic-collisions-in-1d"));
    QVERIFY(w.ready());
    Canvas* canvas = w.canvas();
    sim::World& world = w.controller()->mutableWorld();
    while (world.time() < 4.0 - 0.5 * world.settings().time.dt)
        world.step();
    w.controller()->notifyBallsChanged();
    const sim::BallState& balls = w.balls();
    int outside = -1;
    for (int i = 0; i < balls.size(); ++i)
        if (balls.position(0, i) < 0.0)
            outside = i;
    QVERIFY2(outside >= 0, "no ball left the box on the left");
    const QRectF shown = canvas->viewTransform().area();
    QVERIFY(!shown.contains(canvas->worldToWidget(sim::Vec2(balls.position.col(outside)))));
    canvas->setFocus();
    QTest::keyClick(canvas, Qt::Key_A);
    QTRY_VERIFY(!canvas->camera().fitted());
    const ViewTransform view = canvas->viewTransform();
    const double margin = canvas->paintOptions().margin;
    double left = 1e300, right = -1e300, top = 1e300, bottom = -1e300;
    for (int i = 0; i < balls.size(); ++i) {
        const QPointF c = view.toWidget(sim::Vec2(balls.position.col(i)));
        const double r = view.toWidget(balls.radius[i]);
        left = std::min(left, c.x() - r);
        right = std::max(right, c.x() + r);
        top = std::min(top, c.y() - r);
        bottom = std::max(bottom, c.y() + r);
    }
    const QRectF room = view.area().adjusted(margin, margin, -margin, -margin);
    QVERIFY(left >= room.left() - 1e-9 && right <= room.right() + 1e-9);
    QVERIFY(top >= room.top() - 1e-9 && bottom <= room.bottom() + 1e-9);
    // As large as fits: the balls span the room's width or its height.
    QVERIFY(std::abs((right - left) - room.width()) < 1e-6 || std::abs((bottom - top) - room.height()) < 1e-6);
}

// Lesson 19: select the Moon, follow it, zoom in; while the lesson runs the
// Moon stays in the middle of the stage.
void TestGuiZoom::followKeepsTheMoonInTheMiddle()
{
    Workbench w(QStringLiteral("two-bodies-in-orbit"));
    QVERIFY(w.ready());
    Canvas* canvas = w.canvas();
    const int moon = w.balls().mass[0] < w.balls().mass[1] ? 0 : 1;
    canvas->setSelectedBall(moon);
    canvas->setFocus();
    QTest::keyClick(canvas, Qt::Key_F);
    QTRY_VERIFY(canvas->isFollowing());
    QVERIFY(w.action("followAction")->isChecked());
    QTest::keyClick(canvas, Qt::Key_Plus);
    QTest::keyClick(canvas, Qt::Key_Plus);
    QTRY_VERIFY(std::abs(canvas->camera().zoom - 1.5625) < 1e-12);
    const sim::Vec2 start = w.balls().position.col(moon);
    w.controller()->play();
    QTRY_VERIFY_WITH_TIMEOUT(distance(sim::Vec2(w.balls().position.col(moon)), start) > 50.0, 20000);
    w.controller()->pause();
    QVERIFY(w.painted());
    const sim::Vec2 now = w.balls().position.col(moon);
    QVERIFY2(distance(canvas->worldToWidget(now), middle(canvas)) < 1e-9, "the Moon is not in the middle");
    // A pan stops following and leaves the view where the Moon was.
    dragWith(canvas, middle(canvas), middle(canvas) + QPointF(40, 0), Qt::MiddleButton);
    QVERIFY(!canvas->isFollowing());
    QVERIFY(!w.action("followAction")->isChecked());
    QVERIFY(distance(canvas->worldToWidget(now), middle(canvas) + QPointF(40, 0)) < 1e-9);
}

// Zoomed in 8 times on a ball: a click picks it, and a drag of 80 px moves it
// 80 / scale world px, as the screen shows.
void TestGuiZoom::aZoomedClickSelectsAndDragsInWorldUnits()
{
    Workbench w(QStringLiteral("elastic-collisions-in-1d"));
    QVERIFY(w.ready());
    Canvas* canvas = w.canvas();
    const int ball = 2;
    const sim::Vec2 start = w.balls().position.col(ball);
    Camera camera;
    camera.zoom = 8.0;
    camera.centre = start;
    canvas->setCamera(camera);
    const double scale = canvas->viewTransform().scale();
    const QPointF at = canvas->worldToWidget(start);
    QVERIFY(distance(at, middle(canvas)) < 1e-9);
    // A press, moves past the drag distance, a pause, a release: a drop.
    const QPointF to = at + QPointF(0, 80);
    sendMouse(canvas, QEvent::MouseButtonPress, at, Qt::LeftButton, Qt::LeftButton);
    QCOMPARE(canvas->selectedBall(), ball);
    for (int k = 1; k <= 4; ++k)
        sendMouse(canvas, QEvent::MouseMove, at + (to - at) * (k / 4.0), Qt::NoButton, Qt::LeftButton);
    for (int k = 0; k < 6; ++k) // longer than the throw window, standing still
        sendMouse(canvas, QEvent::MouseMove, to, Qt::NoButton, Qt::LeftButton);
    sendMouse(canvas, QEvent::MouseButtonRelease, to, Qt::LeftButton, Qt::NoButton);
    const sim::Vec2 end = w.balls().position.col(ball);
    QVERIFY2(std::abs(end.y() - start.y() - 80.0 / scale) < 1e-9, qPrintable(QString::number(end.y() - start.y())));
    QCOMPARE(end.x(), start.x());
}

// The grid's labelled spacing is the smallest round step at least
// kGridLabelPixels apart on screen at every zoom; the scale bar's length is
// drawn at the view's scale.
void TestGuiZoom::gridAndScaleBarUseRoundWorldSteps()
{
    Workbench w(QStringLiteral("elastic-collisions-in-1d"));
    QVERIFY(w.ready());
    Canvas* canvas = w.canvas();
    auto isRound = [](double step) {
        const double mantissa = step / std::pow(10.0, std::floor(std::log10(step) + 1e-12));
        return std::abs(mantissa - 1.0) < 1e-9 || std::abs(mantissa - 2.0) < 1e-9 || std::abs(mantissa - 5.0) < 1e-9;
    };
    auto previousRound = [](double step) { // the round step below
        const double mantissa = step / std::pow(10.0, std::floor(std::log10(step) + 1e-12));
        return std::abs(mantissa - 5.0) < 1e-9 ? step * 0.4 : step / 2.0; // 5 → 2, 2 → 1, 1 → 0.5
    };
    for (double zoom : {0.05, 0.3, 1.0, 7.0, 300.0}) {
        Camera camera;
        camera.zoom = zoom;
        camera.centre = sim::Vec2(200.0, 150.0); // the box's inside stays on screen at every zoom
        canvas->setCamera(camera);
        QVERIFY(w.painted());
        const double scale = canvas->viewTransform().scale();
        const PaintedFrame& frame = canvas->painter().lastFrame();
        const double step = frame.gridStep;
        QVERIFY2(step > 0.0 && isRound(step), qPrintable(QString::number(step)));
        QVERIFY(step * scale >= WorldPainter::kGridLabelPixels * (1 - 1e-12));
        QVERIFY(previousRound(step) * scale < WorldPainter::kGridLabelPixels);
        QVERIFY(isRound(frame.scaleBarLength));
        QVERIFY(std::abs(frame.scaleBar.length() - frame.scaleBarLength * scale) < 1e-9);
        QVERIFY(frame.scaleBar.length() >= WorldPainter::kScaleBarPixels * (1 - 1e-12));
    }
    // At the fitted view there is no scale bar: the grid says it all.
    canvas->fitBox();
    QVERIFY(w.painted());
    QCOMPARE(canvas->painter().lastFrame().scaleBarLength, 0.0);
    QCOMPARE(canvas->painter().lastFrame().gridStep, 100.0);
}

// On the stage, where there is no menu bar: the keys and the wheel work, and
// the right-click menu zooms, fits and follows.
void TestGuiZoom::theStageHasTheSameControls()
{
    Workbench w(QStringLiteral("two-bodies-in-orbit"));
    QVERIFY(w.ready());
    w.action("presentationAction")->setChecked(true);
    QVERIFY(test::waitForSettledLayout(&w.window));
    QVERIFY(!w.window.menuBar()->isVisible());
    Canvas* canvas = w.canvas();
    canvas->setFocus();
    QTest::keyClick(canvas, Qt::Key_Plus);
    QTRY_COMPARE(canvas->camera().zoom, 1.25);
    wheel(canvas, middle(canvas), 120);
    QTRY_VERIFY(std::abs(canvas->camera().zoom - 1.5625) < 1e-12);
    // Right-click on empty space: zoom in there, about that point.
    const QPointF empty = canvas->viewTransform().shownBox().topLeft() + QPointF(30, 30);
    QCOMPARE(canvas->ballAt(empty), -1);
    const sim::Vec2 under = canvas->widgetToWorld(empty);
    {
        QMenu menu;
        canvas->fillContextMenu(menu, empty);
        QStringList texts;
        for (QAction* a : menu.actions())
            if (!a->isSeparator())
                texts << a->text();
        for (const char* name : {"Zoom in here", "Zoom out", "Fit the box", "Fit all balls"})
            QVERIFY2(texts.contains(QString::fromLatin1(name)), name);
        for (QAction* a : menu.actions())
            if (a->text() == QStringLiteral("Zoom in here"))
                a->trigger();
    }
    QVERIFY(std::abs(canvas->camera().zoom - 1.953125) < 1e-12);
    QVERIFY(distance(canvas->worldToWidget(under), empty) < 1e-9);
    // Right-click on a ball: follow it.
    const QPointF onBall = canvas->worldToWidget(sim::Vec2(w.balls().position.col(1)));
    {
        QMenu menu;
        canvas->fillContextMenu(menu, onBall);
        for (QAction* a : menu.actions())
            if (a->text() == QStringLiteral("Follow it"))
                a->trigger();
    }
    QVERIFY(canvas->isFollowing());
    QCOMPARE(canvas->selectedBall(), 1);
    QTest::keyClick(canvas, Qt::Key_0); // Fit the Box stops following
    QTRY_VERIFY(canvas->camera().fitted());
    QVERIFY(!canvas->isFollowing());
}

void TestGuiZoom::aNewLessonOpensOnTheWholeBox()
{
    Workbench w(QStringLiteral("two-bodies-in-orbit"));
    QVERIFY(w.ready());
    w.canvas()->zoomIn();
    QVERIFY(!w.canvas()->camera().fitted());
    w.action("nextLessonAction")->trigger();
    QTRY_VERIFY(w.window.lesson().title != QStringLiteral("Two bodies in orbit"));
    QVERIFY(w.canvas()->camera().fitted());
    QVERIFY(!w.canvas()->isFollowing());
}

QTEST_MAIN(TestGuiZoom)
#include "test_gui_zoom.moc"
