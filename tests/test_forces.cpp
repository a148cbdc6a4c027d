// Each force model's direction and magnitude on a hand-computed case, the
// invariants of mutual gravity, the wind modes and the settings checks.

#include "sim_test_util.h"

#include "sim/names.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace forcelab;
using namespace forcelab::sim;
using forcelab::test::ballAt;
using forcelab::test::openScene;

namespace {

// Acceleration of ball i in a world built from this scene.
Vec2 accelerationOf(const Scene& s, int i = 0)
{
    World w;
    const auto error = w.reset(s);
    if (error)
        qFatal("%s", toString(*error).c_str());
    return w.accelerations().col(i);
}

bool near(const Vec2& a, const Vec2& b, double tol = 1e-12)
{
    return (a - b).norm() <= tol * std::max(1.0, b.norm());
}

#define QCOMPARE_VEC(a, b)                                                                                            \
    QVERIFY2(near(a, b), qPrintable(QString("(%1, %2) vs (%3, %4)")                                                   \
                                        .arg((a).x(), 0, 'g', 17)                                                     \
                                        .arg((a).y(), 0, 'g', 17)                                                     \
                                        .arg((b).x(), 0, 'g', 17)                                                     \
                                        .arg((b).y(), 0, 'g', 17)))

} // namespace

class TestForces : public QObject {
    Q_OBJECT
private slots:
    void noModelsNoAcceleration();
    void uniformGravity();
    void linearDrag();
    void quadraticDrag();
    void pointForce();
    void pointForceScaledByMass();
    void spring();
    void homing();
    void mutualGravityPair();
    void mutualGravityConservesMomentum();
    void negativeGravityRepels();
    void coincidentCentresStayFinite();
    void windScaling();
    void windModes();
    void pointerAttractsAndRepels();
    void speedLimit();
    void defaultMassIsEqualDensitySphere();
    void settingsChecks_data();
    void settingsChecks();
    void namesRoundTrip();
    void spawnIsDeterministicAndInside();
    void spawnOverTime();
    void perFrameIgnoresDt();
    void randomAcceleration();
    void compareWindActsOnNothing();
    void dragIsAForce_data();
    void dragIsAForce();
    void sourcesAddUpToTheAcceleration();
};

void TestForces::noModelsNoAcceleration()
{
    QCOMPARE_VEC(accelerationOf(openScene({ballAt(1, 2, 3, 4)})), Vec2(0, 0));
}

void TestForces::uniformGravity()
{
    Scene s = openScene({ballAt(1, 2)});
    s.settings.gravity.enabled = true;
    s.settings.gravity.g = Vec2(-3, 980);
    QCOMPARE_VEC(accelerationOf(s), Vec2(-3, 980));
}

void TestForces::linearDrag()
{
    // a = −k v: k = 0.5 /s, v = (10, −20) px/s → (−5, 10) px/s².
    Scene s = openScene({ballAt(0, 0, 10, -20)});
    s.settings.drag = DragSettings{true, DragLaw::Linear, 0.5};
    QCOMPARE_VEC(accelerationOf(s), Vec2(-5, 10));
    // Over time, v(t) = v0 e^(−kt). rk4's error per step is about (k dt)^5 / 120
    // of v, 3e-14 here, so 200 steps stay within 1e-10.
    s.settings.time.integrator = IntegratorKind::Rk4;
    s.settings.time.dt = 0.01;
    World w;
    QVERIFY(!w.reset(s));
    for (int k = 0; k < 200; ++k)
        w.step();
    QVERIFY(near(w.balls().velocity.col(0), Vec2(10, -20) * std::exp(-0.5 * w.time()), 1e-10));
}

void TestForces::quadraticDrag()
{
    // a = −k |v| v: k = 0.01 /px, v = (3, 4), |v| = 5 → (−0.15, −0.2).
    Scene s = openScene({ballAt(0, 0, 3, 4)});
    s.settings.drag = DragSettings{true, DragLaw::Quadratic, 0.01};
    QCOMPARE_VEC(accelerationOf(s), Vec2(-0.15, -0.2));
}

