// The world stops itself before the motion blows up, and says why with the
// fix. Limits are checked against the closed-form stability regions.

#include "sim_test_util.h"

#include "sim/stability.h"

#include <QTest>

#include <cmath>

using namespace forcelab;
using namespace forcelab::sim;
using forcelab::test::ballAt;
using forcelab::test::openScene;

namespace {

Scene springScene(IntegratorKind integrator, double k, double dt)
{
    Scene s = openScene({ballAt(110, 200)});
    s.settings.spring = SpringSettings{true, Vec2(100, 200), k};
    s.settings.time.integrator = integrator;
    s.settings.time.dt = dt;
    return s;
}

bool finiteState(const World& w)
{
    return w.balls().position.allFinite() && w.balls().velocity.allFinite();
}

} // namespace

class TestStability : public QObject {
    Q_OBJECT
private slots:
    void growthMatchesClosedForm();
    void springLimitIsTwoOverOmega_data();
    void springLimitIsTwoOverOmega();
    void dragLimitIsTwoOverK();
    void messagesSayWhyAndTheFix();
    void newSettingsClearTheHalt();
    void runawayIsUndoneAndExplained();
    void closePassWithoutSofteningStaysFinite();
    void adaptiveIntegratorsGiveUpInTime_data();
    void adaptiveIntegratorsGiveUpInTime();
};

// One step of semi-implicit Euler on x'' = −ω² x is [[1 − ω²h², h], [−ω²h, 1]]:
// determinant 1, so |λ| = 1 while ωh ≤ 2. Explicit Euler's eigenvalues are
// 1 ± iωh: |λ| = √(1 + ω²h²) > 1 at every h.
void TestStability::growthMatchesClosedForm()
{
    WorldSettings s;
    s.spring = SpringSettings{true, Vec2(0, 0), 4.0};
    s.time.integrator = IntegratorKind::Euler;
    QCOMPARE(linearGrowthPerStep(s, 0.1), std::sqrt(1.0 + 4.0 * 0.01));
    s.time.integrator = IntegratorKind::SemiImplicitEuler;
    QVERIFY(std::abs(linearGrowthPerStep(s, 0.5) - 1.0) < 1e-12);
    // ωh = 2.5 > 2: λ = (2 − ω²h² ∓ √((2 − ω²h²)² − 4)) / 2, the larger |λ| is 4.
    s.spring.k = 25.0;
    QVERIFY(std::abs(linearGrowthPerStep(s, 0.5) - (4.25 + std::sqrt(4.25 * 4.25 - 4)) / 2) < 1e-12);
}

void TestStability::springLimitIsTwoOverOmega_data()
{
    QTest::addColumn<int>("integrator");
    QTest::addColumn<double>("limit"); // largest stable ω h
    QTest::newRow("semi-implicit-euler") << int(IntegratorKind::SemiImplicitEuler) << 2.0;
    QTest::newRow("verlet") << int(IntegratorKind::Verlet) << 2.0;
    QTest::newRow("rk4") << int(IntegratorKind::Rk4) << 2.0 * std::sqrt(2.0);
}

// ω = 100 rad/s: stable a little below ωh = limit, halted a little above.
void TestStability::springLimitIsTwoOverOmega()
{
    QFETCH(int, integrator);
    QFETCH(double, limit);
    const double omega = 100.0;
    World below, above;
    QVERIFY(!below.reset(springScene(static_cast<IntegratorKind>(integrator), omega * omega, 0.98 * limit / omega)));
    QVERIFY(!above.reset(springScene(static_cast<IntegratorKind>(integrator), omega * omega, 1.02 * limit / omega)));
    QVERIFY(!below.halted());
    QVERIFY(above.halted());
    // Bounded swing: symplectic Euler and Verlet keep an ellipse whose x reach
    // is at most A / √(1 − (ωh/2)²) = 5.03 A at ωh = 0.98 × 2 (A = 10 px).
    double reach = 0;
    for (int k = 0; k < 1000; ++k) {
        below.step();
        reach = std::max(reach, std::abs(below.balls().position(0, 0) - 100.0));
    }
    QVERIFY2(reach <= 10.0 / std::sqrt(1.0 - 0.98 * 0.98) * 1.001, qPrintable(QString::number(reach)));
    above.step();
    QCOMPARE(above.stepCount(), std::int64_t(0)); // halted: nothing moves
    QCOMPARE(above.balls().position(0, 0), 110.0);
}

// Linear drag with explicit or semi-implicit Euler: v ← (1 − k dt) v, which
// flips sign and grows once k dt > 2.
void TestStability::dragLimitIsTwoOverK()
{
    Scene s = openScene({ballAt(100, 100, 50, 0)});
    s.settings.drag = DragSettings{true, DragLaw::Linear, 100.0};
    s.settings.time.dt = 0.019;
    World ok, bad;
    QVERIFY(!ok.reset(s));
    QVERIFY(!ok.halted());
    s.settings.time.dt = 0.021;
    QVERIFY(!bad.reset(s));
    QVERIFY(bad.halted());
    QVERIFY2(QString::fromStdString(*bad.halted()).contains("k·dt = 2.1"), bad.halted()->c_str());
}

