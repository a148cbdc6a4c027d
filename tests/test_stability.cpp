// The world stops itself before the motion blows up, and says why with the
// fix. Limits are checked against the closed-form stability regions.

#include "sim_test_util.h"

#include "sim/stability.h"

#include <QRegularExpression>
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
    void linearGrowthAtTheLimitIsRefused();
    void messagesNeverContradictThemselves_data();
    void messagesNeverContradictThemselves();
    void dragAsAForceLimitsTheLightestBall();
    void weakDragAndSoftSpringsAreStable();
    void dragLimitWithSubsteps();
    void perFrameAdvisesSubsteps();
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

// Semi-implicit Euler at exactly ω dt = 2: the step matrix [[−3, h], [−4/h, 1]]
// has the double eigenvalue −1 with one eigenvector, so the amplitude grows by
// one swing's worth every step (×707 in 50 s at ω = 10), though |λ| = 1.
// Before, a spectral radius of 1 was taken as stable. Just below the limit
// the eigenvalues are two and on the unit circle: stable.
void TestStability::linearGrowthAtTheLimitIsRefused()
{
    World w;
    QVERIFY(!w.reset(springScene(IntegratorKind::SemiImplicitEuler, 100.0, 0.2)));
    QVERIFY(w.halted());
    qInfo("%s", w.halted()->c_str());
    QVERIFY2(QString::fromStdString(*w.halted()).contains("Lower dt below 0.199 s"), w.halted()->c_str());
    QVERIFY(!w.reset(springScene(IntegratorKind::SemiImplicitEuler, 100.0, 0.199)));
    QVERIFY(!w.halted());
    QVERIFY(!w.reset(springScene(IntegratorKind::Verlet, 100.0, 0.2)));
    QVERIFY(w.halted());
}

void TestStability::messagesNeverContradictThemselves_data()
{
    QTest::addColumn<int>("integrator");
    QTest::addColumn<double>("limit"); // ω h
    QTest::newRow("rk4 at 0.284 (limit 2√2/ω = 0.28284)") << int(IntegratorKind::Rk4) << 2.0 * std::sqrt(2.0);
    QTest::newRow("semi-implicit-euler") << int(IntegratorKind::SemiImplicitEuler) << 2.0;
    QTest::newRow("verlet") << int(IntegratorKind::Verlet) << 2.0;
    // Where the trace of the three Verlet matrices of weights w₁, w₀, w₁
    // reaches 2 (bisection on the product, to 1e-15).
    QTest::newRow("yoshida4") << int(IntegratorKind::Yoshida4) << 1.5734019474345;
}

// ω = 10 rad/s and dt a hair above the limit, at many dt: the message names
// the dt with enough figures to tell it from the advice, and advises a dt
// below the true limit (rounded down, not to the nearest). Before: "unstable
// at dt = 0.284 s … lower dt below 0.284 s" for rk4, whose limit is 0.28284.
void TestStability::messagesNeverContradictThemselves()
{
    QFETCH(int, integrator);
    QFETCH(double, limit);
    const double trueLimit = limit / 10.0;
    // From 0.4% above the limit (rk4's 0.284 s against 0.28284 s) to 10%:
    // near enough that three figures could round onto the limit.
    for (const double above : {1.0041, 1.006, 1.01, 1.03, 1.1}) {
        const double dt = trueLimit * above;
        World w;
        QVERIFY(!w.reset(springScene(static_cast<IntegratorKind>(integrator), 100.0, dt)));
        QVERIFY(w.halted());
        const QString m = QString::fromStdString(*w.halted());
        const QRegularExpression re(QStringLiteral("at dt = ([0-9.e-]+) s.*Lower dt below ([0-9.e-]+) s"));
        const auto match = re.match(m);
        QVERIFY2(match.hasMatch(), qPrintable(m));
        const double said = match.captured(1).toDouble(), advised = match.captured(2).toDouble();
        QVERIFY2(match.captured(1) != match.captured(2), qPrintable(m));
        QVERIFY2(advised < said && advised < trueLimit, qPrintable(m));
        QVERIFY2(std::abs(said / dt - 1.0) < 5e-3, qPrintable(m));
        QVERIFY2(advised > 0.99 * trueLimit, qPrintable(m)); // three figures, not a loose guess
    }
}

// Drag as a force slows a ball by k m₁₀ / m: a ball of a tenth of the
// reference mass has c = 10 k. k = 20 /s at dt = 16 ms is k·dt = 0.32 for a
// 10 px ball, fine, but c·dt = 3.2 > 2 for the light one: semi-implicit Euler
// flips its velocity back and forth, growing. The check sees the lightest ball.
void TestStability::dragAsAForceLimitsTheLightestBall()
{
    Scene s = openScene({ballAt(100, 100, 50, 0), ballAt(200, 100, 50, 0, 10, sphereMass(10) / 10)});
    s.settings.drag = DragSettings{true, DragLaw::Linear, 20.0};
    s.settings.time.dt = 0.016;
    World w;
    QVERIFY(!w.reset(s));
    QVERIFY(w.halted());
    QVERIFY2(QString::fromStdString(*w.halted()).contains("c·dt = 3.2 for the lightest ball"), w.halted()->c_str());
    s.balls.pop_back();
    QVERIFY(!w.reset(s));
    QVERIFY(!w.halted());
    s.settings.drag.scale = ForceScale::None; // the tutorial's drag: every ball c = k
    s.balls.push_back(ballAt(200, 100, 50, 0, 10, sphereMass(10) / 10));
    QVERIFY(!w.reset(s));
    QVERIFY(!w.halted());
    // Scaled by radius, c = k × 10 px / r: a 1 px ball has c = 10 k, and the
    // message names it by its size, not its mass.
    s.settings.drag.scale = ForceScale::Radius;
    s.balls.back() = ballAt(200, 100, 50, 0, 1);
    QVERIFY(!w.reset(s));
    QVERIFY(w.halted());
    QVERIFY2(QString::fromStdString(*w.halted()).contains("(c·dt = 3.2 for the smallest ball, c = k × 10 px / r = 200/s)"),
             w.halted()->c_str());
}