void TestForces::pointForce()
{
    // Ball at (30, 40) from the point: d = 50, |a| = S / d² = 1e6 / 2500 = 400,
    // along (0.6, 0.8): repel (240, 320), attract (−240, −320).
    Scene s = openScene({ballAt(130, 240)});
    s.settings.point.enabled = true;
    s.settings.point.position = Vec2(100, 200);
    s.settings.point.strength = 1e6;
    s.settings.point.maxAccel = 0.0;
    s.settings.point.kind = PointKind::Repel;
    QCOMPARE_VEC(accelerationOf(s), Vec2(240, 320));
    s.settings.point.kind = PointKind::Attract;
    QCOMPARE_VEC(accelerationOf(s), Vec2(-240, -320));
    // The clamp caps |a| at 100 without turning it.
    s.settings.point.maxAccel = 100;
    QCOMPARE_VEC(accelerationOf(s), Vec2(-60, -80));
}

void TestForces::pointForceScaledByMass()
{
    // With mass scaling the force is the reference ball's: a 20 px ball has 8×
    // the mass of a 10 px one, so 1/8 of the acceleration; a 5 px ball 8×.
    Scene s = openScene({ballAt(130, 240, 0, 0, 10), ballAt(130, 240, 0, 0, 20), ballAt(130, 240, 0, 0, 5)});
    s.settings.point = PointForceSettings{true, PointKind::Repel, Vec2(100, 200), 1e6, 0.0, ForceScale::Mass};
    QCOMPARE_VEC(accelerationOf(s, 0), Vec2(240, 320));
    QCOMPARE_VEC(accelerationOf(s, 1), Vec2(30, 40));
    QCOMPARE_VEC(accelerationOf(s, 2), Vec2(1920, 2560));
    s.settings.point.scale = ForceScale::Radius;
    QCOMPARE_VEC(accelerationOf(s, 1), Vec2(120, 160));
}

void TestForces::spring()
{
    // a = −k (x − anchor) = −4 (3, 4) = (−12, −16); period 2π/√k = π s.
    Scene s = openScene({ballAt(103, 204)});
    s.settings.spring = SpringSettings{true, Vec2(100, 200), 4.0};
    QCOMPARE_VEC(accelerationOf(s), Vec2(-12, -16));
    s.settings.time.integrator = IntegratorKind::Rk4;
    s.settings.time.dt = std::numbers::pi / 1000;
    World w;
    QVERIFY(!w.reset(s));
    for (int k = 0; k < 500; ++k) // half a period: the ball is on the other side
        w.step();
    QCOMPARE_VEC(Vec2(w.balls().position.col(0)), Vec2(97, 196));
}

void TestForces::homing()
{
    Scene s = openScene({ballAt(10, 20)});
    s.settings.homing = HomingSettings{true, 2.0};
    World w;
    QVERIFY(!w.reset(s));
    w.mutableBalls().home.col(0) = Vec2(40, 60);
    QCOMPARE_VEC(Vec2(w.accelerations().col(0)), Vec2(60, 80));
}

void TestForces::mutualGravityPair()
{
    // F = G m1 m2 r / (r² + ε²)^(3/2): G = 1000, m1 = 2, m2 = 6, r = 10, ε = 0 →
    // a1 = G m2 / r² = 60 towards ball 2, a2 = G m1 / r² = 20 towards ball 1.
    Scene s = openScene({ballAt(0, 0, 0, 0, 1, 2), ballAt(10, 0, 0, 0, 1, 6)});
    s.settings.mutualGravity = MutualGravitySettings{true, 1000.0, 0.0};
    QCOMPARE_VEC(accelerationOf(s, 0), Vec2(60, 0));
    QCOMPARE_VEC(accelerationOf(s, 1), Vec2(-20, 0));
    // Plummer softening ε = 10: r / (r² + ε²)^(3/2) = 10 / 200^(3/2), which is
    // 1/(2√2) of 1/r²: a1 = 60 / (2√2) = 21.2132.
    s.settings.mutualGravity.softening = 10.0;
    QCOMPARE_VEC(accelerationOf(s, 0), Vec2(60.0 / (2.0 * std::sqrt(2.0)), 0));
    // At r = 0.01 ≪ ε the pull fades to almost nothing instead of staying at
    // G m2 / ε² (which the old law kept, flipping its direction through r = 0):
    // G m2 r / ε³ = 1000 · 6 · 0.01 / 1000 = 0.06 (to 1e-5 relative).
    Scene close = openScene({ballAt(0, 0, 0, 0, 1, 2), ballAt(0.01, 0, 0, 0, 1, 6)});
    close.settings.mutualGravity = MutualGravitySettings{true, 1000.0, 10.0};
    QVERIFY(std::abs(accelerationOf(close, 0).x() - 0.06) <= 1e-5 * 0.06);
}