void TestStability::messagesSayWhyAndTheFix()
{
    World w;
    QVERIFY(!w.reset(springScene(IntegratorKind::SemiImplicitEuler, 4444.0, 0.05)));
    QVERIFY(w.halted());
    QCOMPARE(QString::fromStdString(*w.halted()),
             QString("semi-implicit-euler is unstable for this spring at dt = 0.05 s (ω = √k = 66.7 rad/s): the "
                     "motion grows more than a million times every second. Lower dt below 0.03 s"));
    // Explicit Euler gains energy on any spring; when it doubles within 10 s
    // it is stopped and verlet is suggested.
    QVERIFY(!w.reset(springScene(IntegratorKind::Euler, 400.0, 1.0 / 60)));
    QVERIFY(w.halted());
    QVERIFY2(QString::fromStdString(*w.halted()).startsWith("euler is unstable for this spring"), w.halted()->c_str());
    QVERIFY2(QString::fromStdString(*w.halted()).endsWith("or pick verlet"), w.halted()->c_str());
}

void TestStability::newSettingsClearTheHalt()
{
    World w;
    QVERIFY(!w.reset(springScene(IntegratorKind::Verlet, 10000.0, 0.05)));
    QVERIFY(w.halted());
    WorldSettings s = w.settings();
    s.time.dt = 0.001;
    QVERIFY(!w.setSettings(s));
    QVERIFY(!w.halted());
    w.step();
    QCOMPARE(w.stepCount(), std::int64_t(1));
}

// An attracting point with no clamp: a ball dropped straight at it gains
// unbounded speed at the centre. The world takes the step back, stops, and
// names the clamp as the fix; the state stays finite.
void TestStability::runawayIsUndoneAndExplained()
{
    Scene s = openScene({ballAt(300, 200.0 + 1e-7, 0, 0)});
    s.settings.point = PointForceSettings{true, PointKind::Attract, Vec2(300, 200), 1e12, 0.0, ForceScale::None};
    World w;
    QVERIFY(!w.reset(s));
    for (int k = 0; k < 100 && !w.halted(); ++k)
        w.step();
    QVERIFY(w.halted());
    QVERIFY(finiteState(w));
    QVERIFY(w.balls().velocity.cwiseAbs().maxCoeff() < 1e12);
    QVERIFY2(QString::fromStdString(*w.halted()).contains("set max_accel"), w.halted()->c_str());
}

// Two bodies on a collision course, mutual gravity with no softening: the
// force never becomes Inf or NaN, and if the pass is too close for dt the
// world stops with softening as the fix.
void TestStability::closePassWithoutSofteningStaysFinite()
{
    Scene s = openScene({ballAt(100, 200, 0, 0, 1, 1e6), ballAt(200, 200, 0, 0, 1, 1e6)});
    s.settings.mutualGravity = MutualGravitySettings{true, 1e6, 0.0};
    World w;
    QVERIFY(!w.reset(s));
    for (int k = 0; k < 2000 && !w.halted(); ++k) {
        w.step();
        QVERIFY(finiteState(w));
        QVERIFY(w.accelerations().allFinite());
    }
    if (w.halted())
        QVERIFY2(QString::fromStdString(*w.halted()).contains("add softening"), w.halted()->c_str());
}

void TestStability::adaptiveIntegratorsGiveUpInTime_data()
{
    QTest::addColumn<int>("integrator");
    QTest::newRow("rk45") << int(IntegratorKind::Rk45);
    QTest::newRow("ias15") << int(IntegratorKind::Ias15);
}

// Three heavy bodies falling together with no softening, at a tight
// tolerance: near the collision an adaptive integrator asks for ever shorter
// sub-steps. It stops after its budget instead of freezing the program, the
// step is undone, and the world says why.
void TestStability::adaptiveIntegratorsGiveUpInTime()
{
    QFETCH(int, integrator);
    Scene s = openScene({ballAt(100, 200, 0, 0, 1, 1e6), ballAt(200, 200, 0, 0, 1, 1e6), ballAt(150, 280, 0, 0, 1, 1e6)});
    s.settings.mutualGravity = MutualGravitySettings{true, 1e9, 0.0};
    s.settings.time.integrator = static_cast<IntegratorKind>(integrator);
    s.settings.time.tolerance = 1e-12;
    World w;
    QVERIFY(!w.reset(s));
    for (int k = 0; k < 600 && !w.halted(); ++k)
        w.step();
    QVERIFY(w.halted());
    QVERIFY(finiteState(w));
    QVERIFY2(QString::fromStdString(*w.halted()).contains("add softening"), w.halted()->c_str());
    QVERIFY(w.lastStep().acceptedSteps + w.lastStep().rejectedSteps <= kMaxAdaptiveSubSteps);
}

QTEST_APPLESS_MAIN(TestStability)
#include "test_stability.moc"
