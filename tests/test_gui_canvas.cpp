// The canvas's teaching overlays, pointer and drag-and-throw, the trail ring,
// the trajectory export and the plots dock, checked against the world: a
// grabbed image shows each overlay where the world's numbers put it, pointer
// events give the forces they should, a thrown ball gets the drag's velocity,
// the CSV holds the states the world went through, and the plots sample once
// per step and never while paused.

#include "tests/sim_test_util.h"
#include "sim/collision/broad_phase/broad_phase_geometry.h"
#include "ui/canvas/canvas.h"
#include "ui/docks/plots_dock.h"
#include "ui/canvas/simulation_controller.h"
#include "ui/drawing/trail_recorder.h"
#include "ui/docks/trajectory_export.h"
#include "ui/drawing/world_painter.h"

#include "lessons/lesson_loader.h"

#include <QApplication>
#include <QBuffer>
#include <QLineSeries>
#include <QMouseEvent>

#include <cstring>
#include <QTemporaryDir>
#include <QTest>
#include <QTextStream>

#include <cmath>

using namespace forcelab;

namespace {

// A number as humanNumber writes it ("−1.234 × 10⁵", "12.5") read back.
double studentNumber(QString text)
{
    text.replace(QChar(0x2212), QLatin1Char('-'));
    const qsizetype times = text.indexOf(QStringLiteral(" × 10"));
    if (times < 0)
        return text.toDouble();
    static const QString superscripts = QStringLiteral("⁰¹²³⁴⁵⁶⁷⁸⁹");
    int exponent = 0, sign = 1;
    for (const QChar c : text.mid(times + 5)) {
        if (c == QChar(0x207B))
            sign = -1;
        else
            exponent = 10 * exponent + static_cast<int>(superscripts.indexOf(c));
    }
    return text.left(times).toDouble() * std::pow(10.0, sign * exponent);
}

int colorDistance(QRgb a, QRgb b)
{
    return std::max({std::abs(qRed(a) - qRed(b)), std::abs(qGreen(a) - qGreen(b)), std::abs(qBlue(a) - qBlue(b))});
}

// The smallest distance to `want` among the pixels within `radius` of p (a
// thin antialiased line lands on one of them at full strength).
int nearestColorDistance(const QImage& image, QPointF p, QRgb want, int radius = 1)
{
    const int cx = static_cast<int>(std::floor(p.x())), cy = static_cast<int>(std::floor(p.y()));
    int best = 1000;
    for (int y = cy - radius; y <= cy + radius; ++y)
        for (int x = cx - radius; x <= cx + radius; ++x)
            if (image.rect().contains(x, y))
                best = std::min(best, colorDistance(image.pixel(x, y), want));
    return best;
}

QRgb pixelAt(const QImage& image, QPointF p)
{
    return image.pixel(static_cast<int>(std::floor(p.x())), static_cast<int>(std::floor(p.y())));
}

sim::Ball ball(sim::Vec2 position, sim::Vec2 velocity, double radius, sim::Rgb color = 0x3070c0)
{
    return forcelab::test::coloured(sim::ballAt(position.x(), position.y(), velocity.x(), velocity.y(), radius), color);
}

// A 600 × 400 box (shown at scale 1.2 in a 900 × 500 canvas) without the grid.
sim::Scene box(std::vector<sim::Ball> balls)
{
    sim::Scene scene;
    scene.settings.box = {600.0, 400.0};
    scene.balls = std::move(balls);
    return scene;
}

Overlays only(void (*set)(Overlays&))
{
    Overlays o;
    o.grid = false;
    o.markers = false;
    set(o);
    return o;
}

// A mouse event with an explicit timestamp (ms), as the window system sends it.
void sendMouse(QWidget* w, QEvent::Type type, QPointF pos, Qt::MouseButton button, Qt::MouseButtons buttons,
               quint64 ms)
{
    QMouseEvent event(type, pos, w->mapToGlobal(pos), button, buttons, Qt::NoModifier);
    event.setTimestamp(ms);
    QApplication::sendEvent(w, &event);
}

} // namespace

class GuiCanvasTest : public QObject {
    Q_OBJECT
private slots:
    void readoutsNeverCoverThePhysics_data();
    void readoutsNeverCoverThePhysics();
    void clickSelectsWithoutTouchingThePhysics();
    void middleWallIsDrawn();
    void overlayNamesSwitchOverlays();
    void velocityArrowPointsAlongVelocity();
    void trailRingIsBoundedAndOrdered();
    void trailFollowsThePastPath();
    void vanePointsWhereTheWindBlows();
    void vanesLeaveASmallBoxFree();
    void lineOfImpactPassesThroughBothCentres();
    void totalsShowTheWorldsEnergyAndMomentum();
    void broadPhaseShowsCellsAndIntervals();
    void pointerHoverAttractsPressRepelsLeaveStops();
    void draggingABallThrowsIt();
    void renderImageMatchesTheCanvas();
    void trajectoryCsvHoldsTheStates();
    void plotsSampleOncePerStepAndNotWhilePaused();
};

void GuiCanvasTest::overlayNamesSwitchOverlays()
{
    const Overlays none = Overlays::fromNames({});
    QVERIFY(none.grid && none.markers);
    QVERIFY(!none.velocity && !none.trails && !none.vanes && !none.impact && !none.broadphase && !none.histogram);
    const Overlays all = Overlays::fromNames({"velocity", "acceleration", "readout", "colliding", "trails", "vanes",
                                              "impact", "broadphase", "histogram", "totals"});
    QVERIFY(all.velocity && all.acceleration && all.readout && all.colliding && all.trails && all.vanes &&
            all.impact && all.broadphase && all.histogram && all.totals);
}

