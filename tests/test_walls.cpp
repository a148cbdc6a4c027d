// The three wall models against the closed form of a bouncing ball.

#include "sim_test_util.h"

#include <QTest>

#include <cmath>

using namespace forcelab;
using namespace forcelab::sim;
using forcelab::test::ballAt;

namespace {

constexpr double kG = 980.0;       // px/s²
constexpr double kFloor = 390.0;   // centre height when the ball (r = 10) touches the floor of a 400 px box
constexpr double kDropY = 100.0;   // start: 290 px above its resting height

Scene dropScene(WallModel model, double restitution, IntegratorKind integrator, double dt)
{
    Scene s;
    s.settings.box = BoxSettings{600.0, 400.0};
    s.settings.walls = WallSettings{true, true, true, true, model, restitution};
    s.settings.gravity.enabled = true;
    s.settings.gravity.g = Vec2(0.0, kG);
    s.settings.time.integrator = integrator;
    s.settings.time.dt = dt;
    s.balls = {ballAt(300.0, kDropY)};
    return s;
}

// Height of the ball's next apex above its resting height, from its energy:
// h = (floor − y) + v_y² / 2g (exact between bounces for a parabola).
double apexHeight(const World& w)
{
    const double y = w.balls().position(1, 0);
    const double vy = w.balls().velocity(1, 0);
    return (kFloor - y) + vy * vy / (2.0 * kG);
}

} // namespace

class TestWalls : public QObject {
    Q_OBJECT
private slots:
    void exactKeepsHeight_data();
    void exactKeepsHeight();
    void exactRestitutionApexes_data();
    void exactRestitutionApexes();
    void clampAndMirrorStayInside_data();
    void clampAndMirrorStayInside();
    void exactWallsKeepEnergyBounded_data();
    void exactWallsKeepEnergyBounded();
    void clampLosesHeight();
    void wallsOffLetBallsLeave();
    void reverseTrapsBallsThatStartOutside();
    void middleWallKeepsSides();
    void centreOnlyLetsBallsSinkIn();
};

void TestWalls::exactKeepsHeight_data()
{
    QTest::addColumn<double>("dt");
    QTest::newRow("1/60") << 1.0 / 60;
    QTest::newRow("1/30") << 1.0 / 30;
    QTest::newRow("1/240") << 1.0 / 240;
}

// e = 1 and exact walls: after 1000 bounces the ball still rises to its drop
// height, within 1e-9 relative.
void TestWalls::exactKeepsHeight()
{
    QFETCH(double, dt);
    World w;
    QVERIFY(!w.reset(dropScene(WallModel::Exact, 1.0, IntegratorKind::Exact, dt)));
    const double h0 = apexHeight(w);
    while (w.totals().wallHits < 1000)
        w.step();
    QCOMPARE(w.totals().wallHits, std::int64_t(1000));
    const double rel = std::abs(apexHeight(w) - h0) / h0;
    qInfo("dt %.4g: after 1000 bounces (t = %.1f s) relative height error %.3g", dt, w.time(), rel);
    QVERIFY2(rel <= 1e-9, qPrintable(QString::number(rel)));
    QVERIFY(w.balls().position(1, 0) <= kFloor);
}

void TestWalls::exactRestitutionApexes_data()
{
    exactKeepsHeight_data();
}

// e = 0.8: each bounce keeps 0.8 of the speed, so 0.64 of the height. The
// apex after the k-th bounce is 0.64^k of the drop height, to 1e-12 of the drop
// height, for the first 20 bounces.
void TestWalls::exactRestitutionApexes()
{
    QFETCH(double, dt);
    World w;
    QVERIFY(!w.reset(dropScene(WallModel::Exact, 0.8, IntegratorKind::Exact, dt)));
    const double h0 = apexHeight(w);
    int checked = 0;
    while (w.totals().wallHits < 20) {
        w.step();
        const auto k = w.totals().wallHits;
        if (k == 0 || k > 20) // late bounces come many to a step (the ball is settling)
            continue;
        const double expected = h0 * std::pow(0.64, static_cast<double>(k));
        const double err = std::abs(apexHeight(w) - expected) / h0;
        QVERIFY2(err <= 1e-12, qPrintable(QString("bounce %1: error %2").arg(k).arg(err)));
        ++checked;
    }
    QVERIFY(checked > 20);
}