// Each pair is computed once and applied to both with opposite signs: total
// momentum does not change (1e-12 relative to Σ m|v|), and with softening the
// total energy is conserved to the integrator's accuracy.
void TestForces::mutualGravityConservesMomentum()
{
    Scene s = openScene({});
    s.settings.mutualGravity = MutualGravitySettings{true, 10.0, 20.0};
    s.settings.time.integrator = IntegratorKind::Verlet;
    s.settings.time.dt = 1.0 / 600;
    s.spawn.count = 20;
    s.spawn.minSpeed = 0;
    s.spawn.maxSpeed = 50;
    World w;
    QVERIFY(!w.reset(s));
    const Vec2 p0 = w.momentum();
    const double scale = w.balls().mass.dot(w.balls().velocity.colwise().norm().transpose());
    const double e0 = w.energy().total();
    for (int k = 0; k < 1000; ++k)
        w.step();
    const double drift = (w.momentum() - p0).norm() / scale;
    const double energyDrift = std::abs(w.energy().total() - e0) / std::abs(e0);
    qInfo("momentum drift %.3g (relative to sum m|v|), energy drift %.3g", drift, energyDrift);
    QVERIFY2(drift <= 1e-12, qPrintable(QString::number(drift)));
    QVERIFY2(energyDrift <= 1e-5, qPrintable(QString::number(energyDrift))); // measured 1.2e-7
}

void TestForces::negativeGravityRepels()
{
    Scene s = openScene({ballAt(0, 0, 0, 0, 1, 2), ballAt(10, 0, 0, 0, 1, 6)});
    s.settings.mutualGravity = MutualGravitySettings{true, -1000.0, 0.0};
    QCOMPARE_VEC(accelerationOf(s, 0), Vec2(-60, 0));
}

void TestForces::coincidentCentresStayFinite()
{
    Scene s = openScene({ballAt(5, 5), ballAt(5, 5)});
    s.settings.mutualGravity = MutualGravitySettings{true, 1000.0, 0.0};
    s.settings.point = PointForceSettings{true, PointKind::Attract, Vec2(5, 5), 1e6, 0.0, ForceScale::None};
    World w;
    QVERIFY(!w.reset(s));
    QVERIFY(w.accelerations().allFinite());
    QVERIFY(std::isfinite(w.energy().total()));
}

void TestForces::windScaling()
{
    // Random wind w per step; a reference ball (r = 10) gets w whatever the
    // scaling, a 20 px ball w/2 (radius) or w/8 (mass).
    Scene s = openScene({ballAt(0, 0, 0, 0, 10), ballAt(0, 0, 0, 0, 20)});
    s.settings.wind.mode = WindMode::Random;
    s.settings.wind.strength = 50;
    for (ForceScale scale : {ForceScale::None, ForceScale::Radius, ForceScale::Mass}) {
        s.settings.wind.scale = scale;
        World w;
        QVERIFY(!w.reset(s));
        w.step();
        const double wind = w.wind();
        QVERIFY(wind != 0.0 && std::abs(wind) <= 50);
        const Matrix2X a = w.accelerations();
        const double factor = scale == ForceScale::None ? 1.0 : scale == ForceScale::Radius ? 0.5 : 0.125;
        QCOMPARE(a(0, 0), wind);
        QCOMPARE(a(0, 1), wind * factor);
        QCOMPARE(a(1, 0), 0.0);
    }
}