void GuiCanvasTest::velocityArrowPointsAlongVelocity()
{
    SimulationController controller;
    // Speed 200 px/s at (0.8, -0.6): the arrow (0.25 s of path) ends 50 px away.
    QVERIFY(!controller.setScene(box({ball({300, 200}, {160, -120}, 10)})));
    Canvas canvas(&controller);
    canvas.resize(900, 500);
    canvas.setOverlays(only([](Overlays& o) { o.velocity = true; }));
    const QImage image = canvas.grab().toImage();
    const sim::Vec2 c(300, 200), u(0.8, -0.6);
    for (double s : {15.0, 25.0, 35.0}) {
        QVERIFY2(nearestColorDistance(image, canvas.worldToWidget(c + s * u), canvas_colors::kVelocity) <= 40,
                 qPrintable(QStringLiteral("no arrow %1 px along v").arg(s)));
        // Nothing the other way, nor across.
        QCOMPARE(colorDistance(pixelAt(image, canvas.worldToWidget(c - s * u)), canvas_colors::kBackground), 0);
        QCOMPARE(colorDistance(pixelAt(image, canvas.worldToWidget(c + s * sim::Vec2(0.6, 0.8))),
                               canvas_colors::kBackground), 0);
    }
    // Switched off: background where the arrow was.
    canvas.setOverlays(only([](Overlays&) {}));
    QCOMPARE(colorDistance(pixelAt(canvas.grab().toImage(), canvas.worldToWidget(c + 25.0 * u)),
                           canvas_colors::kBackground), 0);
}

void GuiCanvasTest::trailRingIsBoundedAndOrdered()
{
    sim::BallState balls;
    const std::vector<sim::Ball> two{ball({0, 0}, {0, 0}, 1), ball({0, 0}, {0, 0}, 1)};
    balls.assign(two);
    TrailRecorder trails;
    trails.setCapacity(5);
    for (int k = 0; k < 8; ++k) {
        balls.position.col(0) = sim::Vec2(k, 0);
        balls.position.col(1) = sim::Vec2(0, 10 * k);
        trails.record(balls, 0.1 * k);
        trails.record(balls, 0.1 * k); // same time (a redraw while paused): nothing new
    }
    QCOMPARE(trails.length(), 5);
    QCOMPARE(trails.balls().size(), std::size_t{2});
    for (int age = 0; age < 5; ++age) {
        QCOMPARE(trails.at(0, age), QPointF(7 - age, 0));
        QCOMPARE(trails.at(1, age), QPointF(0, 10 * (7 - age)));
    }
    // Earlier time (a reset) starts afresh; so does the selected-only scope.
    trails.record(balls, 0.0);
    QCOMPARE(trails.length(), 1);
    trails.setScope(TrailRecorder::Scope::Selected);
    trails.setSelected(1);
    trails.record(balls, 1.0);
    QCOMPARE(trails.balls(), std::vector<int>{1});
    QCOMPARE(trails.length(), 1);
}

void GuiCanvasTest::trailFollowsThePastPath()
{
    SimulationController controller;
    const sim::Vec2 start(100, 100), v(240, 120);
    QVERIFY(!controller.setScene(box({ball(start, v, 8, 0x2060c0)})));
    Canvas canvas(&controller);
    canvas.resize(900, 500);
    canvas.setOverlays(only([](Overlays& o) { o.trails = true; }));
    for (int k = 0; k < 60; ++k)
        controller.stepOnce(); // 1 s: the ball ends at (340, 220)
    QCOMPARE(canvas.trails().length(), 61);
    const QImage image = canvas.grab().toImage();
    // Points the ball passed (well away from where it is now) are drawn, in
    // the ball's colour; points beside the path are not.
    const sim::Vec2 dir = v.normalized(), across(-dir.y(), dir.x());
    for (double t : {0.15, 0.35, 0.55, 0.75}) {
        const sim::Vec2 past = start + t * v;
        const QRgb got = pixelAt(image, canvas.worldToWidget(past));
        QVERIFY2(colorDistance(got, canvas_colors::kBackground) > 40,
                 qPrintable(QStringLiteral("t = %1: %2 is background").arg(t).arg(got, 8, 16)));
        QVERIFY(qBlue(got) > qRed(got)); // the ball's blue, faded
        QCOMPARE(colorDistance(pixelAt(image, canvas.worldToWidget(past + 12.0 * across)), canvas_colors::kBackground),
                 0);
    }
    // A new scene drops the trail.
    controller.reset();
    QCOMPARE(canvas.trails().length(), 1);
}