void TestWalls::clampAndMirrorStayInside_data()
{
    QTest::addColumn<int>("model");
    QTest::newRow("clamp") << int(WallModel::Clamp);
    QTest::newRow("mirror") << int(WallModel::Mirror);
    QTest::newRow("exact") << int(WallModel::Exact);
}

// A fast ball in a box never ends a step outside it, whichever model.
void TestWalls::clampAndMirrorStayInside()
{
    QFETCH(int, model);
    Scene s = dropScene(static_cast<WallModel>(model), 1.0, IntegratorKind::SemiImplicitEuler, 1.0 / 60);
    s.balls = {ballAt(300, 200, 5000, -3000, 10), ballAt(50, 50, -700, 900, 30)};
    World w;
    QVERIFY(!w.reset(s));
    for (int k = 0; k < 2000; ++k) {
        w.step();
        for (int i = 0; i < 2; ++i) {
            const double r = w.balls().radius[i];
            const Vec2 p = w.balls().position.col(i);
            QVERIFY2(p.x() >= r && p.x() <= 600 - r && p.y() >= r && p.y() <= 400 - r,
                     qPrintable(QString("step %1 ball %2 at (%3, %4)").arg(k).arg(i).arg(p.x()).arg(p.y())));
        }
    }
}

void TestWalls::exactWallsKeepEnergyBounded_data()
{
    QTest::addColumn<int>("integrator");
    QTest::newRow("euler") << int(IntegratorKind::Euler);
    QTest::newRow("semi-implicit-euler") << int(IntegratorKind::SemiImplicitEuler);
    QTest::newRow("verlet") << int(IntegratorKind::Verlet);
    QTest::newRow("rk4") << int(IntegratorKind::Rk4);
    QTest::newRow("yoshida4") << int(IntegratorKind::Yoshida4);
}

// Exact walls with every integrator: the bounce happens on the path the
// integrator itself took through the step (a straight drift for the two
// Euler methods, the parabola for the others), so a ball bouncing with e = 1
// keeps its height. Measured as the largest height error over bounces 1–20
// and over 1–400: it must not keep growing (≤ 1.5×). The higher-order methods
// follow gravity's parabola exactly (1e-12); the Euler methods carry their own
// first-order error, an energy that swings by about g h v per step: h v / H ≈
// 4% of the drop height here, which does not grow.
void TestWalls::exactWallsKeepEnergyBounded()
{
    QFETCH(int, integrator);
    World w;
    QVERIFY(!w.reset(dropScene(WallModel::Exact, 1.0, static_cast<IntegratorKind>(integrator), 1.0 / 60)));
    const double h0 = apexHeight(w);
    double first = 0, all = 0;
    while (w.totals().wallHits < 400) {
        w.step();
        const double err = std::abs(apexHeight(w) - h0) / h0;
        if (w.totals().wallHits <= 20)
            first = std::max(first, err);
        all = std::max(all, err);
    }
    qInfo("%s: largest height error over 20 bounces %.3g, over 400 bounces %.3g", QTest::currentDataTag(), first,
          all);
    const bool firstOrder = integrator == int(IntegratorKind::Euler) ||
                            integrator == int(IntegratorKind::SemiImplicitEuler);
    QVERIFY2(all <= (firstOrder ? 0.05 : 1e-12), qPrintable(QString::number(all)));
    QVERIFY2(all <= 1.5 * first + 1e-12, qPrintable(QString("%1 vs %2").arg(all).arg(first)));
}