void TestForces::windModes()
{
    Scene s = openScene({ballAt(0, 0)});
    s.settings.wind.strength = 50;
    // Random: a fresh value in [−50, 50] every step, centred on zero.
    s.settings.wind.mode = WindMode::Random;
    World random;
    QVERIFY(!random.reset(s));
    double sum = 0, largestJump = 0, previous = 0;
    const int n = 4000;
    for (int k = 0; k < n; ++k) {
        random.step();
        QVERIFY(std::abs(random.wind()) <= 50);
        sum += random.wind();
        if (k)
            largestJump = std::max(largestJump, std::abs(random.wind() - previous));
        previous = random.wind();
    }
    // Mean of n uniform values on [−50, 50]: standard deviation 50/√(3n) ≈ 0.46; 5σ.
    QVERIFY2(std::abs(sum / n) < 2.3, qPrintable(QString::number(sum / n)));
    QVERIFY(largestJump > 50);
    // Smoothed: never more than 10% of the strength per step, never beyond it.
    s.settings.wind.mode = WindMode::Smoothed;
    World smoothed;
    QVERIFY(!smoothed.reset(s));
    previous = 0;
    for (int k = 0; k < n; ++k) {
        smoothed.step();
        QVERIFY(std::abs(smoothed.wind() - previous) <= 5.0 + 1e-12);
        QVERIFY(std::abs(smoothed.wind()) <= 50);
        previous = smoothed.wind();
    }
    // Noise: continuous in time, bounded by the strength.
    s.settings.wind.mode = WindMode::Noise;
    s.settings.time.integrator = IntegratorKind::Rk4;
    World noise;
    QVERIFY(!noise.reset(s));
    double prevA = noise.accelerations()(0, 0), maxStep = 0, maxAbs = 0;
    for (int k = 0; k < n; ++k) {
        noise.step();
        const double a = noise.accelerations()(0, 0);
        maxStep = std::max(maxStep, std::abs(a - prevA));
        maxAbs = std::max(maxAbs, std::abs(a));
        prevA = a;
    }
    QVERIFY(maxAbs <= 50 && maxAbs > 10);
    QVERIFY2(maxStep < 3.0, qPrintable(QString::number(maxStep))); // smooth: small change per 1/60 s
    // The same seed gives the same wind.
    World again;
    QVERIFY(!again.reset(s));
    for (int k = 0; k < n; ++k)
        again.step();
    QCOMPARE(again.accelerations()(0, 0), noise.accelerations()(0, 0));
    // Pointer: left of centre blows right, proportionally; outside the canvas, none.
    s.settings.wind.mode = WindMode::Pointer;
    World pointer;
    QVERIFY(!pointer.reset(s));
    pointer.setPointer(PointerInput{true, false, Vec2(150, 10)}); // a quarter from the left of 600 px
    pointer.step();
    QCOMPARE(pointer.wind(), 25.0);
    pointer.setPointer(PointerInput{false, false, Vec2(150, 10)});
    pointer.step();
    QCOMPARE(pointer.wind(), 0.0);
}

void TestForces::pointerAttractsAndRepels()
{
    Scene s = openScene({ballAt(130, 240)});
    s.settings.pointer = PointerSettings{true, 1e6, 0.0};
    World w;
    QVERIFY(!w.reset(s));
    QCOMPARE_VEC(Vec2(w.accelerations().col(0)), Vec2(0, 0)); // pointer not over the canvas
    w.setPointer(PointerInput{true, false, Vec2(100, 200)});
    QCOMPARE_VEC(Vec2(w.accelerations().col(0)), Vec2(-240, -320));
    w.setPointer(PointerInput{true, true, Vec2(100, 200)});
    QCOMPARE_VEC(Vec2(w.accelerations().col(0)), Vec2(240, 320));
}

void TestForces::speedLimit()
{
    Scene s = openScene({ballAt(0, 0, 300, 400), ballAt(0, 0, 3, 4)});
    s.settings.speedLimit = SpeedLimitSettings{true, 100.0};
    World w;
    QVERIFY(!w.reset(s));
    w.step();
    QCOMPARE_VEC(Vec2(w.balls().velocity.col(0)), Vec2(60, 80));
    QCOMPARE_VEC(Vec2(w.balls().velocity.col(1)), Vec2(3, 4));
}

void TestForces::defaultMassIsEqualDensitySphere()
{
    World w;
    QVERIFY(!w.reset(openScene({ballAt(0, 0, 0, 0, 3), ballAt(0, 0, 0, 0, 3, 7.5)})));
    QCOMPARE(w.balls().mass[0], 4.0 / 3.0 * std::numbers::pi * 27.0);
    QCOMPARE(w.balls().mass[1], 7.5);
    QCOMPARE(w.balls().inverseMass[1], 1.0 / 7.5);
}