void GuiCanvasTest::vanePointsWhereTheWindBlows()
{
    SimulationController controller;
    sim::Scene scene = box({ball({300, 300}, {0, 0}, 10)});
    scene.settings.wind.mode = sim::WindMode::Pointer;
    scene.settings.wind.strength = 50.0;
    QVERIFY(!controller.setScene(scene));
    Canvas canvas(&controller);
    canvas.resize(900, 500);
    canvas.setOverlays(only([](Overlays& o) { o.vanes = true; }));
    const double r = WorldPainter::vaneRadius(1.0);

    auto blowFrom = [&](double x) {
        sim::PointerInput pointer;
        pointer.inside = true;
        pointer.position = {x, 200.0};
        controller.setPointer(pointer);
        controller.stepOnce();
    };
    // The pointer on the left: the wind blows right, at 80% of full strength.
    blowFrom(60.0);
    QVERIFY(controller.world().wind() > 0.0);
    QImage image = canvas.grab().toImage();
    QPointF c = WorldPainter::vaneCentre(canvas.viewTransform(), 0, 1.0);
    QVERIFY(nearestColorDistance(image, c + QPointF(0.5 * r, 0), canvas_colors::kVane, 0) <= 30);
    QVERIFY(nearestColorDistance(image, c - QPointF(0.5 * r, 0), canvas_colors::kVane, 1) > 100);
    // The pointer on the right: it blows left.
    blowFrom(540.0);
    QVERIFY(controller.world().wind() < 0.0);
    image = canvas.grab().toImage();
    QVERIFY(nearestColorDistance(image, c - QPointF(0.5 * r, 0), canvas_colors::kVane, 0) <= 30);
    QVERIFY(nearestColorDistance(image, c + QPointF(0.5 * r, 0), canvas_colors::kVane, 1) > 100);

    // A compared wind gets a second vane (its hub is drawn whatever it blows).
    const QPointF second = WorldPainter::vaneCentre(canvas.viewTransform(), 1, 1.0);
    QVERIFY(nearestColorDistance(image, second, canvas_colors::kVane, 0) > 100);
    sim::WorldSettings settings = controller.world().settings();
    settings.wind.compare = sim::WindMode::Smoothed;
    QVERIFY(controller.setSettings(settings));
    controller.stepOnce();
    image = canvas.grab().toImage();
    QVERIFY(nearestColorDistance(image, second, canvas_colors::kVane, 0) <= 30);
    const double share = controller.world().compareWind() / 50.0;
    if (std::abs(share) > 0.3) // its arrow points its own way
        QVERIFY(nearestColorDistance(image, second + QPointF(0.25 * r * (share > 0 ? 1 : -1), 0),
                                     canvas_colors::kVane, 0) <= 30);
}

// In the normal layout at 1024x768 the box is small and the vanes covered a
// third of its height; where the canvas has room over the box they sit
// there, and draw nothing inside the box. Where it has none (the stage
// view) they stay in the box's corner.
void GuiCanvasTest::vanesLeaveASmallBoxFree()
{
    SimulationController controller;
    sim::Scene scene = box({ball({300, 500}, {0, 0}, 10)});
    scene.settings.wind.mode = sim::WindMode::Random;
    scene.settings.wind.strength = 200.0;
    scene.settings.wind.compare = sim::WindMode::Smoothed;
    QVERIFY(!controller.setScene(scene));
    controller.stepOnce();
    Canvas canvas(&controller);
    canvas.setOverlays(only([](Overlays& o) { o.vanes = true; }));
    const double r = WorldPainter::vaneRadius(1.0);

    canvas.resize(600, 700); // a tall canvas: room over the box
    QImage image = canvas.grab().toImage();
    QRectF boxRect = canvas.viewTransform().boxRect();
    for (int i = 0; i < 2; ++i) {
        const QPointF c = WorldPainter::vaneCentre(canvas.viewTransform(), i, 1.0);
        QVERIFY2(c.y() + r + 14.0 < boxRect.top(), qPrintable(QStringLiteral("%1 %2").arg(c.y()).arg(boxRect.top())));
        QVERIFY(c.y() - r >= 0.0);
        QVERIFY(nearestColorDistance(image, c, canvas_colors::kVane, 0) <= 30); // its hub
    }
    // Nothing of the vanes in the box: its top-left corner is as without them.
    canvas.setOverlays(only([](Overlays&) {}));
    const QImage bare = canvas.grab().toImage();
    const QRect corner = boxRect.toAlignedRect().adjusted(2, 2, 0, 0);
    int differing = 0;
    for (int y = corner.top(); y < corner.top() + 100; ++y)
        for (int x = corner.left(); x < corner.left() + 300; ++x)
            differing += image.pixel(x, y) != bare.pixel(x, y) ? 1 : 0;
    QCOMPARE(differing, 0);

    canvas.setOverlays(only([](Overlays& o) { o.vanes = true; }));
    canvas.resize(900, 500); // no room over the box: in its corner
    boxRect = canvas.viewTransform().boxRect();
    const QPointF inside = WorldPainter::vaneCentre(canvas.viewTransform(), 0, 1.0);
    QVERIFY(boxRect.contains(inside - QPointF(r, r)));
    QVERIFY(nearestColorDistance(canvas.grab().toImage(), inside, canvas_colors::kVane, 0) <= 30);
}

