// The course lessons: every built-in lesson runs 10 s headless and keeps its
// invariants, and each of stages 1–15 shows, in numbers, what it teaches.
// `forcelab-cli validate` is driven as a process at the end.

#include "lessons/lesson_loader.h"
#include "sim/world/world.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QtTest>

#include "cli_runner.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <vector>

using namespace forcelab;

namespace {

using forcelab::test::CliResult;
using forcelab::test::runCli;

constexpr double kWidth = 600.0;  // px, the box of every lesson of stages 1–15
constexpr double kHeight = 400.0; // px

/// A built-in lesson by file stem; fails the test (empty optional) if it does not load.
std::optional<Lesson> builtIn(const QString& stem)
{
    const LoadResult r = LessonLoader::load(stem);
    if (!r.ok()) {
        qWarning("%s", qPrintable(stem + ": " + r.errors().join(" | ")));
        return std::nullopt;
    }
    if (r.lesson->source != QStringLiteral(":/lessons/") + stem + QStringLiteral(".json")) {
        qWarning("%s loaded from %s", qPrintable(stem), qPrintable(r.lesson->source));
        return std::nullopt;
    }
    return r.lesson;
}

#define LOAD(var, stem)                                                                                             \
    const std::optional<Lesson> var##Opt = builtIn(QStringLiteral(stem));                                            \
    QVERIFY2(var##Opt, stem);                                                                                       \
    const Lesson& var = *var##Opt

#define RESET(world, scene)                                                                                         \
    do {                                                                                                            \
        const auto resetError = (world).reset(scene);                                                               \
        QVERIFY2(!resetError, resetError ? sim::toString(*resetError).c_str() : "");                                               \
    } while (false)

int stepsFor(const sim::Scene& scene, double seconds)
{
    return static_cast<int>(std::lround(seconds / scene.settings.time.dt));
}

void run(sim::World& world, int steps)
{
    for (int k = 0; k < steps; ++k)
        world.step();
}

void openWalls(sim::Scene& scene)
{
    sim::WallSettings& w = scene.settings.walls;
    w.left = w.right = w.top = w.bottom = w.middle = false;
}

/// Does anything in this scene put energy in (or is energy not meant to be kept)?
/// Returns the reason, or nullptr when total energy must not grow.
const char* energySource(const sim::Scene& scene)
{
    const sim::WorldSettings& s = scene.settings;
    if (s.wind.mode != sim::WindMode::Off)
        return "wind";
    if (s.randomAccel.enabled)
        return "random acceleration";
    if (s.pointer.enabled)
        return "pointer";
    if (scene.spawn.perStep > 0.0)
        return "spawning over time";
    if (s.point.enabled && s.point.maxAccel > 0.0)
        return "clamped point force (the clamp breaks energy conservation near the point)";
    if (s.walls.model == sim::WallModel::Mirror)
        return "mirror walls";
    if (s.point.enabled && s.point.kind == sim::PointKind::Attract)
        return "an unclamped attractor (close passes fling balls away: the slingshot)";
    if (s.walls.model == sim::WallModel::Clamp && s.gravity.enabled &&
        s.time.integrator != sim::IntegratorKind::SemiImplicitEuler && s.time.integrator != sim::IntegratorKind::Euler)
        return "clamp walls under gravity with an integrator that follows the parabola: lifting the ball out of the "
               "floor keeps the speed it gained in there";
    if (s.walls.model == sim::WallModel::Reverse && (s.gravity.enabled || s.point.enabled || s.spring.enabled ||
                                                     s.mutualGravity.enabled || s.homing.enabled))
        return "reverse walls under a force (balls sink into the wall)";
    if (s.time.perFrame)
        return "per-frame motion (moves by a different time than the forces act)";
    if (s.time.integrator == sim::IntegratorKind::Euler)
        return "explicit Euler (gains energy by design)";
    return nullptr;
}

/// Every entry of `v` within `tol` of one of the values in `groups` is one group: the number of groups.
int distinctValues(std::vector<double> v, double tol)
{
    std::sort(v.begin(), v.end());
    int groups = 0;
    for (std::size_t i = 0; i < v.size(); ++i)
        if (i == 0 || v[i] - v[i - 1] > tol)
            ++groups;
    return groups;
}

} // namespace

class TestLessons : public QObject {
    Q_OBJECT

private slots:
    void everyLessonKeepsItsInvariants_data();
    void everyLessonKeepsItsInvariants();

    void stage01BallsStandStill();
    void stage02BallsLeaveAndNeverReturn();
    void stage03CentreOnlySinksHalfway();
    void stage04PartlyOutsideBallsStick();
    void stage05MotionIndependentOfFrameRate();
    void stage06EqualSpeedEqualDistance();
    void stage07ReverseWallLetsTheBallSink();
    void stage08BounceKeepsShareOfSpeed();
    void stage09ClampBunchesExactDoesNot();
    void stage10FixedGrowsLinearRandomWalksAsRoot();
    void stage11WindMovesAllInLockStep();
    void stage12SmoothedAndNoiseAreSmooth();
    void stage13SmallBallsArePushedMore();
    void stage14PointerWindBlowsAway();
    void stage15DragDecaysExponentially();