void TestForces::settingsChecks_data()
{
    QTest::addColumn<int>("which");
    QTest::addColumn<QString>("message");
    // The messages the lesson loader gives for the same values, units included
    // (both come from the rows of sim/parameters.h).
    QTest::newRow("dt zero") << 0 << "time.dt: 0 is outside (0, 1] s";
    QTest::newRow("NaN gravity") << 1 << "models.gravity.y: nan is not a finite number";
    QTest::newRow("restitution") << 2 << "world.restitution: 1.5 is outside [0, 1]";
    QTest::newRow("substeps") << 3 << "time.substeps: 0 is outside [1, 1000]";
    QTest::newRow("negative drag") << 4 << "models.drag.k: -1 is outside [0, 1000000] 1/s (linear) or 1/px (quadratic)";
    QTest::newRow("infinite G") << 5 << "models.mutual_gravity.G: inf is not a finite number";
}

void TestForces::settingsChecks()
{
    QFETCH(int, which);
    QFETCH(QString, message);
    World w;
    QVERIFY(!w.reset(openScene({ballAt(1, 1)})));
    const WorldSettings before = w.settings();
    WorldSettings s = before;
    switch (which) {
    case 0: s.time.dt = 0; break;
    case 1: s.gravity.g.y() = std::nan(""); break;
    case 2: s.walls.restitution = 1.5; break;
    case 3: s.time.substeps = 0; break;
    case 4: s.drag.k = -1; break;
    case 5: s.mutualGravity.G = INFINITY; break;
    }
    const auto error = w.setSettings(s);
    QVERIFY(error);
    QCOMPARE(QString::fromStdString(toString(*error)), message);
    QCOMPARE(w.settings().time.dt, before.time.dt); // refused whole: nothing changed
    QCOMPARE(w.settings().walls.restitution, before.walls.restitution);
}

void TestForces::namesRoundTrip()
{
    for (auto name : integratorNames())
        QCOMPARE(toString(*parseIntegrator(name)), name);
    for (auto name : responseNames())
        QCOMPARE(toString(*parseResponse(name)), name);
    QVERIFY(!parseWindMode("gust"));
    QCOMPARE(QString::fromStdString(joinNames(windModeNames())), QString("off, random, smoothed, noise, pointer"));
}

void TestForces::spawnIsDeterministicAndInside()
{
    Scene s = openScene({});
    s.spawn.count = 500;
    s.spawn.seed = 42;
    const BallState a = buildBalls(s), b = buildBalls(s);
    QCOMPARE(a.size(), 500);
    QVERIFY(a.position == b.position && a.velocity == b.velocity && a.radius == b.radius);
    for (int i = 0; i < a.size(); ++i) {
        const double r = a.radius[i];
        QVERIFY(r >= 4 && r <= 12);
        QVERIFY(a.position(0, i) >= r && a.position(0, i) <= 600 - r);
        QVERIFY(a.position(1, i) >= r && a.position(1, i) <= 400 - r);
        QVERIFY(a.velocity.col(i).norm() <= 300);
    }
    s.spawn.seed = 43;
    QVERIFY(buildBalls(s).position != a.position);
}

// One ball appears with probability perStep each step: over 3000 steps at
// 0.1 the count is binomial, mean 300, standard deviation 16.4; ±5σ.
void TestForces::spawnOverTime()
{
    Scene s = openScene({});
    s.spawn.perStep = 0.1;
    s.spawn.maxCount = 100000;
    s.spawn.horizontal = true;
    World w;
    QVERIFY(!w.reset(s));
    for (int k = 0; k < 3000; ++k)
        w.step();
    const int n = w.balls().size();
    QVERIFY2(std::abs(n - 300) <= 82, qPrintable(QString::number(n)));
    QVERIFY((w.balls().velocity.row(1).array() == 0.0).all()); // horizontal only
    s.spawn.maxCount = 5;
    QVERIFY(!w.reset(s));
    for (int k = 0; k < 3000; ++k)
        w.step();
    QCOMPARE(w.balls().size(), 5);
}