void GuiCanvasTest::lineOfImpactPassesThroughBothCentres()
{
    SimulationController controller;
    // Ball 0 runs into ball 1 slightly off centre: a glancing, elastic hit of equal masses.
    sim::Scene scene = box({ball({150, 200}, {300, 0}, 20, 0xc04040), ball({260, 215}, {0, 0}, 20, 0x40a040)});
    scene.settings.collisions.response = sim::Response::Impulse2D;
    scene.settings.collisions.restitution = 1.0;
    QVERIFY(!controller.setScene(scene));
    Canvas canvas(&controller);
    canvas.resize(900, 500);
    canvas.setOverlays(only([](Overlays& o) { o.impact = true; }));
    canvas.setSelectedBall(0);
    for (int k = 0; k < 40 && !canvas.collisionView().valid(); ++k)
        controller.stepOnce();
    const CollisionView view = canvas.collisionView();
    QVERIFY(view.valid());
    QCOMPARE(view.a, 0);
    QCOMPARE(view.b, 1);
    const sim::BallState& balls = controller.world().balls();
    QCOMPARE(view.positionA, sim::Vec2(balls.position.col(0)));
    QCOMPARE(view.positionB, sim::Vec2(balls.position.col(1)));
    QCOMPARE(view.afterA, sim::Vec2(balls.velocity.col(0)));
    QCOMPARE(view.beforeA, sim::Vec2(300, 0));
    QCOMPARE(view.beforeB, sim::Vec2(0, 0));
    // Before and after are around one impulse along the line of centres:
    // momentum is kept, the tangential parts do not change, energy is kept (e = 1).
    const sim::Vec2 n = (view.positionB - view.positionA).normalized(), t(-n.y(), n.x());
    QVERIFY((view.beforeA + view.beforeB - view.afterA - view.afterB).norm() < 1e-9);
    QVERIFY(std::abs((view.afterA - view.beforeA).dot(t)) < 1e-9);
    QVERIFY(std::abs(view.beforeA.squaredNorm() - view.afterA.squaredNorm() - view.afterB.squaredNorm()) < 1e-6);
    QVERIFY(view.afterB.dot(n) > 0.0);
    // Ball 1, selected only after the hit, shows the same collision from its side.
    canvas.setSelectedBall(1);
    const CollisionView other = canvas.collisionView();
    QVERIFY(other.valid());
    QCOMPARE(other.a, 1);
    QCOMPARE(other.b, 0);
    QCOMPARE(other.time, view.time);
    QCOMPARE(other.beforeA, view.beforeB);
    QCOMPARE(other.afterB, view.afterA);
    canvas.setSelectedBall(0);
    QCOMPARE(canvas.collisionView().time, view.time);

    // The drawn line of impact runs through both centres and on beyond them.
    const QImage image = canvas.grab().toImage();
    for (const sim::Vec2& p : {sim::Vec2(view.positionA - n * 30.0), sim::Vec2(view.positionA - n * 60.0),
                               sim::Vec2(view.positionB + n * 95.0)})
        QVERIFY2(nearestColorDistance(image, canvas.worldToWidget(p), canvas_colors::kImpactLine) <= 40,
                 qPrintable(QStringLiteral("no line of impact at (%1, %2)").arg(p.x()).arg(p.y())));
    // ... and nowhere off it at the same distance.
    QVERIFY(nearestColorDistance(image, canvas.worldToWidget(view.positionA - t * 60.0), canvas_colors::kImpactLine) >
            100);
    // The tangent (dashed) crosses the line at the contact point, at right angles.
    const sim::Vec2 contact = 0.5 * (view.positionA + view.positionB);
    int onTangent = 0;
    for (int k = 2; k <= 10; ++k)
        onTangent += nearestColorDistance(image, canvas.worldToWidget(contact + t * (6.0 * k)), canvas_colors::kTangent) <= 40;
    QVERIFY(onTangent >= 3);
}

void GuiCanvasTest::totalsShowTheWorldsEnergyAndMomentum()
{
    SimulationController controller;
    sim::Scene scene = box({ball({100, 100}, {50, -20}, 10), ball({400, 100}, {-30, 0}, 12)});
    scene.settings.gravity.enabled = true;
    QVERIFY(!controller.setScene(scene));
    controller.stepOnce();
    const sim::Energy e = controller.world().energy();
    const QStringList text = WorldPainter::totalsText(controller.world());
    // Six lines: energy's head line with the unit, kinetic, potential and
    // total, the momentum's head line, its x and y. Four digits counted from
    // the larger of kinetic and potential (and from Σm|v| for the momentum).
    QCOMPARE(text.size(), 6);
    QVERIFY(text[0].contains(QStringLiteral("mass·px²/s²")) && text[4].contains(QStringLiteral("mass·px/s")));
    const double energyScale = std::max(std::abs(e.kinetic), std::abs(e.potential));
    const double kinetic = studentNumber(text[1].section(QStringLiteral("kinetic"), 1).trimmed());
    const double total = studentNumber(text[3].section(QStringLiteral("total"), 1).trimmed());
    QVERIFY2(std::abs(kinetic - e.kinetic) <= 5e-4 * energyScale, qPrintable(text[1]));
    QVERIFY2(std::abs(total - e.total()) <= 5e-4 * energyScale, qPrintable(text[3]));
    const sim::Vec2 p = controller.world().momentum();
    const double pScale = WorldPainter::momentumScale(controller.world());
    const QStringList pxy = text[5].trimmed().mid(1).chopped(1).split(QStringLiteral(", "));
    QCOMPARE(pxy.size(), 2);
    QVERIFY2(std::abs(studentNumber(pxy[0]) - p.x()) <= 5e-4 * pScale, qPrintable(text[5]));
    QVERIFY2(std::abs(studentNumber(pxy[1]) - p.y()) <= 5e-4 * pScale, qPrintable(text[5]));

    // The panel sits in the box's top-right corner only when switched on.
    Canvas canvas(&controller);
    canvas.resize(900, 500);
    const QPointF corner = canvas.worldToWidget({590, 14});
    canvas.setOverlays(only([](Overlays&) {}));
    QCOMPARE(colorDistance(pixelAt(canvas.grab().toImage(), corner), canvas_colors::kBackground), 0);
    canvas.setOverlays(only([](Overlays& o) { o.totals = true; }));
    QVERIFY(colorDistance(pixelAt(canvas.grab().toImage(), corner), canvas_colors::kBackground) > 0);
}

