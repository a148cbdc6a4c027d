// Integrators against closed forms: Kepler orbits (convergence order, energy
// behaviour), free fall (exact), and rk45's tolerance.

#include "sim_test_util.h"

#include "sim/integrator_info.h"
#include "sim/stability.h"

#include "sim/kepler.h"

#include "sim/names.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace forcelab;
using namespace forcelab::sim;
using forcelab::test::ballAt;
using forcelab::test::fittedOrder;
using forcelab::test::openScene;

namespace {

// The Kepler orbit of sim/kepler.h: a = 100 px, period 1 s, e = 0.5 unless
// changed, starting at periapsis; its position at any time comes from
// Kepler's equation.
using Kepler = KeplerOrbit;

// Largest relative energy error over `orbits` orbits, sampled every step.
double maxEnergyError(World& world, std::int64_t steps, double e0)
{
    double worst = 0.0;
    for (std::int64_t k = 0; k < steps; ++k) {
        world.step();
        worst = std::max(worst, std::abs((world.energy().total() - e0) / e0));
    }
    return worst;
}

} // namespace

class TestIntegrators : public QObject {
    Q_OBJECT
private slots:
    void keplerOrder_data();
    void keplerOrder();
    void symplecticEnergyBounded_data();
    void symplecticEnergyBounded();
    void rk45MeetsTolerance();
    void exactFreeFall_data();
    void exactFreeFall();
    void exactRejectedWithNonConstantForces();
    void forceEvaluationsPerStep_data();
    void forceEvaluationsPerStep();
    void recordsAgreeWithTheMethods_data();
    void recordsAgreeWithTheMethods();
};

void TestIntegrators::keplerOrder_data()
{
    QTest::addColumn<int>("integrator");
    QTest::addColumn<double>("order");
    QTest::newRow("euler") << int(IntegratorKind::Euler) << 1.0;
    QTest::newRow("semi-implicit-euler") << int(IntegratorKind::SemiImplicitEuler) << 1.0;
    QTest::newRow("verlet") << int(IntegratorKind::Verlet) << 2.0;
    QTest::newRow("rk4") << int(IntegratorKind::Rk4) << 4.0;
    QTest::newRow("yoshida4") << int(IntegratorKind::Yoshida4) << 4.0;
}

// Position error against Kepler's equation at t = 0.30078125 P, for
// dt = P / 2^k, k = 8..12. Not a whole number of orbits: at whole orbits some
// errors cancel and semi-implicit Euler would look second order. Inside the
// first orbit: by 2.3 orbits explicit Euler's error at these steps is the size
// of the orbit itself, no longer in the range where the error shrinks as dt^p.
void TestIntegrators::keplerOrder()
{
    QFETCH(int, integrator);
    QFETCH(double, order);
    const Kepler kepler;
    const double end = 0.30078125 * kepler.period; // a whole number of steps for every dt below
    std::vector<double> dts, errors;
    for (int k = 8; k <= 12; ++k) {
        const double dt = kepler.period / std::ldexp(1.0, k);
        World world;
        QVERIFY(!world.reset(kepler.scene(static_cast<IntegratorKind>(integrator), dt)));
        const auto steps = static_cast<std::int64_t>(std::llround(end / dt));
        for (std::int64_t s = 0; s < steps; ++s)
            world.step();
        QCOMPARE(world.time(), end);
        const double err = (world.balls().position.col(0) - kepler.position(end)).norm();
        QVERIFY(std::isfinite(err));
        dts.push_back(dt);
        errors.push_back(err);
    }
    const double fitted = fittedOrder(dts, errors);
    QCOMPARE(integratorInfo(static_cast<IntegratorKind>(integrator)).order, order);
    qInfo("%s: errors %.3g .. %.3g px, fitted order %.3f", QTest::currentDataTag(), errors.front(), errors.back(),
          fitted);
    QVERIFY2(std::abs(fitted - order) <= 0.15, qPrintable(QString("fitted order %1").arg(fitted)));
}

void TestIntegrators::symplecticEnergyBounded_data()
{
    QTest::addColumn<int>("integrator");
    QTest::addColumn<bool>("symplectic");
    QTest::addColumn<int>("stepsPerOrbit");
    // Explicit Euler needs a small step, or the orbit is destroyed within ten
    // orbits and there is nothing left to drift.
    QTest::newRow("euler") << int(IntegratorKind::Euler) << false << 16384;
    QTest::newRow("semi-implicit-euler") << int(IntegratorKind::SemiImplicitEuler) << true << 512;
    QTest::newRow("verlet") << int(IntegratorKind::Verlet) << true << 512;
    QTest::newRow("rk4") << int(IntegratorKind::Rk4) << false << 512;
    QTest::newRow("yoshida4") << int(IntegratorKind::Yoshida4) << true << 512;
}