// The clamp model forgets the overshoot, and the bounce starts from the floor
// with the speed of the end of the step: the ball does not come back to its
// drop height (the point of curriculum stage 9).
void TestWalls::clampLosesHeight()
{
    World clamp, exact;
    QVERIFY(!clamp.reset(dropScene(WallModel::Clamp, 1.0, IntegratorKind::Exact, 1.0 / 60)));
    QVERIFY(!exact.reset(dropScene(WallModel::Exact, 1.0, IntegratorKind::Exact, 1.0 / 60)));
    const double h0 = apexHeight(clamp);
    while (clamp.totals().wallHits < 10)
        clamp.step();
    while (exact.totals().wallHits < 10)
        exact.step();
    const double clampErr = std::abs(apexHeight(clamp) - h0) / h0;
    const double exactErr = std::abs(apexHeight(exact) - h0) / h0;
    qInfo("after 10 bounces: clamp height error %.3g, exact %.3g", clampErr, exactErr);
    QVERIFY(clampErr > 1e-3);
    QVERIFY(exactErr < 1e-12);
}

void TestWalls::wallsOffLetBallsLeave()
{
    Scene s = dropScene(WallModel::Exact, 1.0, IntegratorKind::Exact, 1.0 / 60);
    s.settings.walls.bottom = false;
    World w;
    QVERIFY(!w.reset(s));
    for (int k = 0; k < 120; ++k)
        w.step();
    QCOMPARE(w.totals().wallHits, std::int64_t(0));
    QVERIFY(w.balls().position(1, 0) > 400.0);
}

// The naive wall flips the velocity whenever the ball is past the wall. A
// ball that starts half outside, moving slowly, flips every step and never
// gets free; clamp puts it back and it leaves.
void TestWalls::reverseTrapsBallsThatStartOutside()
{
    for (WallModel model : {WallModel::Reverse, WallModel::Clamp}) {
        Scene s = dropScene(model, 1.0, IntegratorKind::SemiImplicitEuler, 1.0 / 60);
        s.settings.gravity.enabled = false;
        s.balls = {ballAt(595, 200, 60, 0, 20)}; // centre 15 px beyond its allowed 580
        World w;
        QVERIFY(!w.reset(s));
        int flips = 0;
        double previous = w.balls().velocity(0, 0);
        for (int k = 0; k < 120; ++k) {
            w.step();
            flips += (w.balls().velocity(0, 0) > 0) != (previous > 0);
            previous = w.balls().velocity(0, 0);
        }
        const double x = w.balls().position(0, 0);
        if (model == WallModel::Reverse) {
            QVERIFY2(x > 580 && x < 600, qPrintable(QString::number(x))); // still stuck in the wall
            QVERIFY(flips >= 100);                                         // jittering: a flip nearly every step
        } else {
            QVERIFY2(x < 500, qPrintable(QString::number(x))); // bounced off and travelled away
            QCOMPARE(flips, 1);
        }
    }
}

void TestWalls::middleWallKeepsSides()
{
    Scene s = dropScene(WallModel::Clamp, 1.0, IntegratorKind::SemiImplicitEuler, 1.0 / 60);
    s.settings.gravity.enabled = false;
    s.settings.walls.middle = true;
    s.balls = {ballAt(100, 100, 400, 0, 10), ballAt(500, 300, -400, 0, 10)};
    World w;
    QVERIFY(!w.reset(s));
    for (int k = 0; k < 600; ++k) {
        w.step();
        QVERIFY(w.balls().position(0, 0) <= 290.0);
        QVERIFY(w.balls().position(0, 1) >= 310.0);
    }
    QVERIFY(w.totals().wallHits > 10);
}

// Testing the centre instead of the edge lets a ball sink in by its radius.
void TestWalls::centreOnlyLetsBallsSinkIn()
{
    for (bool centreOnly : {true, false}) {
        Scene s = dropScene(WallModel::Clamp, 1.0, IntegratorKind::SemiImplicitEuler, 1.0 / 60);
        s.settings.gravity.enabled = false;
        s.settings.walls.centreOnly = centreOnly;
        s.balls = {ballAt(300, 200, 300, 0, 40)};
        World w;
        QVERIFY(!w.reset(s));
        double furthest = 0;
        for (int k = 0; k < 300; ++k) {
            w.step();
            furthest = std::max(furthest, w.balls().position(0, 0));
        }
        QCOMPARE(furthest, centreOnly ? 600.0 : 560.0);
    }
}

QTEST_APPLESS_MAIN(TestWalls)
#include "test_walls.moc"