void GuiCanvasTest::broadPhaseShowsCellsAndIntervals()
{
    SimulationController controller;
    sim::Scene scene = box({ball({300, 200}, {0, 0}, 10), ball({500, 100}, {0, 0}, 10)});
    scene.settings.collisions.response = sim::Response::Flag;
    scene.settings.collisions.detection = sim::Detection::Grid;
    QVERIFY(!controller.setScene(scene));
    Canvas canvas(&controller);
    canvas.resize(900, 500);
    canvas.setOverlays(only([](Overlays& o) { o.broadphase = true; }));
    // The detector's cells: 1.5 × 20 = 30 px (and a hair) from the smallest
    // corner (290, 90), so ball 0 ([290, 310] × [190, 210]) lies in cell
    // [290, 320] × [180, 210] only; cell [320, 350] × [180, 210] is empty.
    const sim::BroadPhaseGeometry grid = sim::broadPhaseGeometry(controller.world());
    QVERIFY(std::abs(grid.cellSize - 30.0) < 1e-6 && std::abs(grid.originX - 290.0) < 1e-6);
    QImage image = canvas.grab().toImage();
    QVERIFY(colorDistance(pixelAt(image, canvas.worldToWidget({316, 195})), canvas_colors::kBackground) > 5);
    QCOMPARE(colorDistance(pixelAt(image, canvas.worldToWidget({335, 195})), canvas_colors::kBackground), 0);

    // Sweep: rows of the detector's height, 20.5 px (20 px × 1.001 rounded up
    // to 6 bits); ball 0's x-interval [290, 310] is a band in the row of its
    // top edge, [184.5, 205]; outside it there is nothing.
    sim::WorldSettings settings = controller.world().settings();
    settings.collisions.detection = sim::Detection::Sweep;
    QVERIFY(controller.setSettings(settings));
    QCOMPARE(sim::broadPhaseGeometry(controller.world()).rowHeight, 20.5);
    image = canvas.grab().toImage();
    QVERIFY(colorDistance(pixelAt(image, canvas.worldToWidget({293, 188})), canvas_colors::kBackground) > 5);
    QCOMPARE(colorDistance(pixelAt(image, canvas.worldToWidget({320, 188})), canvas_colors::kBackground), 0);
    // Brute force draws nothing: every pair is tested.
    settings.collisions.detection = sim::Detection::Brute;
    QVERIFY(controller.setSettings(settings));
    QCOMPARE(colorDistance(pixelAt(canvas.grab().toImage(), canvas.worldToWidget({293, 188})),
                           canvas_colors::kBackground), 0);
}

void GuiCanvasTest::pointerHoverAttractsPressRepelsLeaveStops()
{
    SimulationController controller;
    sim::Scene scene = box({ball({150, 200}, {0, 0}, 10)});
    scene.settings.pointer.enabled = true;
    QVERIFY(!controller.setScene(scene));
    Canvas canvas(&controller);
    canvas.resize(900, 500);
    canvas.show();
    QVERIFY(QTest::qWaitForWindowExposed(&canvas));
    const sim::Vec2 ballAt(150, 200), pointer(400, 290);
    const sim::Vec2 toPointer = (pointer - ballAt).normalized();
    const QPoint where = canvas.worldToWidget(pointer).toPoint();
    const sim::Vec2 used = canvas.widgetToWorld(where); // the whole pixel the event lands on
    const sim::Vec2 towards = (used - ballAt).normalized();
    QVERIFY(towards.dot(toPointer) > 0.9999);

    QTest::mouseMove(&canvas, where);
    sim::Vec2 a = controller.world().accelerations().col(0);
    QVERIFY(a.norm() > 1.0);
    QVERIFY(a.normalized().dot(towards) > 1.0 - 1e-12);

    QTest::mousePress(&canvas, Qt::LeftButton, {}, where); // empty space: repel
    QCOMPARE(canvas.draggedBall(), -1);
    a = controller.world().accelerations().col(0);
    QVERIFY(a.norm() > 1.0);
    QVERIFY(a.normalized().dot(towards) < -1.0 + 1e-12);
    QTest::mouseRelease(&canvas, Qt::LeftButton, {}, where);
    QVERIFY(controller.world().accelerations().col(0).normalized().dot(towards) > 1.0 - 1e-12);

    QEvent leave(QEvent::Leave);
    QCoreApplication::sendEvent(&canvas, &leave);
    QCOMPARE(controller.world().accelerations().col(0).norm(), 0.0);
}