// With dt the distance travelled in 1 s is the same at 30, 60 or 144 steps a
// second; per frame it is proportional to the number of frames.
void TestForces::perFrameIgnoresDt()
{
    for (bool perFrame : {false, true}) {
        for (int rate : {30, 60, 144}) {
            Scene s = openScene({ballAt(0, 0, 120, 0)});
            s.settings.time.dt = 1.0 / rate;
            s.settings.time.perFrame = perFrame;
            World w;
            QVERIFY(!w.reset(s));
            for (int k = 0; k < rate; ++k)
                w.step();
            const double expected = perFrame ? 120.0 * rate / 60.0 : 120.0;
            QVERIFY2(std::abs(w.balls().position(0, 0) - expected) < 1e-9,
                     qPrintable(QString("%1 Hz: %2").arg(rate).arg(w.balls().position(0, 0))));
        }
    }
}

// A fixed random acceleration per ball never changes; a per-step one does and
// averages out: after 3600 steps the fixed kind's speed is a t (thousands of
// px/s), the per-step kind's a random walk: each component has a spread of
// strength × dt × √(n/3) ≈ 58 px/s, so the mean speed is about 72 px/s.
void TestForces::randomAcceleration()
{
    Scene s = openScene({ballAt(0, 0), ballAt(0, 0), ballAt(0, 0), ballAt(0, 0)});
    s.settings.randomAccel = RandomAccelSettings{true, true, 100.0};
    World fixed;
    QVERIFY(!fixed.reset(s));
    fixed.step();
    const Matrix2X first = fixed.accelerations();
    for (int k = 0; k < 3599; ++k)
        fixed.step();
    QVERIFY(fixed.accelerations() == first);
    QVERIFY((first.array().abs() <= 100.0).all());
    s.settings.randomAccel.fixed = false;
    World perStep;
    QVERIFY(!perStep.reset(s));
    for (int k = 0; k < 3600; ++k)
        perStep.step();
    const double fixedSpeed = fixed.balls().velocity.colwise().norm().mean();
    const double walkSpeed = perStep.balls().velocity.colwise().norm().mean();
    qInfo("mean speed after 60 s: fixed %.1f px/s, per step %.1f px/s", fixedSpeed, walkSpeed);
    QVERIFY(fixedSpeed > 1000.0);
    QVERIFY(walkSpeed < 250.0);
}

void TestForces::compareWindActsOnNothing()
{
    Scene s = openScene({ballAt(0, 0)});
    s.settings.wind.mode = WindMode::Off;
    s.settings.wind.compare = WindMode::Random;
    World w;
    QVERIFY(!w.reset(s));
    bool moved = false;
    for (int k = 0; k < 10; ++k) {
        w.step();
        moved = moved || w.compareWind() != 0.0;
    }
    QVERIFY(moved);
    QCOMPARE(w.balls().velocity(0, 0), 0.0);
}

void TestForces::dragIsAForce_data()
{
    QTest::addColumn<int>("law");
    QTest::addColumn<int>("scale");
    QTest::newRow("linear, force") << int(DragLaw::Linear) << int(ForceScale::Mass);
    QTest::newRow("quadratic, force") << int(DragLaw::Quadratic) << int(ForceScale::Mass);
    QTest::newRow("linear, radius") << int(DragLaw::Linear) << int(ForceScale::Radius);
    QTest::newRow("quadratic, radius") << int(DragLaw::Quadratic) << int(ForceScale::Radius);
    QTest::newRow("linear, tutorial (none)") << int(DragLaw::Linear) << int(ForceScale::None);
    QTest::newRow("quadratic, tutorial (none)") << int(DragLaw::Quadratic) << int(ForceScale::None);
}

