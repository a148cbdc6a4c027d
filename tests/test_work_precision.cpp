// The work-precision engine (sim/work_precision.h): on a spring, whose
// integrators' orders are known from theory, the fitted orders come out as
// theory says; the reference measured against itself has no error; the
// cancel flag stops a study early.

#include "sim_test_util.h"

#include "sim/names.h"
#include "sim/work_precision.h"
#include "sim/world.h"

#include <QTest>

#include <atomic>
#include <cmath>

using namespace forcelab;
using namespace forcelab::sim;
using forcelab::test::ballAt;
using forcelab::test::openScene;

namespace {

// A ball on a spring to an anchor, ω = 2 rad/s: a smooth problem on which
// every method shows its order.
Scene springScene()
{
    Scene s = openScene({ballAt(400, 200, 0, 120, 10, 1)});
    s.settings.box = BoxSettings{600.0, 400.0};
    s.settings.spring = SpringSettings{true, Vec2(300, 200), 4.0};
    return s;
}

} // namespace

class TestWorkPrecision : public QObject {
    Q_OBJECT
private slots:
    void fittedOrdersMatchTheory_data();
    void fittedOrdersMatchTheory();
    void referenceAgainstItselfHasNoError();
    void errorsAndCostsAreFilledIn();
    void cancelStopsEarly();
    void durationMustBeWholeSteps();
    void fittedOrderOfAPowerLaw();
};

void TestWorkPrecision::fittedOrdersMatchTheory_data()
{
    QTest::addColumn<int>("kind");
    QTest::addColumn<double>("dt");
    // Each method at steps where its error is well above rounding and well
    // below the size of the motion (the asymptotic range of error ≈ C dtᵖ).
    QTest::newRow("euler") << int(IntegratorKind::Euler) << 1.0 / 1024;
    QTest::newRow("semi-implicit-euler") << int(IntegratorKind::SemiImplicitEuler) << 1.0 / 512;
    QTest::newRow("verlet") << int(IntegratorKind::Verlet) << 1.0 / 64;
    QTest::newRow("rk4") << int(IntegratorKind::Rk4) << 1.0 / 16;
    QTest::newRow("yoshida4") << int(IntegratorKind::Yoshida4) << 1.0 / 16;
}

void TestWorkPrecision::fittedOrdersMatchTheory()
{
    QFETCH(int, kind);
    QFETCH(double, dt);
    const auto integrator = static_cast<IntegratorKind>(kind);
    const ConvergenceResult c = measureConvergence(springScene(), integrator, dt, 2.0);
    QVERIFY2(!c.study.error, c.study.error.value_or("").c_str());
    QCOMPARE(c.study.runs.size(), std::size_t(4));
    for (const PrecisionRun& r : c.study.runs)
        qInfo("%s dt=%g error=%.3e px", std::string(toString(integrator)).c_str(), r.dt, r.positionError);
    const double expected = theoreticalOrder(integrator);
    QVERIFY2(std::abs(c.order - expected) <= 0.15,
             qPrintable(QStringLiteral("fitted %1, theory %2").arg(c.order).arg(expected)));
}

void TestWorkPrecision::referenceAgainstItselfHasNoError()
{
    Scene s = springScene();
    WorkPrecisionSettings settings;
    settings.duration = 2.0;
    settings.dts = {1.0 / 64};
    settings.integrators = {IntegratorKind::Ias15};
    s.settings.time.tolerance = settings.referenceTolerance; // the very same run as the reference
    const WorkPrecisionResult r = measureWorkPrecision(s, settings);
    QVERIFY(!r.error);
    QCOMPARE(r.runs.size(), std::size_t(1));
    QVERIFY2(r.runs[0].positionError < 1e-9, qPrintable(QString::number(r.runs[0].positionError)));
    QVERIFY(r.runs[0].energyError < 1e-12);
    // And the reference is close to the closed form x = A cos ωt, y = (v₀/ω) sin ωt.
    World w;
    s.settings.time.integrator = IntegratorKind::Ias15;
    s.settings.time.dt = 1.0 / 64;
    QVERIFY(!w.reset(s));
    for (int k = 0; k < 128; ++k)
        w.step();
    const Vec2 exact = Vec2(300, 200) + Vec2(100 * std::cos(4.0), 60 * std::sin(4.0));
    QVERIFY((w.balls().position.col(0) - exact).norm() < 1e-8);
}