void GuiCanvasTest::draggingABallThrowsIt()
{
    SimulationController controller;
    sim::Scene scene = box({ball({300, 200}, {0, 0}, 20), ball({100, 100}, {0, 0}, 10)});
    scene.settings.gravity.enabled = true;
    scene.settings.pointer.enabled = true;
    QVERIFY(!controller.setScene(scene));
    Canvas canvas(&controller);
    canvas.resize(900, 500);
    canvas.show();
    QVERIFY(QTest::qWaitForWindowExposed(&canvas));
    const sim::BallState& balls = controller.world().balls();

    // Press 5 px right of the ball's centre and drag: +3.6 widget px and
    // -1.2 widget px every 10 ms is (300, -100) world px/s at scale 1.2.
    const QPointF grab = canvas.worldToWidget({305, 200});
    sendMouse(&canvas, QEvent::MouseButtonPress, grab, Qt::LeftButton, Qt::LeftButton, 1000);
    QCOMPARE(canvas.draggedBall(), -1); // a press selects; the ball is taken only once the pointer moves
    QCOMPARE(canvas.selectedBall(), 0);
    QVERIFY(!controller.world().pointer().inside); // no pointer forces while the button is down on a ball
    const int grabAfter = QApplication::startDragDistance(); // px, Manhattan, the platform's drag distance
    QPointF at = grab;
    for (int k = 1; k <= 12; ++k) {
        at += QPointF(3.6, -1.2);
        sendMouse(&canvas, QEvent::MouseMove, at, Qt::NoButton, Qt::LeftButton, 1000 + 10 * k);
        if ((at - grab).manhattanLength() < grabAfter) { // not yet taken: untouched
            QCOMPARE(canvas.draggedBall(), -1);
            QCOMPARE(sim::Vec2(balls.velocity.col(0)), sim::Vec2(0, 0));
            continue;
        }
        QCOMPARE(canvas.draggedBall(), 0);
        // The ball follows the pointer, keeping where it was grabbed, at rest.
        const sim::Vec2 want = canvas.widgetToWorld(at) - sim::Vec2(5, 0);
        QVERIFY((sim::Vec2(balls.position.col(0)) - want).norm() < 1e-9);
        QCOMPARE(sim::Vec2(balls.velocity.col(0)), sim::Vec2(0, 0));
    }
    // Held while the simulation runs: gravity does not pull it away.
    const sim::Vec2 held = balls.position.col(0);
    controller.advance(3 * controller.world().settings().time.dt);
    QVERIFY((sim::Vec2(balls.position.col(0)) - held).norm() < 1e-9);
    QVERIFY(balls.position(1, 1) > 100.0); // the other ball falls

    at += QPointF(3.6, -1.2);
    sendMouse(&canvas, QEvent::MouseButtonRelease, at, Qt::LeftButton, Qt::NoButton, 1130);
    QCOMPARE(canvas.draggedBall(), -1);
    const sim::Vec2 thrown = balls.velocity.col(0);
    QVERIFY2((thrown - sim::Vec2(300, -100)).norm() < 1e-6 * 300,
             qPrintable(QStringLiteral("thrown at (%1, %2)").arg(thrown.x()).arg(thrown.y())));
    QVERIFY(controller.world().pointer().inside);
    // Then it flies (the pointer gone, so only gravity acts): one step moves it by v dt in x.
    QEvent leave(QEvent::Leave);
    QCoreApplication::sendEvent(&canvas, &leave);
    const sim::Vec2 before = balls.position.col(0);
    controller.stepOnce();
    const sim::Vec2 moved = sim::Vec2(balls.position.col(0)) - before;
    QVERIFY(std::abs(moved.x() - 300.0 / 60.0) < 1e-9);

    // Held still for 100 ms before letting go: a drop, not a throw.
    const QPointF c = canvas.worldToWidget(balls.position.col(0));
    sendMouse(&canvas, QEvent::MouseButtonPress, c, Qt::LeftButton, Qt::LeftButton, 2000);
    sendMouse(&canvas, QEvent::MouseMove, c + QPointF(12, 0), Qt::NoButton, Qt::LeftButton, 2020);
    sendMouse(&canvas, QEvent::MouseButtonRelease, c + QPointF(12, 0), Qt::LeftButton, Qt::NoButton, 2120);
    QCOMPARE(sim::Vec2(balls.velocity.col(0)), sim::Vec2(0, 0));
}

// A click on a moving ball (press and release without moving) selects it and
// leaves the world alone: velocity and position bit for bit, and the next
// steps give the same state as a twin world nobody clicked. Before, a click
// counted as a throw at no speed and stopped the ball (the Moon in lesson 19).
void GuiCanvasTest::readoutsNeverCoverThePhysics_data()
{
    QTest::addColumn<QString>("lesson");
    QTest::addColumn<QSize>("size");
    for (const char* lesson : {"19-two-bodies-in-orbit", "31-break-shot", "33-orbit-energy-drift"})
        for (const QSize size : {QSize(960, 640), QSize(700, 900), QSize(560, 420)})
            QTest::newRow(qPrintable(QStringLiteral("%1 %2x%3").arg(lesson).arg(size.width()).arg(size.height())))
                << QString::fromLatin1(lesson) << size;
}

// The per-ball readout, the totals, the force legend and the momenta inset
// sit in a strip outside the box: no ball's disc under any panel at any
// moment of the first 5 s, the panels apart from each other and from the
// box, and inside the canvas.
void GuiCanvasTest::readoutsNeverCoverThePhysics()
{
    QFETCH(QString, lesson);
    QFETCH(QSize, size);
    const LoadResult r = LessonLoader::load(lesson);
    QVERIFY2(r.ok(), qPrintable(r.errors().join(" | ")));
    SimulationController controller;
    QVERIFY(!controller.setScene(r.lesson->scene));
    Canvas canvas(&controller);
    canvas.resize(size);
    Overlays o = Overlays::fromNames(r.lesson->overlays);
    o.readout = true;
    o.totals = true;
    o.forceSources = true; // every panel there is: the legend and the momenta inset too
    o.momenta = true;
    canvas.setOverlays(o);
    PaintOptions options;
    options.overlays = o;
    const QRectF area(QPointF(0, 0), QSizeF(size));
    const WorldPainter::Panels panels = WorldPainter::panels(controller.world(), area, options);
    const QList<QRectF> all{panels.readout, panels.totals, panels.sources, panels.momenta};
    const ViewTransform view = WorldPainter::view(controller.world(), area, options);
    for (qsizetype a = 0; a < all.size(); ++a) {
        QVERIFY2(!all[a].isEmpty(), qPrintable(QStringLiteral("panel %1 missing").arg(a)));
        QVERIFY2(area.contains(all[a]), qPrintable(QStringLiteral("panel %1 outside the canvas").arg(a)));
        QVERIFY(!view.boxRect().intersects(all[a]));
        for (qsizetype b = a + 1; b < all.size(); ++b)
            QVERIFY2(!all[a].intersects(all[b]), qPrintable(QStringLiteral("panels %1 and %2 overlap").arg(a).arg(b)));
    }
    const double dt = controller.world().settings().time.dt;
    for (int k = 0; k < static_cast<int>(5.0 / dt); k += 10) {
        const sim::BallState& b = controller.world().balls();
        for (int i = 0; i < b.size(); ++i) {
            const QPointF c = view.toWidget(sim::Vec2(b.position.col(i)));
            const double rad = view.toWidget(b.radius[i]);
            const QRectF disc(c - QPointF(rad, rad), QSizeF(2 * rad, 2 * rad));
            for (const QRectF& panel : all)
                QVERIFY2(!disc.intersects(panel),
                         qPrintable(QStringLiteral("ball %1 under a panel at t = %2 s").arg(i).arg(controller.world().time())));
        }
        for (int s = 0; s < 10; ++s)
            controller.stepOnce();
    }
    // The picture agrees: the readout's card is drawn where panels() says.
    const QImage shot = canvas.renderImage();
    QCOMPARE(shot.pixelColor(panels.readout.center().toPoint()).lightness() > 200, true);
}