// Relative energy error sampled at every step (many times inside each orbit):
// symplectic methods keep it bounded, so its maximum over 100 orbits is at most
// 1.5× the maximum over the first 10; euler and rk4 drift, so it keeps growing.
void TestIntegrators::symplecticEnergyBounded()
{
    QFETCH(int, integrator);
    QFETCH(bool, symplectic);
    QFETCH(int, stepsPerOrbit);
    const Kepler kepler;
    World world;
    QVERIFY(!world.reset(kepler.scene(static_cast<IntegratorKind>(integrator), kepler.period / stepsPerOrbit)));
    const double e0 = world.energy().total();
    const double first10 = maxEnergyError(world, 10 * stepsPerOrbit, e0);
    const double upTo100 = std::max(first10, maxEnergyError(world, 90 * stepsPerOrbit, e0));
    const double growth = upTo100 / first10;
    qInfo("%s: max |dE/E| over 10 orbits %.3g, over 100 orbits %.3g, growth %.2f", QTest::currentDataTag(), first10,
          upTo100, growth);
    if (symplectic)
        QVERIFY2(growth <= 1.5, qPrintable(QString("growth %1").arg(growth)));
    else
        QVERIFY2(growth >= 3.0, qPrintable(QString("growth %1").arg(growth)));
}

// rk45 adapts its sub-steps to keep each one's error below the tolerance, so
// the error after 2.3 orbits (outer steps of P/16) scales with the tolerance:
// measured about 14–20 × tol × a for tol = 1e-6 … 1e-10, asserted ≤ 50 × tol × a.
// A tighter tolerance buys a smaller error with more sub-steps.
void TestIntegrators::rk45MeetsTolerance()
{
    const Kepler kepler;
    double previousError = 1e300;
    std::int64_t previousSteps = 0;
    for (double tol : {1e-6, 1e-8, 1e-10}) {
        Scene s = kepler.scene(IntegratorKind::Rk45, kepler.period / 16);
        s.settings.time.tolerance = tol;
        World world;
        QVERIFY(!world.reset(s));
        for (int k = 0; k < 16 * 2 + 5; ++k)
            world.step();
        const double err = (world.balls().position.col(0) - kepler.position(world.time())).norm();
        const std::int64_t accepted = world.totals().acceptedSteps;
        qInfo("rk45 tol %.0e: error %.3g px, %lld accepted, %lld rejected sub-steps", tol, err,
              static_cast<long long>(accepted), static_cast<long long>(world.totals().rejectedSteps));
        QVERIFY2(err <= 50.0 * tol * kepler.a, qPrintable(QString("error %1 at tol %2").arg(err).arg(tol)));
        QVERIFY(err < previousError);
        QVERIFY(accepted > previousSteps);
        previousError = err;
        previousSteps = accepted;
    }
}

void TestIntegrators::exactFreeFall_data()
{
    QTest::addColumn<double>("dt");
    QTest::newRow("1/30") << 1.0 / 30;
    QTest::newRow("1/60") << 1.0 / 60;
    QTest::newRow("1/1000") << 1.0 / 1000;
}

// y(t) = y0 + vy0 t + ½ g t² exactly (to 1e-12 relative) at every step.
void TestIntegrators::exactFreeFall()
{
    QFETCH(double, dt);
    Scene s = openScene({ballAt(100.0, 50.0, 30.0, -200.0)});
    s.settings.gravity.enabled = true;
    s.settings.gravity.g = Vec2(0.0, 980.0);
    s.settings.time.integrator = IntegratorKind::Exact;
    s.settings.time.dt = dt;
    World world;
    QVERIFY(!world.reset(s));
    for (int k = 0; k < 2.0 / dt; ++k) {
        world.step();
        const double t = world.time();
        const Vec2 expected(100.0 + 30.0 * t, 50.0 - 200.0 * t + 0.5 * 980.0 * t * t);
        const Vec2 got = world.balls().position.col(0);
        QVERIFY2((got - expected).norm() <= 1e-12 * expected.norm(),
                 qPrintable(QString("t=%1: %2 vs %3").arg(t).arg(got.y(), 0, 'g', 17).arg(expected.y(), 0, 'g', 17)));
    }
}