void TestWorkPrecision::errorsAndCostsAreFilledIn()
{
    WorkPrecisionSettings settings;
    settings.duration = 1.0;
    settings.dts = {1.0 / 32, 1.0 / 64};
    settings.integrators = {IntegratorKind::Euler, IntegratorKind::Rk4};
    int calls = 0, lastTotal = 0;
    const WorkPrecisionResult r =
        measureWorkPrecision(springScene(), settings, [&](int done, int total) {
            ++calls;
            QCOMPARE(done, calls);
            lastTotal = total;
        });
    QVERIFY(!r.error && !r.cancelled);
    QCOMPARE(calls, 5);
    QCOMPARE(lastTotal, 5);
    QCOMPARE(r.runs.size(), std::size_t(4));
    // Euler: one evaluation a step; rk4: four.
    QCOMPARE(r.runs[0].forceEvaluations, std::int64_t(32));
    QCOMPARE(r.runs[2].forceEvaluations, std::int64_t(4 * 32));
    // At the same cost rk4 is far more accurate than Euler.
    QVERIFY(r.runs[2].positionError < 1e-3 * r.runs[1].positionError);
    QVERIFY(r.runs[0].energyError > r.runs[2].energyError);

    // On two threads: the same runs, in the same order, with the same numbers.
    settings.threads = 2;
    std::atomic<int> parallelCalls{0};
    const WorkPrecisionResult p =
        measureWorkPrecision(springScene(), settings, [&](int, int) { ++parallelCalls; });
    QCOMPARE(parallelCalls.load(), 5);
    QCOMPARE(p.runs.size(), r.runs.size());
    for (std::size_t i = 0; i < r.runs.size(); ++i) {
        QVERIFY(p.runs[i].integrator == r.runs[i].integrator);
        QCOMPARE(p.runs[i].dt, r.runs[i].dt);
        QCOMPARE(p.runs[i].positionError, r.runs[i].positionError);
        QCOMPARE(p.runs[i].forceEvaluations, r.runs[i].forceEvaluations);
    }
}

void TestWorkPrecision::cancelStopsEarly()
{
    WorkPrecisionSettings settings;
    settings.duration = 1.0;
    settings.dts = {1.0 / 256, 1.0 / 512};
    settings.integrators = {IntegratorKind::Euler, IntegratorKind::Verlet, IntegratorKind::Rk4};
    std::atomic<bool> cancel{false};
    int calls = 0;
    const WorkPrecisionResult r = measureWorkPrecision(
        springScene(), settings,
        [&](int done, int) {
            ++calls;
            if (done == 2)
                cancel = true; // the next run sees it at its first step
        },
        &cancel);
    QVERIFY(r.cancelled);
    QCOMPARE(calls, 2);
    QCOMPARE(r.runs.size(), std::size_t(1));

    // Cancelled before it starts: not even the reference runs.
    const WorkPrecisionResult none = measureWorkPrecision(springScene(), settings, {}, &cancel);
    QVERIFY(none.cancelled);
    QVERIFY(none.runs.empty());
    QCOMPARE(none.reference.forceEvaluations, std::int64_t(0));

    // On two threads both workers stop.
    cancel = false;
    settings.threads = 2;
    settings.duration = 500.0;
    const WorkPrecisionResult both = measureWorkPrecision(
        springScene(), settings, [&](int done, int) { if (done == 1) cancel = true; }, &cancel);
    QVERIFY(both.cancelled);
    QVERIFY(both.runs.empty());
}

void TestWorkPrecision::durationMustBeWholeSteps()
{
    WorkPrecisionSettings settings;
    settings.duration = 1.0;
    settings.dts = {0.3};
    settings.integrators = {IntegratorKind::Euler};
    const WorkPrecisionResult r = measureWorkPrecision(springScene(), settings);
    QVERIFY(r.error);
    QVERIFY(r.runs.empty());
}

void TestWorkPrecision::fittedOrderOfAPowerLaw()
{
    const std::vector<double> dt{0.1, 0.05, 0.025};
    const std::vector<double> err{3 * std::pow(0.1, 3), 3 * std::pow(0.05, 3), 3 * std::pow(0.025, 3)};
    QVERIFY(std::abs(fittedOrder(dt, err) - 3.0) < 1e-12);
    // Unusable errors are left out; one point is not a slope.
    const std::vector<double> bad{0.0, std::nan(""), 1e-3};
    QVERIFY(std::isnan(fittedOrder(dt, bad)));
}

QTEST_APPLESS_MAIN(TestWorkPrecision)
#include "test_work_precision.moc"