void GuiCanvasTest::clickSelectsWithoutTouchingThePhysics()
{
    sim::Scene scene = box({ball({200, 150}, {120, -80}, 25), ball({420, 260}, {-60, 10}, 15, 0xd08020)});
    scene.settings.gravity.enabled = true;
    scene.settings.pointer.enabled = true; // a press on empty space would push: not on a ball
    SimulationController controller, twin;
    QVERIFY(!controller.setScene(scene));
    QVERIFY(!twin.setScene(scene));
    controller.stepOnce();
    twin.stepOnce();
    Canvas canvas(&controller);
    canvas.resize(900, 500);
    canvas.show();
    QVERIFY(QTest::qWaitForWindowExposed(&canvas));
    const sim::BallState& balls = controller.world().balls();
    const sim::Matrix2X v = balls.velocity, x = balls.position;
    const QPointF at = canvas.worldToWidget(balls.position.col(0)) + QPointF(2, 1);
    sendMouse(&canvas, QEvent::MouseButtonPress, at, Qt::LeftButton, Qt::LeftButton, 1000);
    sendMouse(&canvas, QEvent::MouseMove, at + QPointF(1, 0), Qt::NoButton, Qt::LeftButton, 1040); // a hand's tremble
    sendMouse(&canvas, QEvent::MouseButtonRelease, at + QPointF(1, 0), Qt::LeftButton, Qt::NoButton, 1090);
    QCOMPARE(canvas.selectedBall(), 0);
    QCOMPARE(canvas.draggedBall(), -1);
    QVERIFY(std::memcmp(balls.velocity.data(), v.data(), sizeof(double) * v.size()) == 0);
    QVERIFY(std::memcmp(balls.position.data(), x.data(), sizeof(double) * x.size()) == 0);
    // The pointer sits on the canvas again (inside, not pressed); the twin's too.
    twin.setPointer(controller.world().pointer());
    for (int k = 0; k < 30; ++k) {
        controller.stepOnce();
        twin.stepOnce();
    }
    const sim::BallState& b = twin.world().balls();
    QVERIFY(std::memcmp(balls.velocity.data(), b.velocity.data(), sizeof(double) * v.size()) == 0);
    QVERIFY(std::memcmp(balls.position.data(), b.position.data(), sizeof(double) * x.size()) == 0);
}

// Stage 3's middle wall is drawn where it stands, x = width / 2, in the
// frame's colour (before: the lesson talked about a wall nobody could see).
void GuiCanvasTest::middleWallIsDrawn()
{
    for (const bool middle : {true, false}) {
        sim::Scene scene = box({ball({100, 100}, {0, 0}, 10)});
        scene.settings.walls.middle = middle;
        SimulationController controller;
        QVERIFY(!controller.setScene(scene));
        Canvas canvas(&controller);
        canvas.resize(700, 420);
        const QImage shot = canvas.renderImage();
        const QPointF top = canvas.worldToWidget({300, 100}), bottom = canvas.worldToWidget({300, 300});
        int dark = 0;
        for (int y = int(top.y()); y <= int(bottom.y()); ++y)
            dark += QColor(shot.pixel(int(std::lround(top.x())), y)).lightness() < 100 ? 1 : 0;
        const int rows = int(bottom.y()) - int(top.y()) + 1;
        qInfo("middle wall %s: %d of %d pixels down x = 300 are dark", middle ? "on" : "off", dark, rows);
        QVERIFY(middle ? dark == rows : dark == 0);
    }
}

void GuiCanvasTest::renderImageMatchesTheCanvas()
{
    SimulationController controller;
    QVERIFY(!controller.setScene(box({ball({200, 150}, {80, 40}, 25), ball({420, 260}, {-60, 10}, 15, 0xd08020)})));
    Canvas canvas(&controller);
    canvas.resize(700, 420);
    Overlays o;
    o.velocity = true;
    o.vanes = true;
    canvas.setOverlays(o);
    controller.stepOnce(); // past t = 0: no "press Space" banner, which pictures leave out
    const QImage shot = canvas.renderImage();
    QCOMPARE(shot.size(), QSize(700, 420));
    const QImage grabbed = canvas.grab().toImage().convertToFormat(shot.format());
    QCOMPARE(shot, grabbed);
}