    void validateCli_data();
    void validateCli();
    void validateCliBuiltInsAreOk();
};

// ---------------------------------------------------------------------------
// Every built-in lesson, 10 s of simulated time.

void TestLessons::everyLessonKeepsItsInvariants_data()
{
    QTest::addColumn<QString>("file");
    const QStringList files = LessonLoader::builtInFiles();
    QVERIFY(files.size() >= 16);
    for (const QString& f : files)
        QTest::newRow(qPrintable(QFileInfo(f).completeBaseName())) << f;
}

void TestLessons::everyLessonKeepsItsInvariants()
{
    QFETCH(QString, file);
    const LoadResult r = LessonLoader::load(file);
    QVERIFY2(r.ok(), qPrintable(r.errors().join(" | ")));
    const Lesson& lesson = *r.lesson;
    QVERIFY2(lesson.challenges.size() >= 2 && lesson.challenges.size() <= 4, qPrintable(file));
    QVERIFY(!lesson.text.isEmpty());
    const sim::Scene& scene = lesson.scene;
    sim::World world;
    RESET(world, scene);

    // Inside the box: only when all four walls are on and the lesson is not
    // about a wall that lets balls in on purpose (stage 3 centre-only, stage 4
    // balls created partly outside with the reverse model).
    const sim::WallSettings& w = scene.settings.walls;
    const bool boxed = w.left && w.right && w.top && w.bottom && !w.centreOnly &&
                       w.model != sim::WallModel::Reverse && scene.spawn.fullyInside;
    const char* source = energySource(scene);

    const double e0 = world.energy().total();
    double keMax = world.energy().kinetic;
    double worst = 0.0; // largest energy growth seen
    const int steps = stepsFor(scene, 10.0);
    const double slack = 1e-6; // px
    for (int k = 1; k <= steps; ++k) {
        world.step();
        const sim::BallState& b = world.balls();
        if (!b.position.allFinite() || !b.velocity.allFinite())
            QFAIL(qPrintable(QStringLiteral("%1: NaN or Inf after step %2").arg(file).arg(k)));
        if (boxed) {
            for (int i = 0; i < b.size(); ++i) {
                const double x = b.position(0, i), y = b.position(1, i), rad = b.radius[i];
                if (x < rad - slack || x > scene.settings.box.width - rad + slack || y < rad - slack ||
                    y > scene.settings.box.height - rad + slack)
                    QFAIL(qPrintable(QStringLiteral("%1: ball %2 outside the box at (%3, %4) after step %5")
                                         .arg(file)
                                         .arg(i)
                                         .arg(x)
                                         .arg(y)
                                         .arg(k)));
            }
        }
        const sim::Energy e = world.energy();
        keMax = std::max(keMax, e.kinetic);
        worst = std::max(worst, e.total() - e0);
    }
    // Energy: where nothing adds any, the total may only wobble by the
    // integrator's error. Tolerance: 2% of the largest kinetic energy seen
    // (semi-implicit Euler under gravity oscillates by about g·dt·v per unit
    // mass); 10% with mutual gravity, whose close encounters are where the
    // integrator errs most (measured: three bodies 7.8%, many bodies 3.9%).
    const double growth = keMax > 0.0 ? worst / keMax : 0.0;
    qInfo("%s: %d balls, energy growth %.3g of max KE%s%s", qPrintable(QFileInfo(file).completeBaseName()),
          world.balls().size(), growth, source ? ", not checked: " : "", source ? source : "");
    double share = scene.settings.mutualGravity.enabled ? 0.10 : 0.02;
    // A spring under semi-implicit Euler keeps H̃ = E − ½ h ω² x·v, not E, so
    // E swings by up to (ωh/2)/(1 − ωh/2) of itself: 26% for lesson 39's
    // stiff spring at ω dt = 0.42, 0.03% for a soft one.
    if (scene.settings.spring.enabled && scene.settings.time.integrator == sim::IntegratorKind::SemiImplicitEuler) {
        const double half = 0.5 * std::sqrt(scene.settings.spring.k) * scene.settings.time.dt / scene.settings.time.substeps;
        share = std::max(share, half / (1.0 - half));
    }
    if (!source)
        QVERIFY2(worst <= share * keMax + 1e-9 * std::abs(e0),
                 qPrintable(QStringLiteral("%1: total energy grew by %2 (max KE %3)").arg(file).arg(worst).arg(keMax)));
}

// ---------------------------------------------------------------------------
// One test per stage.

// Stage 1: balls are a centre and a radius, and nothing moves them.
void TestLessons::stage01BallsStandStill()
{
    LOAD(lesson, "01-balls-on-a-canvas");
    const sim::Scene& scene = lesson.scene;
    QVERIFY(scene.balls.size() >= 3);
    for (const sim::Ball& b : scene.balls) {
        QCOMPARE(b.velocity.norm(), 0.0);
        QVERIFY(b.position.x() - b.radius >= 0 && b.position.x() + b.radius <= kWidth);
        QVERIFY(b.position.y() - b.radius >= 0 && b.position.y() + b.radius <= kHeight);
    }
    QVERIFY(!scene.settings.gravity.enabled && scene.settings.wind.mode == sim::WindMode::Off &&
            !scene.settings.randomAccel.enabled && !scene.settings.drag.enabled);
    sim::World world;
    RESET(world, scene);
    const sim::Matrix2X start = world.balls().position;
    run(world, stepsFor(scene, 10.0));
    QVERIFY(world.balls().position == start); // bit for bit
    QCOMPARE(world.totals().wallHits, std::int64_t{0});
}

// Stage 2: x = x0 + vx t; once a ball has left the box it never returns.
void TestLessons::stage02BallsLeaveAndNeverReturn()
{
    LOAD(lesson, "02-animation");
    const sim::Scene& scene = lesson.scene;
    const sim::WallSettings& w = scene.settings.walls;
    QVERIFY(!w.left && !w.right && !w.top && !w.bottom);
    sim::World world;
    RESET(world, scene);
    const sim::BallState start = world.balls();
    const int n = start.size();
    QVERIFY(n >= 5);
    std::vector<int> leftAt(static_cast<std::size_t>(n), -1);
    const double dt = scene.settings.time.dt;
    const int steps = stepsFor(scene, 10.0);
    for (int k = 1; k <= steps; ++k) {
        world.step();
        const sim::BallState& b = world.balls();
        for (int i = 0; i < n; ++i) {
            QCOMPARE(b.velocity(1, i), 0.0); // along x only
            const double x = b.position(0, i);
            QVERIFY(std::abs(x - (start.position(0, i) + start.velocity(0, i) * k * dt)) < 1e-9);
            const bool outside = x + b.radius[i] < 0.0 || x - b.radius[i] > kWidth;
            int& at = leftAt[static_cast<std::size_t>(i)];
            if (outside && at < 0)
                at = k;
            if (at >= 0)
                QVERIFY2(outside, qPrintable(QStringLiteral("ball %1 came back at step %2").arg(i).arg(k)));
        }
    }
    const int last = *std::max_element(leftAt.begin(), leftAt.end());
    QVERIFY2(*std::min_element(leftAt.begin(), leftAt.end()) > 0, "every ball has left after 10 s");
    qInfo("stage 2: the last of %d balls left the box after %.2f s", n, last * dt);
}

// Stage 3: with the centre-only test a big ball sinks into the middle wall
// by its radius (its centre stops on the wall); with the edge test never.
void TestLessons::stage03CentreOnlySinksHalfway()
{
    LOAD(lesson, "03-a-wall");
    sim::Scene scene = lesson.scene;
    QVERIFY(scene.settings.walls.middle && scene.settings.walls.centreOnly);
    QCOMPARE(scene.spawn.perStep, 0.1);
    QVERIFY(scene.spawn.horizontal && scene.spawn.minSpeed == 0.0 && scene.spawn.maxSpeed == 300.0);
    const double mid = 0.5 * scene.settings.box.width;

    for (const bool centreOnly : {true, false}) {
        scene.settings.walls.centreOnly = centreOnly;
        sim::World world;
        RESET(world, scene);
        const int steps = stepsFor(scene, 10.0);
        double deepestShare = -1.0; // largest (edge past the wall) / radius over balls of radius ≥ 25 px
        double deepestAny = -1e300; // px, largest edge past the wall over all balls
        for (int k = 0; k < steps; ++k) {
            // A ball that appears during this step may straddle the wall line; the
            // wall sees it from the next step on, so only balls older than one step count.
            const int old = world.balls().size();
            world.step();
            const sim::BallState& b = world.balls();
            for (int i = 0; i < old; ++i) {
                QCOMPARE(b.velocity(1, i), 0.0);
                QVERIFY(std::abs(b.velocity(0, i)) <= 300.0);
                const double past = b.radius[i] - std::abs(b.position(0, i) - mid); // edge beyond the wall line
                deepestAny = std::max(deepestAny, past);
                if (b.radius[i] >= 25.0)
                    deepestShare = std::max(deepestShare, past / b.radius[i]);
            }
        }
        const int count = world.balls().size();
        qInfo("stage 3, centre_only %d: %d balls after 10 s; deepest edge past the wall %.3f px, "
              "share of the radius for big balls %.4f",
              centreOnly, count, deepestAny, deepestShare);
        // 4 at the start plus Binomial(600, 0.1): mean 64, standard deviation 7.3; ±4σ.
        QVERIFY2(count >= 35 && count <= 94, qPrintable(QString::number(count)));
        if (centreOnly) {
            QVERIFY(deepestShare > 0.999);          // sank in by its whole radius: half the ball in the wall
            QVERIFY(deepestShare <= 1.0 + 1e-12);   // but the centre never passes the wall
        } else {
            QVERIFY(deepestAny <= 1e-9);            // the edge never passes the wall
        }
    }
}

// Stage 4: balls created partly outside a wall with the reverse model flip
// every step and never get out; created fully inside (or clamped) none stick.
void TestLessons::stage04PartlyOutsideBallsStick()
{
    LOAD(lesson, "04-walls-and-radius");
    sim::Scene scene = lesson.scene;
    QVERIFY(!scene.spawn.fullyInside);
    QCOMPARE(scene.settings.walls.model, sim::WallModel::Reverse);

    struct Case {
        const char* name;
        bool fullyInside;
        sim::WallModel model;
    };
    for (const Case c : {Case{"bug", false, sim::WallModel::Reverse}, Case{"fully inside", true, sim::WallModel::Reverse},
                         Case{"clamp", false, sim::WallModel::Clamp}}) {
        scene.spawn.fullyInside = c.fullyInside;
        scene.settings.walls.model = c.model;
        sim::World world;
        RESET(world, scene);
        const int n = world.balls().size();
        // A ball is stuck when its centre stays outside [r, width − r] and
        // its velocity changes sign in each of the last 300 steps (5 s).
        std::vector<int> run(static_cast<std::size_t>(n), 0);
        std::vector<int> longest(static_cast<std::size_t>(n), 0);
        const int steps = stepsFor(scene, 10.0);
        for (int k = 0; k < steps; ++k) {
            const sim::Matrix2X before = world.balls().velocity;
            world.step();
            const sim::BallState& b = world.balls();
            for (int i = 0; i < n; ++i) {
                const double x = b.position(0, i), r = b.radius[i];
                const bool outside = x < r || x > kWidth - r;
                const bool flipped = b.velocity(0, i) * before(0, i) < 0.0;
                int& cur = run[static_cast<std::size_t>(i)];
                cur = outside && flipped ? cur + 1 : 0;
                longest[static_cast<std::size_t>(i)] = std::max(longest[static_cast<std::size_t>(i)], cur);
            }
        }
        const int stuck = static_cast<int>(std::count_if(run.begin(), run.end(), [](int v) { return v >= 300; }));
        const int everTwo = static_cast<int>(std::count_if(longest.begin(), longest.end(), [](int v) { return v >= 2; }));
        qInfo("stage 4, %s: %d of %d balls stuck on a wall for the last 5 s; %d flipped outside 2+ steps in a row",
              c.name, stuck, n, everTwo);
        if (c.fullyInside == false && c.model == sim::WallModel::Reverse) {
            QVERIFY(stuck >= 3);
        } else {
            QCOMPARE(stuck, 0);
            QCOMPARE(everTwo, 0);
        }
    }
}

// Stage 5: moving by v·dt gives the same positions after 1 s at 30, 60 and
// 144 steps per second; per-frame motion moves in proportion to the step count.
void TestLessons::stage05MotionIndependentOfFrameRate()
{
    LOAD(lesson, "05-frame-rate");
    sim::Scene scene = lesson.scene;
    QVERIFY(!scene.settings.time.perFrame);
    QCOMPARE(scene.settings.walls.model, sim::WallModel::Exact);
    const int rates[] = {30, 60, 144};

    // With dt: the same positions (the exact walls make bounces step-independent too).
    std::vector<sim::Matrix2X> ends;
    for (const int hz : rates) {
        scene.settings.time.dt = 1.0 / hz;
        sim::World world;
        RESET(world, scene);
        run(world, hz);
        ends.push_back(world.balls().position);
    }
    const double d30 = (ends[0] - ends[1]).cwiseAbs().maxCoeff();
    const double d144 = (ends[2] - ends[1]).cwiseAbs().maxCoeff();
    qInfo("stage 5, with dt: largest difference from 60 Hz after 1 s: %.3g px (30 Hz), %.3g px (144 Hz)", d30, d144);
    QVERIFY(d30 <= 1e-9 && d144 <= 1e-9);

    // Per frame, no walls: each step moves v/60, so 1 s of 30 steps covers half
    // the distance of 60 steps and 144 steps 2.4 times as much.
    scene.settings.time.perFrame = true;
    openWalls(scene);
    std::vector<sim::Matrix2X> moved;
    sim::Matrix2X start;
    for (const int hz : rates) {
        scene.settings.time.dt = 1.0 / hz;
        sim::World world;
        RESET(world, scene);
        start = world.balls().position;
        run(world, hz);
        moved.push_back(world.balls().position - start);
    }
    for (int k = 0; k < 3; ++k) {
        const double expected = rates[k] / 60.0;
        double worst = 0.0;
        for (Eigen::Index i = 0; i < moved[1].cols(); ++i)
            worst = std::max(worst, std::abs(moved[static_cast<std::size_t>(k)](0, i) / moved[1](0, i) - expected));
        qInfo("stage 5, per frame at %d Hz: distance ratio to 60 Hz %.6f (expected %.6f, off by %.2g)", rates[k],
              moved[static_cast<std::size_t>(k)](0, 0) / moved[1](0, 0), expected, worst);
        QVERIFY(worst <= 1e-9);
    }
}

// Stage 6: eight directions at equal speed are at equal distance at equal
// times; a "diagonal" of (v, v) travels √2 times as far.
void TestLessons::stage06EqualSpeedEqualDistance()
{
    LOAD(lesson, "06-velocity-is-a-vector");
    sim::Scene scene = lesson.scene;
    QCOMPARE(scene.balls.size(), std::size_t{8});
    const sim::Vec2 centre(300.0, 200.0);
    std::set<std::pair<long, long>> directions;
    for (const sim::Ball& b : scene.balls) {
        QVERIFY((b.position - centre).norm() == 0.0);
        QVERIFY(std::abs(b.velocity.norm() - 100.0) < 1e-12);
        directions.insert({std::lround(b.velocity.x()), std::lround(b.velocity.y())});
    }
    QCOMPARE(directions.size(), std::size_t{8});
    sim::Ball slip = scene.balls.front();
    slip.velocity = sim::Vec2(100.0, 100.0); // the common slip: vx = vy = speed
    scene.balls.push_back(slip);
    sim::World world;
    RESET(world, scene);
    run(world, stepsFor(scene, 1.0));
    const sim::BallState& b = world.balls();
    for (int i = 0; i < 8; ++i)
        QVERIFY2(std::abs((b.position.col(i) - centre).norm() - 100.0) < 1e-9, qPrintable(QString::number(i)));
    const double slipDistance = (b.position.col(8) - centre).norm();
    qInfo("stage 6: after 1 s the eight balls are 100 px out; the (100, 100) ball %.6f px", slipDistance);
    QVERIFY(std::abs(slipDistance - 100.0 * std::numbers::sqrt2) < 1e-9);
}

// Stage 7: under gravity the reverse wall lets the balls sink below the
// floor over time (20 s: the first ball is through after about 10 s); clamp
// keeps every ball on or above it.
void TestLessons::stage07ReverseWallLetsTheBallSink()
{
    LOAD(lesson, "07-gravity");
    sim::Scene scene = lesson.scene;
    QVERIFY(scene.settings.gravity.enabled && scene.settings.walls.bottom);
    QVERIFY(lesson.controls.contains("wall_model"));
    for (const sim::WallModel model : {sim::WallModel::Reverse, sim::WallModel::Clamp}) {
        scene.settings.walls.model = model;
        sim::World world;
        RESET(world, scene);
        // Deepest a ball's bottom gets below the floor in each 5 s window, px.
        std::vector<double> deepest;
        double firstThrough = -1.0; // s, when a whole ball is first below the floor
        const int window = stepsFor(scene, 5.0);
        for (int w = 0; w < 4; ++w) {
            double d = -1e300;
            for (int k = 0; k < window; ++k) {
                world.step();
                const sim::BallState& b = world.balls();
                for (int i = 0; i < b.size(); ++i) {
                    const double below = b.position(1, i) + b.radius[i] - kHeight;
                    d = std::max(d, below);
                    if (below > 2.0 * b.radius[i] && firstThrough < 0.0)
                        firstThrough = world.time();
                }
            }
            deepest.push_back(d);
        }
        qInfo("stage 7, %s: deepest below the floor per 5 s window %.2f, %.2f, %.2f, %.2f px; "
              "first ball wholly below the floor at %.2f s",
              model == sim::WallModel::Reverse ? "reverse" : "clamp", deepest[0], deepest[1], deepest[2], deepest[3],
              firstThrough);
        if (model == sim::WallModel::Reverse) {
            QVERIFY(firstThrough > 0.0);                // a ball fell through the floor
            QVERIFY(deepest[3] > deepest[1] + 50.0);    // and keeps sinking
        } else {
            QVERIFY(*std::max_element(deepest.begin(), deepest.end()) <= 1e-9);
        }
    }
}

// Stage 8: each bounce keeps the share e of the speed; bounce heights fall by e².
void TestLessons::stage08BounceKeepsShareOfSpeed()
{
    LOAD(lesson, "08-losing-energy");
    const sim::Scene& scene = lesson.scene;
    const double e = scene.settings.walls.restitution;
    QVERIFY(e > 0.0 && e < 1.0);
    const double g = scene.settings.gravity.g.y();
    const double dt = scene.settings.time.dt;
    sim::World world;
    RESET(world, scene);
    const int i = 0; // the first ball; all start at rest at the same height
    const double floorY = kHeight - world.balls().radius[i];
    double worstRatio = 0.0;
    int bounces = 0;
    std::vector<double> apex{floorY - world.balls().position(1, i)}; // rise above the floor of each flight
    double highest = 0.0;
    for (int k = 0; k < stepsFor(scene, 10.0); ++k) {
        const double before = world.balls().velocity(1, i);
        world.step();
        const double after = world.balls().velocity(1, i);
        const double rise = floorY - world.balls().position(1, i);
        if (before >= 0.0 && after < 0.0) {
            // Semi-implicit Euler: the impact speed is before + g dt, and the wall keeps e of it.
            const double ratio = -after / (before + g * dt);
            worstRatio = std::max(worstRatio, std::abs(ratio - e));
            ++bounces;
            if (bounces > 1)
                apex.push_back(highest);
            highest = 0.0;
        }
        highest = std::max(highest, rise);
    }
    QVERIFY(bounces >= 4);
    QVERIFY(worstRatio < 1e-12);
    QString heights;
    for (std::size_t k = 0; k < apex.size() && k < 5; ++k)
        heights += QString::number(apex[k], 'f', 1) + " ";
    qInfo("stage 8: %d bounces, each kept e = %.2f of the speed (to %.1g); apex heights %s px", bounces, e,
          worstRatio, qPrintable(heights));
    // Heights fall by e² per bounce; the step size blurs each apex by about v·dt.
    for (std::size_t k = 1; k < 4 && k < apex.size(); ++k)
        QVERIFY2(std::abs(apex[k] / apex[k - 1] - e * e) < 0.03,
                 qPrintable(QStringLiteral("apex %1/%2 = %3").arg(k).arg(k - 1).arg(apex[k] / apex[k - 1])));
}

// Stage 9: twenty balls, each 1.5 px lower than the last: clamping merges
// balls that cross the floor in the same step into lock-step groups; the
// exact model keeps all twenty apart.
void TestLessons::stage09ClampBunchesExactDoesNot()
{
    LOAD(lesson, "09-bounce-at-the-right-moment");
    sim::Scene scene = lesson.scene;
    QCOMPARE(scene.balls.size(), std::size_t{20});
    QCOMPARE(scene.settings.walls.restitution, 1.0);
    QCOMPARE(scene.settings.walls.model, sim::WallModel::Clamp);
    QCOMPARE(scene.settings.time.integrator, sim::IntegratorKind::Exact);
    for (std::size_t i = 1; i < scene.balls.size(); ++i)
        QVERIFY(scene.balls[i].position.y() > scene.balls[i - 1].position.y());
    std::map<sim::WallModel, int> groups;
    std::map<sim::WallModel, double> drift; // largest |E(t) − E(0)| / E(0)-scale over 10 s
    for (const sim::WallModel model : {sim::WallModel::Clamp, sim::WallModel::Mirror, sim::WallModel::Exact}) {
        scene.settings.walls.model = model;
        sim::World world;
        RESET(world, scene);
        // Energy scale: the potential energy of the drop, Σ m g (floor − y0).
        double scale = 0.0;
        for (int i = 0; i < world.balls().size(); ++i)
            scale += world.balls().mass[i] * scene.settings.gravity.g.y() *
                     (kHeight - world.balls().radius[i] - world.balls().position(1, i));
        const double e0 = world.energy().total();
        double worst = 0.0;
        for (int k = 0; k < stepsFor(scene, 10.0); ++k) {
            world.step();
            worst = std::max(worst, std::abs(world.energy().total() - e0) / scale);
        }
        drift[model] = worst;
        const sim::BallState& b = world.balls();
        std::vector<double> heights;
        for (int i = 0; i < b.size(); ++i)
            heights.push_back(b.position(1, i));
        groups[model] = distinctValues(heights, 1e-9);
        qInfo("stage 9, %s: %d distinct heights among 20 balls after 10 s; largest energy change %.3g of the drop's",
              model == sim::WallModel::Clamp    ? "clamp"
              : model == sim::WallModel::Mirror ? "mirror"
                                                : "exact",
              groups[model], drift[model]);
    }
    QVERIFY(groups[sim::WallModel::Clamp] <= 6);
    QCOMPARE(groups[sim::WallModel::Exact], 20);
    QCOMPARE(groups[sim::WallModel::Mirror], 20);
    // With the fall computed exactly, only the wall changes the energy: clamp
    // and mirror by percents, exact not at all (to rounding).
    QVERIFY(drift[sim::WallModel::Clamp] > 0.02);
    QVERIFY(drift[sim::WallModel::Mirror] > 0.02);
    QVERIFY(drift[sim::WallModel::Exact] < 1e-9);
}

// Stage 10: with no walls, a fixed random acceleration makes the speed grow
// as t, a new one every step makes it grow like a random walk, as √t.
void TestLessons::stage10FixedGrowsLinearRandomWalksAsRoot()
{
    LOAD(lesson, "10-random-acceleration");
    sim::Scene scene = lesson.scene;
    QVERIFY(scene.settings.randomAccel.enabled && !scene.settings.randomAccel.fixed);
    QVERIFY(lesson.controls.contains("random_accel"));
    openWalls(scene);
    scene.spawn.count = 400; // more balls for the statistics
    const double s = scene.settings.randomAccel.strength;
    const double dt = scene.settings.time.dt;
    auto rmsSpeed = [](const sim::BallState& b) {
        return std::sqrt(b.velocity.colwise().squaredNorm().mean());
    };
    for (const bool fixed : {false, true}) {
        scene.settings.randomAccel.fixed = fixed;
        sim::World world;
        RESET(world, scene);
        QVERIFY(world.balls().velocity.isZero());
        run(world, stepsFor(scene, 2.5));
        const double v25 = rmsSpeed(world.balls());
        const sim::Matrix2X vAt25 = world.balls().velocity;
        run(world, stepsFor(scene, 7.5));
        const double v10 = rmsSpeed(world.balls());
        // Each component is uniform in [−s, s]: variance s²/3.
        const double n = std::round(10.0 / dt);
        const double expected = fixed ? std::sqrt(2.0 / 3.0) * s * 10.0               // |a| t
                                      : std::sqrt(2.0 * n / 3.0) * s * dt;              // √N steps of σ dt per axis
        qInfo("stage 10, %s: rms speed %.2f px/s at 2.5 s, %.2f px/s at 10 s (ratio %.3f), expected at 10 s %.2f",
              fixed ? "fixed" : "per step", v25, v10, v10 / v25, expected);
        QVERIFY(std::abs(v10 / expected - 1.0) < 0.1); // 400 balls: the rms has about 2.5% spread
        if (fixed) {
            // Constant acceleration from rest: every ball's velocity exactly ×4 from 2.5 s to 10 s.
            QVERIFY(((world.balls().velocity - 4.0 * vAt25).cwiseAbs().maxCoeff()) < 1e-9 * v10);
        } else {
            QVERIFY(std::abs(v10 / v25 - 2.0) < 0.2); // √4 = 2 for a random walk, 4 for a fixed push
        }
    }
}

// Stage 11: the wind gives every ball the same horizontal acceleration, new
// each step and not accumulated: all balls change vx by the same amount.
void TestLessons::stage11WindMovesAllInLockStep()
{
    LOAD(lesson, "11-forces-not-accelerations");
    sim::Scene scene = lesson.scene;
    QVERIFY(scene.settings.gravity.enabled);
    QCOMPARE(scene.settings.wind.mode, sim::WindMode::Random);
    QCOMPARE(scene.settings.wind.scale, sim::ForceScale::None);
    QVERIFY(lesson.overlays.contains("vanes"));
    openWalls(scene); // no bounces to hide the horizontal motion
    const double strength = scene.settings.wind.strength;
    const double dt = scene.settings.time.dt;
    sim::World world;
    RESET(world, scene);
    std::vector<double> winds;
    double worstSpread = 0.0;
    for (int k = 0; k < stepsFor(scene, 10.0); ++k) {
        const Eigen::RowVectorXd before = world.balls().velocity.row(0);
        world.step();
        const Eigen::RowVectorXd dv = world.balls().velocity.row(0) - before;
        worstSpread = std::max(worstSpread, dv.maxCoeff() - dv.minCoeff());
        const double wind = dv.mean() / dt;
        QVERIFY(std::abs(wind - world.wind()) < 1e-9);
        QVERIFY(std::abs(wind) <= strength + 1e-9); // rebuilt each step, never piling up
        const sim::Matrix2X a = world.accelerations();
        QVERIFY((a.row(0).array() - world.wind()).abs().maxCoeff() < 1e-9);
        winds.push_back(wind);
    }
    // Jerky: one step's wind tells nothing about the next (lag-1 correlation near 0).
    double mean = 0, c0 = 0, c1 = 0;
    for (double w : winds)
        mean += w / winds.size();
    for (std::size_t k = 0; k < winds.size(); ++k) {
        c0 += (winds[k] - mean) * (winds[k] - mean);
        if (k + 1 < winds.size())
            c1 += (winds[k] - mean) * (winds[k + 1] - mean);
    }
    qInfo("stage 11: spread of the per-step change of vx over all balls %.3g px/s; lag-1 correlation of the wind %.3f",
          worstSpread, c1 / c0);
    QVERIFY(worstSpread < 1e-9);
    QVERIFY(std::abs(c1 / c0) < 0.15); // 600 samples: standard error 0.04
}

// Stage 12: the smoothed wind changes by at most smoothed_step × strength per
// step, the random one jumps, the noise changes smoothly; the comparison
// wind pushes nothing.
void TestLessons::stage12SmoothedAndNoiseAreSmooth()
{
    LOAD(lesson, "12-smoother-wind");
    sim::Scene scene = lesson.scene;
    QCOMPARE(scene.settings.wind.mode, sim::WindMode::Smoothed);
    QCOMPARE(scene.settings.wind.compare, sim::WindMode::Random);
    QVERIFY(lesson.controls.contains("wind_compare"));
    const double S = scene.settings.wind.strength;
    openWalls(scene);
    auto changes = [&](sim::WindMode mode, sim::WindMode compare, double& maxMain, double& meanCompare,
                       double& maxCompare) {
        scene.settings.wind.mode = mode;
        scene.settings.wind.compare = compare;
        sim::World world;
        QVERIFY(!world.reset(scene));
        world.step();
        double w = world.wind(), c = world.compareWind();
        maxMain = maxCompare = meanCompare = 0.0;
        const int steps = stepsFor(scene, 10.0);
        for (int k = 0; k < steps; ++k) {
            const double vx = world.balls().velocity(0, 0);
            world.step();
            if (mode == sim::WindMode::Smoothed) // the balls feel the main wind only
                QVERIFY(std::abs((world.balls().velocity(0, 0) - vx) / scene.settings.time.dt - world.wind()) < 1e-9);
            maxMain = std::max(maxMain, std::abs(world.wind() - w));
            maxCompare = std::max(maxCompare, std::abs(world.compareWind() - c));
            meanCompare += std::abs(world.compareWind() - c) / steps;
            w = world.wind();
            c = world.compareWind();
            QVERIFY(std::abs(w) <= S + 1e-9 && std::abs(c) <= S + 1e-9);
        }
    };
    double smoothMax = 0.0, randomMean = 0.0, randomMax = 0.0;
    changes(sim::WindMode::Smoothed, sim::WindMode::Random, smoothMax, randomMean, randomMax);
    double unused, noiseMean, noiseMax;
    changes(sim::WindMode::Smoothed, sim::WindMode::Noise, unused, noiseMean, noiseMax);
    qInfo("stage 12: largest change per step as a share of the strength: smoothed %.4f, random %.4f (mean %.4f), "
          "noise %.4f",
          smoothMax / S, randomMax / S, randomMean / S, noiseMax / S);
    QVERIFY(smoothMax <= scene.settings.wind.smoothedStep * S + 1e-9); // ≤ 10% per step
    QVERIFY(randomMean > 0.5 * S);  // two uniform values in [−S, S] differ by 2S/3 on average
    QVERIFY(noiseMax < 0.05 * S);   // 0.5 Hz sampled 60 times a second: small steps, no jumps
}

// Stage 13: with the wind as a force (scale mass) a ball of radius r gets
// (R/r)³ times the acceleration of one of radius R; with scale radius R/r.
// The speed limit holds throughout the lesson.
void TestLessons::stage13SmallBallsArePushedMore()
{
    LOAD(lesson, "13-mass-matters");
    sim::Scene scene = lesson.scene;
    QCOMPARE(scene.settings.wind.scale, sim::ForceScale::Mass);
    QVERIFY(scene.settings.speedLimit.enabled);
    const double limit = scene.settings.speedLimit.max;
    {
        sim::World world;
        RESET(world, scene);
        double fastest = 0.0;
        for (int k = 0; k < stepsFor(scene, 10.0); ++k) {
            world.step();
            fastest = std::max(fastest, world.balls().velocity.colwise().norm().maxCoeff());
        }
        qInfo("stage 13: fastest ball in 10 s %.3f px/s, limit %.0f px/s", fastest, limit);
        QVERIFY(fastest <= limit * (1.0 + 1e-12));
        QVERIFY(fastest > 0.5 * limit); // the limit is actually reached by the small balls
    }
    const double r = 5.0, R = 20.0;
    scene.spawn.count = 0;
    sim::Ball small, big;
    small.position = sim::Vec2(100.0, 100.0);
    small.radius = r;
    big.position = sim::Vec2(300.0, 100.0);
    big.radius = R;
    scene.balls = {small, big};
    scene.settings.wind.mode = sim::WindMode::Smoothed; // a value that holds for the whole step
    for (const sim::ForceScale scale : {sim::ForceScale::Mass, sim::ForceScale::Radius}) {
        scene.settings.wind.scale = scale;
        sim::World world;
        RESET(world, scene);
        run(world, 5);
        QVERIFY(std::abs(world.wind()) > 1.0);
        const sim::Matrix2X a = world.accelerations();
        const double ratio = a(0, 0) / a(0, 1);
        const double expected = scale == sim::ForceScale::Mass ? std::pow(R / r, 3) : R / r;
        qInfo("stage 13, scale %s: small/big horizontal acceleration %.12g (expected %.0f)",
              scale == sim::ForceScale::Mass ? "mass" : "radius", ratio, expected);
        QVERIFY(std::abs(ratio / expected - 1.0) < 1e-12);
    }
}

// Stage 14: the pointer left of the centre blows right, right of it blows
// left, in proportion to the offset; outside the canvas there is no wind.
void TestLessons::stage14PointerWindBlowsAway()
{
    LOAD(lesson, "14-blow-your-own-wind");
    sim::Scene scene = lesson.scene;
    QCOMPARE(scene.settings.wind.mode, sim::WindMode::Pointer);
    const double S = scene.settings.wind.strength;
    const double half = 0.5 * scene.settings.box.width;
    openWalls(scene);
    sim::World world;
    RESET(world, scene);
    struct Case {
        bool inside;
        double x;
        double expected; // px/s² on a reference ball
    };
    for (const Case c : {Case{true, 150.0, S * 0.5}, Case{true, 0.0, S}, Case{true, 450.0, -S * 0.5},
                         Case{true, half, 0.0}, Case{false, 150.0, 0.0}}) {
        world.setPointer(sim::PointerInput{c.inside, false, sim::Vec2(c.x, 200.0)});
        const Eigen::RowVectorXd vx = world.balls().velocity.row(0);
        world.step();
        const Eigen::RowVectorXd dvx = world.balls().velocity.row(0) - vx;
        qInfo("stage 14: pointer %s at x = %.0f: wind %.3f px/s² (expected %.3f)", c.inside ? "in" : "out", c.x,
              world.wind(), c.expected);
        QVERIFY(std::abs(world.wind() - c.expected) < 1e-9);
        if (c.expected > 0.0)
            QVERIFY(dvx.minCoeff() > 0.0); // every ball pushed to the right
        else if (c.expected < 0.0)
            QVERIFY(dvx.maxCoeff() < 0.0);
        else
            QVERIFY(dvx.cwiseAbs().maxCoeff() == 0.0); // no wind, no horizontal change at all
    }
}

// Stage 15: linear drag: v(t) = v0 e^(−kt) (within the method's error), the
// direction kept; without drag the speed never changes.
// Stage 15: linear drag as a force, F = −k m₁₀ v, slows each ball by
// a = −k (m₁₀ / m) v, so |v| decays as e^(−k t m₁₀ / m): a 10 px ball halves
// its speed in ln 2 / k, a heavier one more slowly. With scaling "none" (the
// tutorial's model) every ball decays as e^(−kt). The direction never changes.
void TestLessons::stage15DragDecaysExponentially()
{
    LOAD(lesson, "15-drag");
    sim::Scene scene = lesson.scene;
    QVERIFY(scene.settings.drag.enabled);
    QCOMPARE(scene.settings.drag.law, sim::DragLaw::Linear);
    QCOMPARE(scene.settings.drag.scale, sim::ForceScale::Mass);
    const double k = scene.settings.drag.k;
    const double dt = scene.settings.time.dt;
    openWalls(scene);
    for (const int mode : {0, 1, 2}) { // force, tutorial's model, off
        scene.settings.drag.enabled = mode != 2;
        scene.settings.drag.scale = mode == 1 ? sim::ForceScale::None : sim::ForceScale::Mass;
        sim::World world;
        RESET(world, scene);
        const sim::Matrix2X v0 = world.balls().velocity;
        const sim::VectorX rate = mode == 2 ? sim::VectorX::Zero(world.balls().size())
                                            : (k * sim::scaleFactors(scene.settings.drag.scale, world.balls())).eval();
        for (const double t : {2.0, 5.0, 10.0}) {
            run(world, stepsFor(scene, t) - static_cast<int>(world.stepCount()));
            const sim::Matrix2X& v = world.balls().velocity;
            double worst = 0.0, worstDirection = 0.0; // worst: error over what is allowed, per ball
            for (Eigen::Index i = 0; i < v.cols(); ++i) {
                const double ratio = v.col(i).norm() / v0.col(i).norm();
                const double c = rate[i];
                // Semi-implicit Euler multiplies by (1 − c dt) per step, and
                // n ln(1 − c dt) = −c t − c² dt t / 2 − …: relative error ≈ c² dt t / 2;
                // allowed 0.6 c² dt t (1e-12 without drag).
                const double allowed = std::max(0.6 * c * c * dt * t, 1e-12);
                worst = std::max(worst, std::abs(ratio / std::exp(-c * t) - 1.0) / allowed);
                worstDirection = std::max(worstDirection, std::abs(v(0, i) * v0(1, i) - v(1, i) * v0(0, i)) /
                                                              (v.col(i).norm() * v0.col(i).norm()));
            }
            qInfo("stage 15, drag %s, t = %.0f s: |v|/|v0| off the closed form by at most %.3g of what is allowed",
                  mode == 0 ? "as a force" : mode == 1 ? "scaling none" : "off", t, worst);
            QVERIFY(worst <= 1.0);
            QVERIFY(worstDirection < 1e-12);
        }
        if (mode == 0) { // the heaviest ball keeps the largest share of its speed
            const sim::BallState& b = world.balls();
            Eigen::Index heavy = 0, light = 0;
            b.mass.maxCoeff(&heavy);
            b.mass.minCoeff(&light);
            QVERIFY(b.velocity.col(heavy).norm() / v0.col(heavy).norm() >
                    b.velocity.col(light).norm() / v0.col(light).norm());
        }
    }
}

// ---------------------------------------------------------------------------
// forcelab-cli validate, as a process.

void TestLessons::validateCli_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QStringList>("expected"); // lines of stderr, with FILE for the path
    // The missing comma is noticed where the next key starts.
    QTest::newRow("syntax error with line and column")
        << QByteArray("{\n  \"format\": 1,\n  \"id\": \"x\"\n  \"title\": \"y\"\n}\n")
        << QStringList{"FILE:4:3: syntax error: expected , or } here (a missing comma, or a { that is never closed)"};
    QTest::newRow("every problem, ranges, names and the nearest key")
        << QByteArray(R"({"format": 1, "id": "x",
  "world": {"wall_model": "bounce", "centre_only": 1},
  "time": {"dt": 0, "per_frme": true},
  "models": {"random_accel": {"strength": -5}},
  "spawn": {"per_step": 2}})")
        << QStringList{
               R"(FILE:2:13: world.wall_model: "bounce" is not one of clamp, mirror, exact, reverse)",
               "FILE:2:37: world.centre_only: expected true or false, got the number 1",
               R"(FILE:3:21: time.per_frme: unknown key "per_frme"; did you mean "per_frame"?)",
               "FILE:3:12: time.dt: 0 is outside (0, 1] s",
               "FILE:4:31: models.random_accel.strength: -5 is outside [0, 10000000] px/s²",
               "FILE:5:13: spawn.per_step: 2 is outside [0, 1]",
           };
}