void TestIntegrators::exactRejectedWithNonConstantForces()
{
    Scene s = openScene({ballAt(100.0, 50.0)});
    s.settings.time.integrator = IntegratorKind::Exact;
    s.settings.drag.enabled = true;
    World world;
    const auto error = world.reset(s);
    QVERIFY(error);
    QCOMPARE(QString::fromStdString(toString(*error)),
             QString("time.integrator: exact needs a constant acceleration, but drag depends on velocity; "
                     "pick another integrator or switch that model off"));
    // Pushed live, the world keeps its old settings.
    World running;
    QVERIFY(!running.reset(openScene({ballAt(1, 1)})));
    WorldSettings edited = running.settings();
    edited.time.integrator = IntegratorKind::Exact;
    edited.spring.enabled = true;
    QVERIFY(running.setSettings(edited));
    QVERIFY(running.settings().time.integrator == IntegratorKind::SemiImplicitEuler);
}

void TestIntegrators::forceEvaluationsPerStep_data()
{
    QTest::addColumn<int>("integrator");
    QTest::addColumn<int>("evaluationsFor10Steps");
    // Verlet-type methods reuse the last acceleration: one extra at the start.
    QTest::newRow("euler") << int(IntegratorKind::Euler) << 10;
    QTest::newRow("semi-implicit-euler") << int(IntegratorKind::SemiImplicitEuler) << 10;
    QTest::newRow("verlet") << int(IntegratorKind::Verlet) << 11;
    QTest::newRow("rk4") << int(IntegratorKind::Rk4) << 40;
    QTest::newRow("yoshida4") << int(IntegratorKind::Yoshida4) << 31;
}

void TestIntegrators::forceEvaluationsPerStep()
{
    QFETCH(int, integrator);
    QFETCH(int, evaluationsFor10Steps);
    const Kepler kepler;
    World world;
    QVERIFY(!world.reset(kepler.scene(static_cast<IntegratorKind>(integrator), kepler.period / 256)));
    for (int k = 0; k < 10; ++k)
        world.step();
    QCOMPARE(world.totals().forceEvaluations, std::int64_t(evaluationsFor10Steps));
    // The integrator's record says the same, give or take the one extra
    // evaluation that starts a Verlet-type run.
    const int perStep = integratorInfo(static_cast<IntegratorKind>(integrator)).evaluationsPerStep;
    QVERIFY(evaluationsFor10Steps == 10 * perStep || evaluationsFor10Steps == 10 * perStep + 1);
}

void TestIntegrators::recordsAgreeWithTheMethods_data()
{
    QTest::addColumn<int>("integrator");
    for (const IntegratorInfo& info : integrators())
        QTest::addRow("%s", info.name.data()) << int(info.kind);
}

// Each integrator's record (sim/integrator_info.h) against the method itself:
// its name round-trips; its spring limit is where one step's growth on
// x'' = −ω² x (sim/stability.h, the eigenvalues of the step matrix) crosses 1,
// within 1e-3 of ω h on either side; explicit Euler grows at any h; the
// fitted Kepler orders (keplerOrder) match the recorded ones.
void TestIntegrators::recordsAgreeWithTheMethods()
{
    QFETCH(int, integrator);
    const IntegratorInfo& info = integratorInfo(static_cast<IntegratorKind>(integrator));
    QCOMPARE(int(info.kind), integrator);
    QVERIFY(parseIntegrator(info.name) == info.kind);
    QCOMPARE(toString(info.kind), info.name);
    if (info.adaptive || info.kind == IntegratorKind::Exact) {
        QVERIFY(std::isinf(info.springLimit));
        return;
    }
    WorldSettings s;
    s.time.integrator = info.kind;
    s.spring = SpringSettings{true, Vec2(0, 0), 1.0}; // ω = 1, so ω h = h
    if (info.springLimit == 0.0) {
        QVERIFY(linearGrowthPerStep(s, 1e-3) > 1.0);
        return;
    }
    const double below = linearGrowthPerStep(s, info.springLimit * (1.0 - 1e-3));
    const double above = linearGrowthPerStep(s, info.springLimit * (1.0 + 1e-3));
    qInfo("%s: growth per step %.12f at 0.999 of ω h = %.4f, %.6f at 1.001", info.name.data(), below,
          info.springLimit, above);
    QVERIFY(below <= 1.0 + 1e-12);
    QVERIFY(above > 1.0 + 1e-6);
}

QTEST_APPLESS_MAIN(TestIntegrators)
#include "test_integrators.moc"