void GuiCanvasTest::trajectoryCsvHoldsTheStates()
{
    SimulationController controller;
    sim::Scene scene = box({ball({100, 100}, {50, -20}, 10), ball({400, 100}, {-30, 0}, 12)});
    scene.settings.gravity.enabled = true;
    QVERIFY(!controller.setScene(scene));
    TrajectoryExport exporter(&controller);
    exporter.start(controller.world(), 1);
    QVERIFY(exporter.isRecording());
    std::vector<TrajectoryExport::Row> want;
    auto remember = [&] {
        const sim::BallState& b = controller.world().balls();
        want.push_back({controller.world().time(), 1, b.position(0, 1), b.position(1, 1), b.velocity(0, 1),
                        b.velocity(1, 1)});
    };
    remember();
    const double dt = controller.world().settings().time.dt;
    for (int k = 0; k < 5; ++k) {
        QCOMPARE(controller.advance(dt), 1);
        remember();
    }
    controller.notifyBallsChanged(); // a redraw while paused: no row
    QCOMPARE(exporter.rows().size(), want.size());

    QString text;
    QTextStream out(&text);
    exporter.writeCsv(out);
    out.flush();
    const QStringList lines = text.split(u'\n', Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 7);
    QCOMPARE(lines[0], QStringLiteral("t_s,ball,x_px,y_px,vx_px_per_s,vy_px_per_s"));
    for (int k = 0; k < 6; ++k) {
        const QStringList f = lines[k + 1].split(u',');
        QCOMPARE(f.size(), 6);
        const auto& w = want[static_cast<std::size_t>(k)];
        QCOMPARE(f[0].toDouble(), w.t);
        QCOMPARE(f[1].toInt(), 1);
        QCOMPARE(f[2].toDouble(), w.x); // 17 digits: the same double back
        QCOMPARE(f[3].toDouble(), w.y);
        QCOMPARE(f[4].toDouble(), w.vx);
        QCOMPARE(f[5].toDouble(), w.vy);
    }
    QCOMPARE(want[5].t, 5 * dt);
    QVERIFY(want[5].vy > want[0].vy); // gravity is in the numbers

    // Every ball: one row per ball per record; a reset stops recording.
    exporter.start(controller.world(), -1);
    controller.stepOnce();
    QCOMPARE(exporter.rows().size(), std::size_t{4});
    QCOMPARE(exporter.rows()[2].ball, 0);
    QCOMPARE(exporter.rows()[3].ball, 1);
    controller.reset();
    QVERIFY(!exporter.isRecording());
    QCOMPARE(exporter.rows().size(), std::size_t{4});

    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("trajectory.csv"));
    QVERIFY(!exporter.save(path));
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.readAll().count('\n'), 5);
    const auto error = exporter.save(dir.filePath(QStringLiteral("missing/dir/trajectory.csv")));
    QVERIFY(error);
    QVERIFY(error->contains(QStringLiteral("missing/dir/trajectory.csv")));
}

void GuiCanvasTest::plotsSampleOncePerStepAndNotWhilePaused()
{
    SimulationController controller;
    sim::Scene scene = box({ball({100, 100}, {50, -20}, 10), ball({400, 100}, {-30, 0}, 12)});
    scene.settings.gravity.enabled = true;
    scene.settings.spring.enabled = true; // potential energy of two kinds
    QVERIFY(!controller.setScene(scene));
    PlotsDock dock(&controller);
    QCOMPARE(dock.objectName(), QStringLiteral("plotsDock"));
    QCOMPARE(dock.samples().size(), std::size_t{1}); // the state it starts from

    const double dt = controller.world().settings().time.dt;
    for (int k = 1; k <= 10; ++k) {
        QCOMPARE(controller.advance(dt), 1);
        QCOMPARE(dock.samples().size(), std::size_t(1 + k));
    }
    // Paused: redraws, pointer moves and setting edits add nothing.
    QVERIFY(!controller.isPlaying());
    controller.notifyBallsChanged();
    QVERIFY(controller.setSettings(controller.world().settings()));
    QCOMPARE(dock.samples().size(), std::size_t{11});

    dock.refreshCharts();
    const sim::Energy e = controller.world().energy();
    QCOMPARE(dock.series(PlotsDock::Series::Kinetic)->count(), 11);
    // The points are the values over the factor the axis names (×10⁶ …).
    auto value = [&dock](PlotsDock::Series s, int k) { return dock.series(s)->at(k).y() * dock.shownFactor(s); };
    QCOMPARE(dock.series(PlotsDock::Series::Kinetic)->at(10).x(), controller.world().time());
    QCOMPARE(value(PlotsDock::Series::Kinetic, 10), e.kinetic);
    QCOMPARE(value(PlotsDock::Series::Potential, 10), e.potential);
    QCOMPARE(value(PlotsDock::Series::Total, 10), e.total());
    QVERIFY(e.potential != 0.0);
    QCOMPARE(value(PlotsDock::Series::MomentumMagnitude, 10), controller.world().momentum().norm());
    QCOMPARE(value(PlotsDock::Series::MomentumX, 10), controller.world().momentum().x());
    QCOMPARE(value(PlotsDock::Series::StepCost, 10), controller.world().lastStep().seconds * 1e6);

    // A rolling window of 10 s, drawn with at most kMaxPoints points.
    for (int k = 0; k < 1500; ++k)
        controller.advance(dt);
    const double now = controller.world().time();
    // The oldest sample is the one exactly 10 s old (to the last bit of the
    // two summed times: 601 samples at 60 steps a second).
    QVERIFY(dock.samples().front().t >= now - PlotsDock::kWindowSeconds - 1e-9);
    QVERIFY(dock.samples().front().t <= now - PlotsDock::kWindowSeconds + 1.5 * dt);
    QCOMPARE(dock.samples().size(), std::size_t{601});
    dock.refreshCharts();
    QCOMPARE(dock.series(PlotsDock::Series::Total)->count(), 601);
    QCOMPARE(dock.series(PlotsDock::Series::Total)->at(600).x(), now);

    // A reset starts the plots again.
    controller.reset();
    QCOMPARE(dock.samples().size(), std::size_t{1});
    QCOMPARE(dock.samples().front().t, 0.0);
}

QTEST_MAIN(GuiCanvasTest)
#include "test_gui_canvas.moc"