// Weak drag and soft springs barely change the motion in a step, and no
// method grows on them. Before, the test motion's two eigenvalues near 1 were
// taken for one defective eigenvalue ("grows a little more every step, without
// end. Lower dt below 3.1e-10 s") once k ≲ 6e-5 /s or ω ≲ 3e-5 rad/s: a tiny
// drag, or drag as a force on a heavy ball (k m₁₀ / m = 4e-7 /s at m = 1e9),
// halted the world.
void TestStability::weakDragAndSoftSpringsAreStable()
{
    for (const IntegratorKind kind :
         {IntegratorKind::SemiImplicitEuler, IntegratorKind::Verlet, IntegratorKind::Rk4, IntegratorKind::Yoshida4}) {
        for (const double k : {1e-5, 1e-9}) {
            Scene s = openScene({ballAt(100, 100, 50, 0)});
            s.settings.drag = DragSettings{true, DragLaw::Linear, k};
            s.settings.time.integrator = kind;
            World w;
            QVERIFY(!w.reset(s));
            QVERIFY2(!w.halted(), w.halted()->c_str());
        }
        Scene heavy = openScene({ballAt(100, 100, 50, 0, 10, 1e9)});
        heavy.settings.drag = DragSettings{true, DragLaw::Linear, 0.1};
        heavy.settings.time.integrator = kind;
        World w;
        QVERIFY(!w.reset(heavy));
        QVERIFY2(!w.halted(), w.halted()->c_str());
        for (const double k : {1e-10, 1e-14}) {
            QVERIFY(!w.reset(springScene(kind, k, 1.0 / 60)));
            QVERIFY2(!w.halted(), w.halted()->c_str());
        }
    }
}

// Semi-implicit Euler on drag alone: v ← (1 − c h) v grows once c h > 2, so
// with 8 sub-steps the limit is dt = 8 × 2 / c = 0.008 s at c = 2000 /s. The
// advice must say so (before: "Lower dt below 3.65e-07 s", the bisection
// misled by rounding in tr² − 4 det near the double eigenvalue 1).
void TestStability::dragLimitWithSubsteps()
{
    Scene s = openScene({ballAt(100, 100, 50, 0)});
    s.settings.drag = DragSettings{true, DragLaw::Linear, 2000.0};
    s.settings.time.substeps = 8;
    World w;
    QVERIFY(!w.reset(s));
    QVERIFY(w.halted());
    const QString m = QString::fromStdString(*w.halted());
    QVERIFY2(m.contains("(k·h = 4.17, h the sub-step)"), qPrintable(m));
    const auto match = QRegularExpression(QStringLiteral("Lower dt below ([0-9.e-]+) s")).match(m);
    QVERIFY2(match.hasMatch(), qPrintable(m));
    const double advised = match.captured(1).toDouble();
    QVERIFY2(advised <= 0.008 && advised > 0.99 * 0.008, qPrintable(m));
    s.settings.time.dt = advised;
    QVERIFY(!w.reset(s));
    QVERIFY2(!w.halted(), w.halted()->c_str());
}

// Per-frame steps ignore dt: each step is 1/60 s in `substeps` pieces. A
// spring of ω = 1000 rad/s under semi-implicit Euler needs h ≤ 2/ω, so
// n ≥ ω / (60 × 2) = 8.33: 9 sub-steps. Before, the message named the
// ignored dt and advised a dt above it ("at dt = 0.001 s … Lower dt below
// 0.00799 s").
void TestStability::perFrameAdvisesSubsteps()
{
    Scene s = springScene(IntegratorKind::SemiImplicitEuler, 1e6, 0.001);
    s.settings.time.perFrame = true;
    s.settings.time.substeps = 4;
    World w;
    QVERIFY(!w.reset(s));
    QVERIFY(w.halted());
    const QString m = QString::fromStdString(*w.halted());
    QVERIFY2(m.contains("with per-frame steps of 1/60 s (dt is ignored)"), qPrintable(m));
    QVERIFY2(!m.contains("at dt =") && !m.contains("Lower dt"), qPrintable(m));
    QVERIFY2(m.endsWith("Raise substeps to 9 or more"), qPrintable(m));
    s.settings.time.substeps = 9;
    QVERIFY(!w.reset(s));
    QVERIFY(!w.halted());
    s.settings.time.substeps = 8;
    QVERIFY(!w.reset(s));
    QVERIFY(w.halted());
}

QTEST_APPLESS_MAIN(TestStability)
#include "test_stability.moc"