// Balls of mass 1 and 50 (radius 10) and spheres of radius 5 and 20 (mass
// m₁₀/8 and 8 m₁₀) fall from rest under g = 980 px/s² with drag k = 0.001.
// As a force, F = −k m₁₀ v (m₁₀ = 4188.79, the 10 px ball's mass) gives each
// ball its own rate c = k m₁₀ / m (scale radius: c = k × 10 px / r):
//   linear:    v(t) = v_t (1 − e^(−c t)),  v_t = g / c = g m / (k m₁₀);
//   quadratic: v(t) = v_t tanh(g t / v_t), v_t = √(g / c) = √(g m / (k m₁₀)).
// So the heavy ball falls faster: before, every ball had c = k (the tutorial's
// model, scale "none"), and all fell identically. rk4 at dt = 1/600 s for
// 2 s, within 1e-8 of v_t or of g t, whichever is smaller.
void TestForces::dragIsAForce()
{
    QFETCH(int, law);
    QFETCH(int, scale);
    Scene s = openScene({ballAt(100, 0, 0, 0, 10, 1.0), ballAt(200, 0, 0, 0, 10, 50.0), ballAt(300, 0, 0, 0, 5),
                         ballAt(400, 0, 0, 0, 20)});
    s.settings.gravity.enabled = true;
    s.settings.drag = DragSettings{true, static_cast<DragLaw>(law), 0.001, static_cast<ForceScale>(scale)};
    s.settings.time.integrator = IntegratorKind::Rk4;
    s.settings.time.dt = 1.0 / 600;
    World w;
    QVERIFY(!w.reset(s));
    for (int k = 0; k < 1200; ++k)
        w.step();
    const double g = 980.0, t = w.time();
    double speed[4];
    for (int i = 0; i < 4; ++i) {
        const double m = w.balls().mass[i], r = w.balls().radius[i];
        const double c = scale == int(ForceScale::Mass)     ? 0.001 * sphereMass(10.0) / m
                         : scale == int(ForceScale::Radius) ? 0.001 * 10.0 / r
                                                            : 0.001;
        const double vt = law == int(DragLaw::Linear) ? g / c : std::sqrt(g / c);
        const double expected = law == int(DragLaw::Linear) ? vt * -std::expm1(-c * t) : vt * std::tanh(g * t / vt);
        speed[i] = w.balls().velocity(1, i);
        qInfo("r %g, mass %g: v = %.9g px/s, closed form %.9g (terminal %.6g)", r, m, speed[i], expected, vt);
        // The scale of the speed is v_t or, for balls drag hardly slows, g t.
        QVERIFY2(std::abs(speed[i] - expected) <= 1e-8 * std::min(vt, g * t),
                 qPrintable(QString::number(speed[i] - expected)));
    }
    if (scale == int(ForceScale::Mass)) {
        QVERIFY(speed[1] > 2.0 * speed[0]); // the heavy ball falls faster through air
        QVERIFY(speed[3] > speed[2]);
    } else if (scale == int(ForceScale::Radius)) {
        QCOMPARE(speed[1], speed[0]); // the same size: the same drag whatever the mass
        QVERIFY(speed[3] > speed[2]);
    } else {
        for (int i = 1; i < 4; ++i)
            QCOMPARE(speed[i], speed[0]); // the tutorial's drag ignores mass and size
    }
}

// Every model on at once (wind, random values and the pointer from the
// world's own inputs after a step): the per-source accelerations the
// Inspector shows add up to the acceleration the step uses, to rounding, and
// name each model that is on once.
void TestForces::sourcesAddUpToTheAcceleration()
{
    Scene s = openScene({ballAt(100, 100, 30, -20, 8), ballAt(300, 250, -10, 5, 12), ballAt(450, 120, 0, 40, 5)});
    WorldSettings& w = s.settings;
    w.gravity.enabled = true;
    w.drag = DragSettings{true, DragLaw::Quadratic, 0.01};
    w.wind.mode = WindMode::Noise;
    w.randomAccel.enabled = true;
    w.point = PointForceSettings{true, PointKind::Repel, Vec2(250, 200), 1e5, 500.0, ForceScale::Radius};
    w.spring = SpringSettings{true, Vec2(300, 200), 2.0};
    w.homing.enabled = true;
    w.pointer.enabled = true;
    w.mutualGravity = MutualGravitySettings{true, 1000.0, 5.0};
    World world;
    QVERIFY(!world.reset(s));
    world.setPointer(PointerInput{true, false, Vec2(200, 150)});
    world.step();
    const Matrix2X total = world.accelerations();
    for (int i = 0; i < world.balls().size(); ++i) {
        const auto sources = world.accelerationBySource(i);
        QCOMPARE(sources.size(), std::size_t(9));
        Vec2 sum = Vec2::Zero();
        for (const auto& source : sources)
            sum += source.acceleration;
        QVERIFY2((sum - total.col(i)).norm() <= 1e-12 * total.col(i).norm(),
                 qPrintable(QString("ball %1: %2").arg(i).arg((sum - total.col(i)).norm())));
    }
}

QTEST_APPLESS_MAIN(TestForces)
#include "test_forces.moc"