void TestLessons::validateCli()
{
    QFETCH(QByteArray, json);
    QFETCH(QStringList, expected);
    QTemporaryDir dir;
    const QString bad = dir.filePath("bad.json");
    const QString good = dir.filePath("good.json");
    QFile f(bad);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(json);
    f.close();
    QFile g(good);
    QVERIFY(g.open(QIODevice::WriteOnly));
    g.write(R"({"format": 1, "id": "fine", "world": {"wall_model": "reverse"}})");
    g.close();

    const CliResult r = runCli({"validate", good, bad});
    QCOMPARE(r.exitCode, 2);
    QCOMPARE(r.out, good + ": ok\n");
    QStringList lines = r.err.split('\n', Qt::SkipEmptyParts);
    for (QString& e : expected)
        e.replace("FILE", bad);
    lines.sort();
    expected.sort();
    QCOMPARE(lines, expected);

    const CliResult ok = runCli({"validate", good});
    QCOMPARE(ok.exitCode, 0);
    QVERIFY(ok.err.isEmpty());
    const CliResult missing = runCli({"validate", dir.filePath("nope.json")});
    QCOMPARE(missing.exitCode, 2);
    QVERIFY2(missing.err.startsWith(dir.filePath("nope.json") + ": cannot open"), qPrintable(missing.err));
    QCOMPARE(runCli({"validate"}).exitCode, 2);
}

void TestLessons::validateCliBuiltInsAreOk()
{
    // The lesson files of the source tree, as a teacher would check them.
    const QDir dir(QStringLiteral(FORCELAB_LESSON_DIR));
    QStringList files;
    for (const QString& name : dir.entryList({"*.json"}, QDir::Files, QDir::Name))
        files << dir.filePath(name);
    QVERIFY(files.size() >= 16);
    const CliResult r = runCli(QStringList{"validate"} + files);
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QCOMPARE(r.out.count(": ok\n"), files.size());
}

QTEST_GUILESS_MAIN(TestLessons)
#include "test_lessons.moc"
