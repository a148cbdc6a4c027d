// Collisions inside a whole world: walls and balls together, energy and
// momentum over long runs, and the same run whichever detector is chosen.

#include "sim/collision/broad_phase/broad_phase_geometry.h"
#include "sim/studies/peer_scene.h"
#include "sim/world/world.h"

#include "sim_check.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include <string>
#include <vector>

using forcelab::test::Text;

using namespace forcelab::sim;

namespace {

Scene boxOfBalls(int count, double width, double height, Detection detection, double restitution)
{
    Scene s;
    s.settings.box = BoxSettings{width, height};
    s.settings.walls = WallSettings{true, true, true, true, WallModel::Clamp, 1.0};
    s.settings.collisions.detection = detection;
    s.settings.collisions.response = Response::Impulse2D;
    s.settings.collisions.restitution = restitution;
    s.spawn.count = count;
    s.spawn.minRadius = 3.0;
    s.spawn.maxRadius = 6.0;
    s.spawn.minSpeed = 50.0;
    s.spawn.maxSpeed = 300.0;
    s.spawn.seed = 42;
    return s;
}

} // namespace


// 2,000 balls in a box, 2d-impulse with e = 1, walls with e = 1, no gravity or
// drag: kinetic energy within 1e-9 relative over 10,000 steps.
TEST_CASE("TestCollisionWorld::boxKeepsKineticEnergy")
{
    World w(boxOfBalls(2000, 1000.0, 800.0, Detection::Grid, 1.0));
    REQUIRE_SAME(w.balls().size(), 2000);
    const double ke0 = w.energy().kinetic;
    VERIFY(ke0 > 0.0);
    double worst = 0.0;
    std::int64_t contacts = 0;
    for (int step = 0; step < 10000; ++step) {
        w.step();
        contacts += w.lastStep().contacts;
        if (step % 100 == 99)
            worst = std::max(worst, std::abs(w.energy().kinetic - ke0) / ke0);
    }
    worst = std::max(worst, std::abs(w.energy().kinetic - ke0) / ke0);
    forcelab::test::report("largest relative change of kinetic energy: %.3g", worst);
    VERIFY2(worst <= 1e-9, Text(Text("relative KE change %1").arg(worst)).c_str());
    VERIFY(contacts > 100000); // the balls really collided
    VERIFY(w.balls().position.allFinite());
}

// No walls, e = 0.8: every collision loses energy but none changes momentum.
TEST_CASE("TestCollisionWorld::openSpaceKeepsMomentum")
{
    Scene s = boxOfBalls(800, 500.0, 500.0, Detection::Sweep, 0.8);
    s.settings.walls = WallSettings{false, false, false, false, WallModel::Clamp, 1.0};
    World w(s);
    const Vec2 p0 = w.momentum();
    const double scale = (w.balls().velocity.colwise().norm().transpose().array() * w.balls().mass.array()).sum();
    const double ke0 = w.energy().kinetic;
    std::int64_t contacts = 0;
    for (int step = 0; step < 300; ++step) {
        w.step();
        contacts += w.lastStep().contacts;
    }
    VERIFY(contacts > 1000);
    VERIFY((w.momentum() - p0).norm() <= 1e-12 * scale);
    VERIFY(w.energy().kinetic < ke0);
}

TEST_CASE("TestCollisionWorld::detectorsGiveTheSameRun")
{
    std::vector<BallState> finals;
    std::vector<std::int64_t> contacts, tested;
    for (Detection d : {Detection::Brute, Detection::Halved, Detection::Sweep, Detection::Grid}) {
        Scene s = boxOfBalls(600, 400.0, 300.0, d, 0.9);
        s.settings.gravity.enabled = true;
        World w(s);
        for (int step = 0; step < 200; ++step)
            w.step();
        finals.push_back(w.balls());
        contacts.push_back(w.totals().contacts);
        tested.push_back(w.totals().pairsTested);
    }
    for (std::size_t k = 1; k < finals.size(); ++k) {
        REQUIRE_SAME(finals[k].position, finals[0].position);
        REQUIRE_SAME(finals[k].velocity, finals[0].velocity);
        REQUIRE_SAME(contacts[k], contacts[0]);
    }
    // Why the workbench shows the counters: brute tests twice what halved does,
    // and sweep and grid a tiny share of it.
    REQUIRE_SAME(tested[0], 2 * tested[1]);
    VERIFY(tested[2] * 20 < tested[1]);
    VERIFY(tested[3] * 20 < tested[1]);
}

TEST_CASE("TestCollisionWorld::flagLeavesMotionAlone")
{
    Scene s = boxOfBalls(500, 400.0, 300.0, Detection::Sweep, 1.0);
    s.settings.gravity.enabled = true;
    Scene none = s;
    none.settings.collisions.response = Response::None;
    s.settings.collisions.response = Response::Flag;
    World flagged(s), plain(none);
    int marked = 0;
    for (int step = 0; step < 100; ++step) {
        flagged.step();
        plain.step();
    }
    for (auto f : flagged.balls().colliding)
        marked += f;
    VERIFY(marked > 0);
    VERIFY(flagged.lastStep().contacts > 0);
    REQUIRE_SAME(flagged.balls().position, plain.balls().position);
    REQUIRE_SAME(flagged.balls().velocity, plain.balls().velocity);
}

// A ball moving 100 radii per step towards a resting ball near the right wall
// (exact wall model): it hits the ball and neither passes through the other
// or the wall.
TEST_CASE("TestCollisionWorld::continuousWithExactWalls")
{
    Scene s;
    s.settings.box = BoxSettings{3000.0, 400.0};
    s.settings.walls = WallSettings{true, true, true, true, WallModel::Exact, 1.0};
    s.settings.collisions.response = Response::Impulse2D;
    s.settings.collisions.continuous = true;
    s.settings.collisions.detection = Detection::Grid;
    Ball fast, still;
    fast.radius = still.radius = 10.0;
    fast.position = Vec2(100.0, 200.0);
    fast.velocity = Vec2(1000.0 / s.settings.time.dt, 0.0); // 100 radii per step
    still.position = Vec2(1550.0, 200.0);
    s.balls = {fast, still};
    World w(s);
    for (int step = 0; step < 20; ++step) {
        w.step();
        const auto& x = w.balls().position;
        VERIFY2(x(0, 0) < x(0, 1), Text(Text("step %1: %2 %3").arg(step).arg(x(0, 0)).arg(x(0, 1))).c_str());
        VERIFY(x(0, 0) >= 10.0 && x(0, 1) <= 2990.0);
    }
    VERIFY(std::abs(w.energy().kinetic - 0.5 * w.balls().mass[0] * std::pow(1000.0 / s.settings.time.dt, 2)) <=
            1e-9 * w.energy().kinetic);
}

// Issue #31, item 5: two impacts inside one step, in time order. Right wall
// at 600 px (exact model, e = 1), ball A (r = 10 px) at x = 586 moving right
// at 600 px/s, ball B of the same mass at rest at x = 565.5, dt = 1/60 s.
// A reaches the wall after 4/600 s, comes back at 600 px/s, meets B after
// another 4.5/600 s and stops there (x = 585.5); B leaves at 600 px/s for
// the 1.5/600 s left and ends at x = 564.0. (The one-event pass ended B at
// 558: it bounced the pair from A's straight path 586 -> 584 instead.)
TEST_CASE("TestCollisionWorld::continuousWallThenBallInOneStep")
{
    Scene s;
    s.settings.box = BoxSettings{600.0, 400.0};
    s.settings.walls = WallSettings{true, true, true, true, WallModel::Exact, 1.0};
    s.settings.collisions.response = Response::Impulse2D;
    s.settings.collisions.restitution = 1.0;
    s.settings.collisions.continuous = true;
    Ball a, b;
    a.radius = b.radius = 10.0;
    a.position = Vec2(586.0, 200.0);
    a.velocity = Vec2(600.0, 0.0);
    b.position = Vec2(565.5, 200.0);
    s.balls = {a, b};
    for (Detection d : {Detection::Brute, Detection::Halved, Detection::Sweep, Detection::Grid}) {
        s.settings.collisions.detection = d;
        World w(s);
        w.step();
        const BallState& x = w.balls();
        forcelab::test::report("wall then ball in one step: A ends at %.9f px (%.6f px/s), B at %.9f px (%.6f px/s)",
                               x.position(0, 0), x.velocity(0, 0), x.position(0, 1), x.velocity(0, 1));
        VERIFY2(std::abs(x.position(0, 1) - 564.0) <= 1e-9, Text(Text::number(x.position(0, 1), 'g', 17)).c_str());
        VERIFY(std::abs(x.position(0, 0) - 585.5) <= 1e-9);
        VERIFY(std::abs(x.velocity(0, 0)) <= 1e-9);
        VERIFY(std::abs(x.velocity(0, 1) + 600.0) <= 1e-9);
        VERIFY(w.lastStep().wallHits == 1);
    }
}

namespace {

// Pairs that overlap at the end of a step (deeper than 1e-9 of the smaller
// radius: two balls that met exactly at the end may sit a rounding error
// inside each other), and the deepest of them as a share of the smaller
// diameter.
struct StepEndOverlaps {
    std::int64_t pairs = 0;
    double deepest = 0.0;
};

void countOverlaps(const World& w, StepEndOverlaps& o)
{
    CollisionSystem sys;
    std::vector<Contact> pairs;
    sys.detect(w.balls(), Detection::Sweep, pairs);
    const BallState& b = w.balls();
    for (const Contact& c : pairs) {
        const double small = std::min(b.radius[c.a], b.radius[c.b]);
        const double depth = b.radius[c.a] + b.radius[c.b] - (b.position.col(c.b) - b.position.col(c.a)).norm();
        if (depth > 1e-9 * small) {
            ++o.pairs;
            o.deepest = std::max(o.deepest, depth / (2.0 * small));
        }
    }
}

} // namespace

// Issue #31, item 5: a gas of 200 balls (r 3-6 px, 50-300 px/s, e = 1) in a
// 300 x 200 px box with exact walls, 600 steps at 60 Hz, counted after the
// first 30 steps (the spawn leaves balls overlapping). Discrete detection leaves
// pairs overlapping at step ends (a ball moves up to 5 px a step; measured
// 6,816 pairs over 570 step ends, the deepest 86% of the smaller diameter);
// continuous detection makes every impact at its moment, so none is left.
// Kinetic energy is kept to 1e-9 with continuous detection (measured 2.5e-15):
// every impact is elastic.
TEST_CASE("TestCollisionWorld::continuousGasLeavesNoOverlaps")
{
    StepEndOverlaps found[2];
    double energyChange = 0.0;
    std::int64_t impacts = 0;
    for (bool continuous : {false, true}) {
        Scene s = boxOfBalls(200, 300.0, 200.0, Detection::Sweep, 1.0);
        s.settings.walls.model = WallModel::Exact;
        s.settings.collisions.continuous = continuous;
        World w(s);
        const double ke0 = w.energy().kinetic;
        StepEndOverlaps& o = found[continuous ? 1 : 0];
        for (int step = 0; step < 600; ++step) {
            w.step();
            if (step >= 30) // the spawn leaves balls overlapping; the end-of-step pass parts them within a few steps
                countOverlaps(w, o);
            if (continuous)
                impacts += w.lastStep().contacts;
        }
        if (continuous)
            energyChange = std::abs(w.energy().kinetic - ke0) / ke0;
    }
    forcelab::test::report("200-ball gas, 600 steps: pairs overlapping at step ends %lld discrete (deepest %.3f of "
                           "the smaller diameter), %lld continuous (deepest %.3g); continuous: %lld contacts, "
                           "kinetic energy changed by %.3g",
                           static_cast<long long>(found[0].pairs), found[0].deepest,
                           static_cast<long long>(found[1].pairs), found[1].deepest, static_cast<long long>(impacts),
                           energyChange);
    VERIFY(found[0].pairs > 100); // the scene does make discrete detection fail
    VERIFY2(found[1].pairs == 0, Text(Text::number(static_cast<double>(found[1].pairs))).c_str());
    VERIFY(impacts > 1000);
    VERIFY2(energyChange <= 1e-9, Text(Text::number(energyChange)).c_str());
}

namespace {

// Deepest overlap of any touching pair, as a share of the smaller radius.
double deepestOverlap(const World& w)
{
    CollisionSystem sys;
    std::vector<Contact> pairs;
    sys.detect(w.balls(), Detection::Sweep, pairs);
    const BallState& b = w.balls();
    double worst = 0.0;
    for (const Contact& c : pairs) {
        const double depth = b.radius[c.a] + b.radius[c.b] - (b.position.col(c.b) - b.position.col(c.a)).norm();
        worst = std::max(worst, depth / std::min(b.radius[c.a], b.radius[c.b]));
    }
    return worst;
}

// A column of 20 balls (r = 10 px) on the floor of a 200 × 600 px box, 1 px
// apart, gravity on, 2d-impulse with e = 0.9 for balls and walls, sweep.
Scene columnScene(WallModel walls, int substeps)
{
    const double r = 10.0, height = 600.0;
    Scene s;
    s.settings.box = BoxSettings{200.0, height};
    s.settings.walls = WallSettings{true, true, true, true, walls, 0.9};
    s.settings.gravity.enabled = true;
    s.settings.time.substeps = substeps;
    s.settings.collisions.detection = Detection::Sweep;
    s.settings.collisions.response = Response::Impulse2D;
    s.settings.collisions.restitution = 0.9;
    for (int i = 0; i < 20; ++i) {
        Ball b;
        b.radius = r;
        b.position = Vec2(100.0, height - r - (2.0 * r + 1.0) * i);
        s.balls.push_back(b);
    }
    return s;
}

bool allInside(const World& w)
{
    const BallState& b = w.balls();
    const BoxSettings& box = w.settings().box;
    for (int i = 0; i < b.size(); ++i) {
        const double r = b.radius[i], x = b.position(0, i), y = b.position(1, i);
        if (!(x >= r - 1e-9 && x <= box.width - r + 1e-9 && y >= r - 1e-9 && y <= box.height - r + 1e-9))
            return false;
    }
    return true;
}

} // namespace

namespace {

struct ColumnStandsUnderGravityRow {
    Text tag;
    int wallModel;
    int substeps;
};

std::vector<ColumnStandsUnderGravityRow> columnStandsUnderGravityRows()
{
    std::vector<ColumnStandsUnderGravityRow> rows;
    rows.push_back({Text("clamp, 1 sub-step"), int(WallModel::Clamp), 1});
    rows.push_back({Text("exact, 1 sub-step"), int(WallModel::Exact), 1});
    rows.push_back({Text("clamp, 4 sub-steps"), int(WallModel::Clamp), 4});
    return rows;
}

} // namespace


// A column of 20 balls (r = 10 px) standing on the floor, dropped from 1 px
// gaps, gravity 980 px/s², e = 0.9 for balls and walls, 60 Hz: after 10 s it
// is still a column 20 diameters tall (within 2%), no pair overlaps by more
// than 1% of a radius, and it never did during the run.
TEST_CASE("TestCollisionWorld::columnStandsUnderGravity")
{
    for (const ColumnStandsUnderGravityRow& row : columnStandsUnderGravityRows()) {
        SUBCASE(row.tag.c_str())
        {
            const auto& wallModel = row.wallModel;
            const auto& substeps = row.substeps;
            World w(columnScene(static_cast<WallModel>(wallModel), substeps));
            const double r = w.balls().radius[0], height = w.settings().box.height;
            double worstOverlap = 0.0;
            double intoFloor = 0.0; // fastest a ball on the floor ends a step moving into it, px/s
            for (int step = 0; step < 600; ++step) {
                w.step();
                if (step >= 60) // after the first second, once the 1 px drops have landed
                    worstOverlap = std::max(worstOverlap, deepestOverlap(w));
                const BallState& b = w.balls();
                for (int i = 0; i < b.size(); ++i)
                    if (b.position(1, i) >= height - r)
                        intoFloor = std::max(intoFloor, b.velocity(1, i));
            }
            // A ball the solver leaves on the floor is not still moving into it: the
            // next wall stage would bounce it up again, every step (the exact wall
            // model's floor ball did, at up to 146 px/s, and the column sank to 289 px).
            // 1e-9 px/s leaves room for the rounding of the impulse sums (~1e-13).
            VERIFY2(intoFloor <= 1e-9, Text(Text::number(intoFloor)).c_str());
            const BallState& b = w.balls();
            VERIFY(b.position.allFinite() && b.velocity.allFinite());
            const double top = b.position.row(1).minCoeff() - r, bottom = b.position.row(1).maxCoeff() + r;
            const double columnHeight = bottom - top;
            forcelab::test::report("column height %.4f px (20 diameters = 400), deepest overlap %.3g r", columnHeight, worstOverlap);
            // Speculative contacts hold a column that stands at touching distance,
            // and with 4 sub-steps no pair overlaps by more than 1% of a radius.
            VERIFY2(std::abs(columnHeight - 400.0) <= 0.02 * 400.0, Text(Text::number(columnHeight)).c_str());
            // 1 sub-step: the first impacts of the 1 px drops overlap by about 1% r
            // (clamp 0.8%, exact 1.3%; 26% to 89% before the solver took back the
            // wall stage's bounces and took lines of impact from the start of the
            // sub-step), where 4 sub-steps hold 1%.
            VERIFY2(worstOverlap <= (substeps == 1 ? 0.02 : 0.01), Text(Text::number(worstOverlap)).c_str());
            // Still one column: no ball moved sideways, and they are still in order.
            VERIFY((b.position.row(0).array() == 100.0).all());
            bool ordered = true;
            for (int i = 0; i + 1 < 20; ++i)
                ordered = ordered && b.position(1, i + 1) < b.position(1, i);
            VERIFY(ordered);
            VERIFY(allInside(w));
        }
    }
}

namespace {

struct PileSettlesUnderGravityRow {
    Text tag;
    int substeps;
};

std::vector<PileSettlesUnderGravityRow> pileSettlesUnderGravityRows()
{
    std::vector<PileSettlesUnderGravityRow> rows;
    rows.push_back({Text("1 sub-step"), 1});
    rows.push_back({Text("8 sub-steps"), 8});
    return rows;
}

} // namespace


// 2,000 balls (r = 3–5 px) on a jittered grid filling 30% of a box, random
// speeds, gravity, e = 0.9, 60 Hz with 1 sub-step (the bench's scene) or 8:
// after 20 s the pile has settled. Its kinetic energy is a tiny share of the
// potential energy it started with, it is about as dense as packed discs
// (a hexagonal packing has 3 contacts per ball), no pair overlaps by more than
// 2% of the smaller radius, and every ball is inside the box.
TEST_CASE("TestCollisionWorld::pileSettlesUnderGravity")
{
    for (const PileSettlesUnderGravityRow& row : pileSettlesUnderGravityRows()) {
        SUBCASE(row.tag.c_str())
        {
            const auto& substeps = row.substeps;
            const int n = 2000;
            std::mt19937_64 rng(11);
            std::uniform_real_distribution<double> u(0.0, 1.0);
            std::vector<Ball> balls(n);
            double area = 0.0;
            for (Ball& b : balls) {
                b.radius = 3.0 + 2.0 * u(rng);
                area += std::numbers::pi * b.radius * b.radius;
            }
            const double side = std::sqrt(area / 0.3);
            const int cols = static_cast<int>(std::ceil(std::sqrt(double(n))));
            const double cell = side / cols;
            for (int i = 0; i < n; ++i) {
                Ball& b = balls[static_cast<std::size_t>(i)];
                const double slack = std::max(0.0, 0.5 * cell - b.radius);
                b.position = Vec2((i % cols + 0.5) * cell + slack * (2.0 * u(rng) - 1.0),
                                  (i / cols + 0.5) * cell + slack * (2.0 * u(rng) - 1.0));
                const double angle = 2.0 * std::numbers::pi * u(rng);
                b.velocity = 100.0 * u(rng) * Vec2(std::cos(angle), std::sin(angle));
            }
            Scene s;
            s.settings.box = BoxSettings{side, side};
            s.settings.time.substeps = substeps;
            s.settings.walls = WallSettings{true, true, true, true, WallModel::Clamp, 0.9};
            s.settings.gravity.enabled = true;
            s.settings.collisions.detection = Detection::Grid;
            s.settings.collisions.response = Response::Impulse2D;
            s.settings.collisions.restitution = 0.9;
            s.balls = balls;
            World w(s);
            // Potential energy above the floor: Σ m g (H − r − y).
            auto potential = [&](const World& world) {
                const BallState& b = world.balls();
                double pe = 0.0;
                for (int i = 0; i < b.size(); ++i)
                    pe += b.mass[i] * 980.0 * (side - b.radius[i] - b.position(1, i));
                return pe;
            };
            const double pe0 = potential(w);
            for (int step = 0; step < 1200; ++step) {
                w.step();
                VERIFY(w.halted() == std::nullopt);
            }
            const BallState& b = w.balls();
            VERIFY(b.position.allFinite() && b.velocity.allFinite());
            const double ke = w.energy().kinetic;
            const double perBall = double(w.lastStep().contacts) / n / substeps; // the step counts every sub-step
            const double overlap = deepestOverlap(w);
            forcelab::test::report("after 20 s: KE / PE0 = %.3g, PE / PE0 = %.3f, %.2f contacts per ball, deepest overlap %.3g r",
                  ke / pe0, potential(w) / pe0, perBall, overlap);
            VERIFY2(ke <= 1e-3 * pe0, Text(Text::number(ke / pe0)).c_str());
            VERIFY2(perBall <= 4.0 && perBall >= 1.5, Text(Text::number(perBall)).c_str());
            // 1 sub-step: balls land at up to 3 radii per step; the deepest pair
            // ends at 0.15 r (1.2 r before speculative contacts reached as far as a
            // ball moves), where 8 sub-steps hold 2%.
            VERIFY2(overlap <= (substeps == 1 ? 0.25 : 0.02), Text(Text::number(overlap)).c_str());
            VERIFY(allInside(w));
        }
    }
}

// Without gravity nothing rests: the collision stage makes its one pass and
// the resting-contact solver is never used, so gravity-free scenes keep the
// textbook step (and the energy test above).
TEST_CASE("TestCollisionWorld::gravityFreeStepIsOnePass")
{
    World w(boxOfBalls(500, 400.0, 300.0, Detection::Sweep, 0.9));
    CollisionSystem sys;
    BallState b = w.balls();
    const Matrix2X start = b.position;
    sys.step(b, start, w.settings().collisions, w.settings().box, w.settings().walls, 1.0 / 60.0);
    VERIFY(!sys.contacts().empty());
    REQUIRE_SAME(sys.lastVelocityPasses(), 0);
    BallState g = w.balls();
    sys.step(g, start, w.settings().collisions, w.settings().box, w.settings().walls, 1.0 / 60.0, Vec2(0.0, 980.0));
    VERIFY(sys.lastVelocityPasses() >= 2);
    // With resting contacts switched off (collisions.resting: false), gravity
    // changes nothing in the stage: the same one pass, to the bit.
    CollisionSettings onePass = w.settings().collisions;
    onePass.resting = false;
    CollisionSystem fresh;
    BallState o = w.balls();
    fresh.step(o, start, onePass, w.settings().box, w.settings().walls, 1.0 / 60.0, Vec2(0.0, 980.0));
    REQUIRE_SAME(fresh.lastVelocityPasses(), 0);
    VERIFY(o.position == b.position && o.velocity == b.velocity);
}

// What the resting-contact solver is for, as a student sees it when they
// switch it off: the 20-ball column of columnStandsUnderGravity (clamp walls,
// 1 sub-step) with one pass of 2d-impulse per step sinks into itself. The
// push of gravity reaches one ball further down per pass, and positional
// correction cannot hold the weight: after 10 s the column is well under
// 90% of its 400 px (measured: 221.5 px), where the solver keeps it at 397 px.
TEST_CASE("TestCollisionWorld::columnSinksWithOnePass")
{
    const Scene s = columnScene(WallModel::Clamp, 1);
    const double r = s.balls.front().radius;
    auto heightAfter10s = [&](bool resting) -> double {
        Scene t = s;
        t.settings.collisions.resting = resting;
        World w(t);
        for (int step = 0; step < 600; ++step)
            w.step();
        const BallState& b = w.balls();
        if (!b.position.allFinite())
            return std::nan(""); // fails both checks below
        return b.position.row(1).maxCoeff() - b.position.row(1).minCoeff() + 2.0 * r;
    };
    const double solved = heightAfter10s(true), onePass = heightAfter10s(false);
    forcelab::test::report("column after 10 s: %.1f px with resting contacts, %.1f px with one pass", solved, onePass);
    VERIFY2(solved >= 0.98 * 400.0, Text(Text::number(solved)).c_str());
    VERIFY2(onePass < 0.9 * 400.0, Text(Text::number(onePass)).c_str());
}

// The resting-contact solver (gravity on) only exchanges equal and opposite
// impulses within pairs, so with the walls off a collision stage never
// changes the total momentum, and a ball farther from every other than their
// radii and speculative margins (speculative_margin.h: |v − u|·h + |g|·h²,
// u the mean velocity around it, at most `speculative` radii) keeps its
// velocity and position to the bit. Where the balls go:
//  * one stage moves each ball by its own change of velocity times h and
//    pushes overlapping pairs apart in proportion to inverse mass
//    (m_a·Δx_a = −m_b·Δx_b), so the centre of mass stays where it was;
//  * the staged solve (K stages of hs = h/K) starts the balls it moves at
//    x − v·h with v − g·h and gives them g·hs per stage, so their centre of
//    mass moves by what that gravity does over the stages less the v·h the
//    stage takes back: M·(−h² + hs²·K(K+1)/2)·g = −M·g·h²·(K−1)/(2K), M
//    the mass of the balls it moved.
// The stage runs on its own (no integration), ten times on the same balls,
// so each solve starts from the last one's state and warm start. The masses
// differ (∝ r³, radii 3–6 px), so a ball's result written back to another
// ball would show in the momentum.
TEST_CASE("TestCollisionWorld::restingSolverKeepsMomentumAndCentre")
{
    for (const int stages : {1, 4}) {
        CAPTURE(stages);
        Scene s = boxOfBalls(800, 500.0, 500.0, Detection::Sweep, 0.9);
        s.settings.walls = WallSettings{false, false, false, false, WallModel::Clamp, 1.0};
        const World w(s);
        BallState b = w.balls();
        const int n = b.size();
        CollisionSystem sys;
        ContactSolverSettings solver = sys.solverSettings();
        solver.stages = stages;
        sys.setSolverSettings(solver);
        // How far a ball's speculative contacts reach: the margins the collision
        // stage computes (speculative_margin.h), from the balls as they are.
        const double cap = solver.speculative;
        std::vector<double> grow;
        SpeculativeMargin margin;
        auto reach = [&](int i) { return grow[static_cast<std::size_t>(i)]; };
        auto isolatedBalls = [&] {
            const double h = 1.0 / 60.0;
            margin.compute(b, h, 980.0 * h * h, cap, grow);
            std::vector<int> out;
            for (int i = 0; i < n; ++i) {
                bool alone = true;
                for (int j = 0; j < n && alone; ++j)
                    alone = j == i || (b.position.col(i) - b.position.col(j)).norm() >
                                          1.01 * (b.radius[i] + b.radius[j] + reach(i) + reach(j));
                if (alone)
                    out.push_back(i);
            }
            return out;
        };

        const Vec2 p0 = b.velocity * b.mass;
        const double momentumScale = (b.velocity.colwise().norm().transpose().array() * b.mass.array()).sum();
        const double centreScale = 500.0 * b.mass.sum();
        const double h = 1.0 / 60.0, g = 980.0;
        double worstP = 0.0, worstC = 0.0;
        std::size_t contacts = 0, untouched = 0;
        for (int k = 0; k < 10; ++k) {
            const std::vector<int> isolated = isolatedBalls();
            const Matrix2X v0 = b.velocity, x0 = b.position;
            sys.step(b, x0, s.settings.collisions, s.settings.box, s.settings.walls, h, Vec2(0.0, g));
            if (k == 0)
                VERIFY(sys.lastVelocityPasses() >= 2); // later stages settle and may stop after one pass
            contacts += sys.contacts().size();
            worstP = std::max(worstP, (b.velocity * b.mass - p0).norm() / momentumScale);
            // The centre of mass, against where this solve kind puts it: the
            // staged solve moves the balls its rows pushed by their share of
            // gravity's lag; the exact impulses of free pairs (free_impacts.h)
            // and positional correction keep the centre where it was.
            double moved = 0.0; // mass of the balls the solve's rows moved
            const std::vector<unsigned char>& held = sys.lastHeld();
            for (int i = 0; i < n; ++i)
                if ((b.position.col(i) != x0.col(i) || b.velocity.col(i) != v0.col(i)) &&
                    (stages == 1 || held[static_cast<std::size_t>(i)]))
                    moved += b.mass[i];
            const Vec2 expected(0.0, -moved * g * h * h * (stages - 1) / (2.0 * stages));
            worstC = std::max(worstC, ((b.position - x0) * b.mass - expected).norm() / centreScale);
            for (int i : isolated) {
                REQUIRE_SAME(b.velocity.col(i), v0.col(i));
                REQUIRE_SAME(b.position.col(i), x0.col(i));
            }
            untouched += isolated.size();
        }
        forcelab::test::report("resting solver, %d stage(s), 10 solves: momentum change %.3g of sum m|v|, centre of mass "
                               "off by %.3g of the box (%zu contacts, %zu isolated balls left alone)",
                               stages, worstP, worstC, contacts, untouched);
        VERIFY(contacts > 500); // the solver really had work
        // 247 measured: these balls move at random (up to 100 px/s each), so
        // their speeds against their neighbours' mean are as large as their own.
        VERIFY(untouched > 200);
        VERIFY2(worstP <= 1e-13, Text(Text::number(worstP)).c_str());
        VERIFY2(worstC <= 1e-13, Text(Text::number(worstC)).c_str());
    }
}


// Issue #18, item 2: the resting solver must not touch a lone bouncing ball.
// An e = 1 ball in an empty box, with collisions on (2d-impulse, so the
// solver and its wall rows run every step), exact walls and the exact
// integrator, keeps its energy to 1e-9 over 10^4 wall hits. Before the wall
// rows allowed the speed that reaches the wall (gap/h plus the speed the
// integrator already moved the ball by), a ball that came within one step
// of the floor was stopped short: at 737 px/s, 0.16 px above it, it went on
// at 9.5 px/s.
TEST_CASE("TestCollisionWorld::restitutionOneKeepsEnergyWithTheSolver")
{
    for (const double dt : {1.0 / 60.0, 1.0 / 240.0}) {
        Scene s;
        s.settings.box = BoxSettings{600.0, 400.0};
        s.settings.walls = WallSettings{true, true, true, true, WallModel::Exact, 1.0};
        s.settings.gravity.enabled = true;
        s.settings.gravity.g = Vec2(0.0, 980.0);
        s.settings.time.integrator = IntegratorKind::Exact;
        s.settings.time.dt = dt;
        s.settings.collisions.response = Response::Impulse2D;
        s.settings.collisions.restitution = 1.0;
        Ball ball;
        ball.position = Vec2(300.0, 100.0);
        ball.velocity = Vec2(37.0, 0.0);
        ball.radius = 10.0;
        s.balls = {ball};
        World w(s);
        // Energy measured from the floor, so it is the scale of the motion.
        auto energy = [&] {
            const BallState& b = w.balls();
            return 0.5 * b.mass[0] * b.velocity.col(0).squaredNorm() + b.mass[0] * 980.0 * (390.0 - b.position(1, 0));
        };
        const double e0 = energy();
        while (w.totals().wallHits < 10000)
            w.step();
        const double rel = std::abs(energy() - e0) / e0;
        forcelab::test::report("e = 1, solver on, dt %.4g: after %lld wall hits (t = %.0f s) energy off by %.3g", dt,
                               static_cast<long long>(w.totals().wallHits), w.time(), rel);
        VERIFY2(rel <= 1e-9, Text(Text::number(rel)).c_str());
        VERIFY(w.collisionSystem().lastVelocityPasses() >= 1); // the resting solver ran
    }
}

// The speculative margins (speculative_margin.h) lose no pair: for 3,000
// balls with random velocities (a falling cloud, a fast stream crossing it,
// still balls), every pair close enough to touch within the cap has
// grow_a + grow_b ≥ |v_b − v_a|·h or one ball at the cap, checked against all
// pairs; and a cloud moving as one grows its balls by far less than |v|·h.
TEST_CASE("TestCollisionWorld::speculativeMarginsFindEveryPair")
{
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    BallState b;
    const int n = 3000;
    b.resize(n);
    for (int i = 0; i < n; ++i) {
        b.position.col(i) = Vec2(1200.0 * u(rng), 900.0 * u(rng));
        b.radius[i] = 3.0 + 3.0 * u(rng);
        const double kind = u(rng);
        const Vec2 fall(0.0, 900.0 + 20.0 * u(rng));
        const Vec2 stream(-1500.0 + 50.0 * u(rng), 300.0 * u(rng));
        b.velocity.col(i) = kind < 0.5 ? fall : kind < 0.8 ? stream : Vec2::Zero();
    }
    const double h = 1.0 / 60.0, cap = 4.0;
    std::vector<double> grow;
    SpeculativeMargin margin;
    margin.compute(b, h, 0.0, cap, grow);
    VERIFY(margin.columns() > 2 && margin.rows() > 2);
    std::int64_t checked = 0;
    for (int a = 0; a < n; ++a) {
        for (int c = a + 1; c < n; ++c) {
            const double d = (b.position.col(c) - b.position.col(a)).norm();
            const double need = (b.velocity.col(c) - b.velocity.col(a)).norm() * h;
            if (d > b.radius[a] + b.radius[c] + need)
                continue; // they cannot touch within the sub-step
            const bool capped = grow[std::size_t(a)] == cap * b.radius[a] || grow[std::size_t(c)] == cap * b.radius[c];
            ++checked;
            VERIFY2(capped || grow[std::size_t(a)] + grow[std::size_t(c)] >= need * (1.0 - 1e-12),
                    Text(Text::number(a)).c_str());
        }
    }
    forcelab::test::report("speculative margins: %lld pairs that can touch checked, grid %d x %d",
                           static_cast<long long>(checked), margin.columns(), margin.rows());
    VERIFY(checked > 1000);
    // All balls falling together at 900-920 px/s: |v|·h is 15 px, the margins
    // are what the 20 px/s spread allows (at most 2·20·h = 0.67 px).
    for (int i = 0; i < n; ++i)
        b.velocity.col(i) = Vec2(0.0, 900.0 + 20.0 * u(rng));
    margin.compute(b, h, 0.0, cap, grow);
    VERIFY(*std::max_element(grow.begin(), grow.end()) <= 2.0 * 20.0 * h + 1e-9);
}

// measurePile on three balls of r = 5 px in a box 100 px tall: two side by
// side on the floor (0.3 px apart, within the 0.5 px that counts as
// touching) moving at 3 and 4 px/s, one 20 px above them at 12 px/s. The
// rms over all three is √((9 + 16 + 144)/3) = 7.51 px/s; the pile is the two
// on the floor, √((9 + 16)/2) = 3.54 px/s, and one ball is in flight. Moved
// 0.6 px apart and 0.6 px off the floor, the right one is in flight too.
TEST_CASE("TestCollisionWorld::pileMeasuresLeaveOutBallsInFlight")
{
    std::vector<double> x{20.0, 30.3, 25.0}, y{95.0, 95.0, 75.0}, vx{3.0, 0.0, 0.0}, vy{0.0, 4.0, -12.0},
        r{5.0, 5.0, 5.0};
    PileMeasures m = measurePile(x, y, vx, vy, r, 100.0);
    CHECK(m.rmsSpeed == doctest::Approx(std::sqrt(169.0 / 3.0)).epsilon(1e-12));
    CHECK(m.pileRmsSpeed == doctest::Approx(std::sqrt(12.5)).epsilon(1e-12));
    CHECK(m.inFlight == 1);
    CHECK(m.overlapping == 0);
    x[1] = 30.6;
    y[1] = 94.4;
    m = measurePile(x, y, vx, vy, r, 100.0);
    CHECK(m.inFlight == 2);
    CHECK(m.pileRmsSpeed == doctest::Approx(3.0).epsilon(1e-12));
}

// The peer scene at 5,000 balls (r = 5 px, 30% of the box, e = 0.9,
// 60 Hz, one sub-step): after 10 s the pile stands still. Targets (issue
// #18, item 1): rms speed below 1 px/s (measured 0.16), deepest overlap below
// 0.3 r (0.087 r), mean overlap below 0.05 r (0.0038 r), mean height within
// 2% of the 4-sub-step pile's 192.7 px (192.3 px; `forcelab-cli pile
// --substeps 4` prints it). The one-stage solve reached 3.0 px/s here.
TEST_CASE("TestCollisionWorld::peerPileStandsAtOneSubStep")
{
    World w(peerScene(5000));
    for (int step = 0; step < 600; ++step)
        w.step();
    const PileMeasures m = measurePile(w);
    forcelab::test::report("peer pile, 5,000 balls, 10 s: deepest overlap %.3f r, mean %.4f r, rms speed %.2f px/s, mean height %.1f px",
                           m.deepestOverlap, m.meanOverlap, m.rmsSpeed, m.meanHeight);
    VERIFY2(m.rmsSpeed < 1.0, Text(Text::number(m.rmsSpeed)).c_str());
    VERIFY2(m.deepestOverlap < 0.3, Text(Text::number(m.deepestOverlap)).c_str());
    VERIFY2(m.meanOverlap < 0.05, Text(Text::number(m.meanOverlap)).c_str());
    VERIFY2(std::abs(m.meanHeight - 192.7) <= 0.02 * 192.7, Text(Text::number(m.meanHeight)).c_str());
    VERIFY(allInside(w));
}

namespace {

// The rise of a ball dropped from h0 onto the top of a resting pile of 500
// balls (the pile settled for 15 s first), and the most rows that alone got
// the extra passes of a bounce in any step of the drop.
struct Drop {
    double touching = 0.0; // centre height where it meets the top ball, px
    double rebound = 0.0;  // how far it rises above that, px
    std::size_t regionRows = 0;
    int asleepBefore = 0;   // most balls asleep in a step before the dropped ball turns back
    int asleepAtImpact = 0; // balls asleep in the step it first turns back
};

class PileDrop {
public:
    PileDrop()
        : m_scene(boxScene(500, 5.0, 5.0, 0.0, 0.9, Detection::Grid, 3))
    {
        m_scene.settings.box.height *= 2.0; // room to drop from
        for (Ball& b : m_scene.balls)
            b.position.y() += 0.5 * m_scene.settings.box.height;
        World settle(m_scene);
        for (int step = 0; step < 900; ++step)
            settle.step();
        m_pile = settle.balls();
        // The highest ball near the middle that a ball falling straight onto
        // its centre meets before any other (a higher neighbour up to 2r to
        // the side would be met first, and the bounce would go sideways).
        const double middle = 0.5 * m_scene.settings.box.width, reach = 10.0;
        for (int i = 0; i < m_pile.size(); ++i) {
            const double x = m_pile.position(0, i), y = m_pile.position(1, i);
            if (std::abs(x - middle) > 30.0 || (m_top >= 0 && y >= m_pile.position(1, m_top)))
                continue;
            bool firstMet = true;
            for (int j = 0; j < m_pile.size() && firstMet; ++j) {
                const double dx = m_pile.position(0, j) - x;
                firstMet = j == i || std::abs(dx) >= reach ||
                           m_pile.position(1, j) - std::sqrt(reach * reach - dx * dx) >= y - reach;
            }
            if (firstMet)
                m_top = i;
        }
    }
    bool found() const { return m_top >= 0; }
    int size() const { return m_pile.size(); }

    // sleepTime 0: no ball sleeps.
    Drop drop(double h0, int bounceLayers, double sleepTime = ContactSolverSettings{}.sleepTime) const
    {
        Scene drop = m_scene;
        for (int i = 0; i < m_pile.size(); ++i) {
            drop.balls[static_cast<std::size_t>(i)].position = m_pile.position.col(i);
            drop.balls[static_cast<std::size_t>(i)].velocity = m_pile.velocity.col(i);
        }
        Drop d;
        d.touching = m_pile.position(1, m_top) - 10.0;
        Ball ball = m_scene.balls[0];
        ball.position = Vec2(m_pile.position(0, m_top), d.touching - h0);
        ball.velocity = Vec2(0.0, 0.0);
        drop.balls.push_back(ball);
        World w(drop);
        ContactSolverSettings solver = w.collisionSystem().solverSettings();
        solver.bounceLayers = bounceLayers;
        solver.sleepTime = sleepTime;
        w.collisionSystem().setSolverSettings(solver);
        const int id = w.balls().size() - 1;
        bool bounced = false;
        double apex = d.touching;
        for (int step = 0; step < 600; ++step) {
            w.step();
            d.regionRows = std::max(d.regionRows, w.collisionSystem().lastBounceRegionRows());
            const double y = w.balls().position(1, id), vy = w.balls().velocity(1, id);
            if (!bounced && vy < 0.0)
                d.asleepAtImpact = w.collisionSystem().sleepingCount();
            if (!bounced && vy >= 0.0)
                d.asleepBefore = std::max(d.asleepBefore, w.collisionSystem().sleepingCount());
            bounced = bounced || vy < 0.0;
            if (bounced) {
                apex = std::min(apex, y);
                if (vy > 0.0)
                    break;
            }
        }
        d.rebound = d.touching - apex;
        return d;
    }

private:
    Scene m_scene;
    BallState m_pile;
    int m_top = -1;
};

} // namespace

// A ball dropped from h0 onto a resting pile of equal balls bounces with the
// restitution e = 0.9: it rises e²·h0 above the point where it touched, as
// from a floor, because the pile holds while the bounce is made. At 60 Hz
// the step stops the ball at the surface up to one step's fall early, which
// costs some of the rebound (measured 81% from 100 px and from 200 px with
// the staged solve; 85% and 93% with one stage); the check asks for 75%.
// When the pile gives way the ball rises 5-7% of e²·h0
// (what it did before the bounce was solved with the other contacts).
TEST_CASE("TestCollisionWorld::ballBouncesOnRestingPile")
{
    const PileDrop pile;
    REQUIRE(pile.found());
    for (const double h0 : {100.0, 200.0}) {
        const Drop d = pile.drop(h0, ContactSolverSettings{}.bounceLayers);
        const double expected = 0.81 * h0;
        forcelab::test::report("dropped from %.0f px on the pile: rises %.1f px, e^2 h0 = %.1f px", h0, d.rebound, expected);
        VERIFY2(d.rebound >= 0.75 * expected && d.rebound <= 1.02 * expected, Text(Text::number(d.rebound)).c_str());
    }
}

// The passes a bounce adds go only to the rows within bounceLayers balls of
// it (staged_solve.cpp, finalPasses), and the ball rises as high as when every row
// gets them (to 2%; measured 0.4%). With 4 layers instead of 12 it rose 20%
// less: the pile under it gave way.
TEST_CASE("TestCollisionWorld::bounceOnPileNeedsOnlyTheRowsNearIt")
{
    const PileDrop pile;
    REQUIRE(pile.found());
    const Drop everyRow = pile.drop(200.0, 0, 0.0);
    const Drop nearRows = pile.drop(200.0, ContactSolverSettings{}.bounceLayers, 0.0);
    forcelab::test::report("dropped from 200 px: rises %.2f px with every row, %.2f px with the %zu rows near the bounce",
                           everyRow.rebound, nearRows.rebound, nearRows.regionRows);
    VERIFY(everyRow.regionRows == 0);
    VERIFY(nearRows.regionRows > 0); // the rows near it were fewer than half: the region was used
    VERIFY2(std::abs(nearRows.rebound - everyRow.rebound) <= 0.02 * everyRow.rebound,
            Text(Text::number(nearRows.rebound)).c_str());
}

// A pile asleep is a pile that gives: the pair the falling ball makes with
// the pile wakes every sleeper within wakeLayers balls of it before the
// solve (contact_solver.h, point 7), so the ball rises as high as from the
// same pile awake (to 2%), and the bounce does not wake the whole pile.
TEST_CASE("TestCollisionWorld::ballBouncesOnSleepingPileAsOnAwakeOne")
{
    const PileDrop pile;
    REQUIRE(pile.found());
    const Drop awake = pile.drop(200.0, ContactSolverSettings{}.bounceLayers, 0.0);
    const Drop asleep = pile.drop(200.0, ContactSolverSettings{}.bounceLayers);
    forcelab::test::report("dropped from 200 px: rises %.2f px from the pile awake, %.2f px from the pile with %d of "
                           "%d balls asleep (%d still asleep as it bounced)",
                           awake.rebound, asleep.rebound, asleep.asleepBefore, pile.size(), asleep.asleepAtImpact);
    VERIFY(awake.asleepBefore == 0);
    VERIFY(asleep.asleepBefore >= pile.size() * 4 / 5); // the ball came down on a pile asleep
    VERIFY(asleep.asleepAtImpact > 0 && asleep.asleepAtImpact < asleep.asleepBefore); // it woke a part of it
    VERIFY2(std::abs(asleep.rebound - awake.rebound) <= 0.02 * awake.rebound, Text(Text::number(asleep.rebound)).c_str());
}

namespace {

// Two balls of 10 px on the floor of a 600 × 400 box under gravity: `rest`
// still at x = 300, `mover` at x = 100 with no speed yet.
Scene twoBallsOnTheFloor()
{
    Scene s;
    s.settings.box = BoxSettings{600.0, 400.0};
    s.settings.walls = WallSettings{true, true, true, true, WallModel::Clamp, 0.9};
    s.settings.gravity.enabled = true;
    s.settings.gravity.g = Vec2(0.0, 980.0);
    s.settings.collisions.response = Response::Impulse2D;
    s.settings.collisions.restitution = 0.9;
    Ball ball;
    ball.radius = 10.0;
    ball.position = Vec2(300.0, 390.0);
    s.balls = {ball};
    ball.position = Vec2(100.0, 390.0);
    s.balls.push_back(ball);
    return s;
}

} // namespace

// A sleeper is a ball of infinite mass only until something pushes on it:
// a ball rolling into a sleeping ball at 30 px/s (slower than v_rest =
// 2 g dt = 32.7 px/s, so the pair does not bounce: e = 0) wakes it before
// the solve, and the two share the momentum, 15 px/s each, along the floor,
// where no wall acts (x momentum kept to 1e-12 of m·30 px/s).
TEST_CASE("TestCollisionWorld::aBallPushingASleeperWakesIt")
{
    World w(twoBallsOnTheFloor());
    for (int step = 0; step < 60; ++step)
        w.step();
    REQUIRE(w.collisionSystem().sleepingCount() == 2); // both rest on the floor
    BallState& b = w.mutableBalls(); // an edit wakes both
    VERIFY(w.collisionSystem().sleepingCount() == 0);
    b.velocity.col(1) = Vec2(30.0, 0.0);
    const double p0 = b.mass[1] * 30.0;
    // The one at rest falls asleep again while the mover rolls on; the
    // last step in which it slept and the first in which it moved.
    int sleptUntil = -1, movedAt = -1;
    for (int step = 0; step < 600 && movedAt < 0; ++step) {
        if (w.collisionSystem().sleeping() && w.collisionSystem().sleeping()[0])
            sleptUntil = step;
        w.step();
        if (w.balls().velocity(0, 0) > 0.0)
            movedAt = step;
    }
    for (int step = 0; step < 60 && w.balls().velocity(0, 0) < w.balls().velocity(0, 1); ++step)
        w.step(); // until the two move as one
    const BallState& after = w.balls();
    const double p1 = (after.velocity.row(0).transpose().array() * after.mass.array()).sum();
    forcelab::test::report("ball at 30 px/s meets a sleeper: speeds after %.4f and %.4f px/s, x momentum off by %.3g",
                           after.velocity(0, 1), after.velocity(0, 0), std::abs(p1 - p0) / p0);
    VERIFY(sleptUntil > 0 && movedAt >= sleptUntil && movedAt <= sleptUntil + 2); // asleep until it was met
    VERIFY(std::abs(after.velocity(0, 0) - 15.0) <= 0.01 * 15.0);
    VERIFY(std::abs(after.velocity(0, 1) - 15.0) <= 0.01 * 15.0);
    VERIFY2(std::abs(p1 - p0) <= 1e-12 * p0, Text(Text::number(std::abs(p1 - p0) / p0)).c_str());
}

// A sleeping ball must feel what changes: new settings wake every ball
// (gravity turned to the side topples the pile), and while a force
// that changes with time acts (wind), no ball sleeps at all.
TEST_CASE("TestCollisionWorld::editsAndChangingForcesKeepBallsAwake")
{
    Scene s = boxScene(300, 5.0, 5.0, 0.0, 0.9, Detection::Grid, 5);
    World w(s);
    for (int step = 0; step < 300; ++step)
        w.step();
    const int asleep = w.collisionSystem().sleepingCount();
    REQUIRE(asleep > 250); // the pile sleeps after 5 s
    const Matrix2X before = w.balls().position;
    WorldSettings tilted = w.settings();
    tilted.gravity.g = Vec2(980.0, 0.0); // the box turned on its side
    REQUIRE(!w.setSettings(tilted));
    VERIFY(w.collisionSystem().sleepingCount() == 0);
    for (int step = 0; step < 60; ++step)
        w.step();
    int moved = 0;
    for (int i = 0; i < w.balls().size(); ++i)
        moved += (w.balls().position.col(i) - before.col(i)).norm() > 1.0 ? 1 : 0;
    forcelab::test::report("%d of 300 balls asleep at 5 s; gravity turned sideways: %d balls moved more than 1 px in 1 s",
                           asleep, moved);
    VERIFY(moved > 150);

    World windy(s);
    WorldSettings wind = windy.settings();
    wind.wind.mode = WindMode::Random;
    wind.wind.strength = 5.0;
    REQUIRE(!windy.setSettings(wind));
    int most = 0;
    for (int step = 0; step < 300; ++step) {
        windy.step();
        most = std::max(most, windy.collisionSystem().sleepingCount());
    }
    VERIFY(most == 0);
}


// A pile whose every ball sleeps costs no detection and no solve: its steps
// leave every ball where it is, to the bit, with the same touching pairs,
// and find no pair. A ball added to it (an edit) wakes it at the next step.
TEST_CASE("TestCollisionWorld::aPileAsleepIsNotDetected")
{
    World w(boxScene(300, 5.0, 5.0, 0.0, 0.9, Detection::Grid, 5));
    int steps = 0;
    while (w.collisionSystem().sleepingCount() < w.balls().size() && steps < 1200) {
        w.step();
        ++steps;
    }
    REQUIRE(w.collisionSystem().sleepingCount() == w.balls().size());
    w.step(); // the step that finds the pairs where the balls now sleep
    VERIFY(w.lastStep().pairsTested > 0);
    const Matrix2X position = w.balls().position, velocity = w.balls().velocity;
    const std::vector<Contact> touching = w.contacts();
    REQUIRE(!touching.empty());
    const double t0 = w.time();
    std::int64_t tested = 0;
    for (int step = 0; step < 120; ++step) {
        w.step();
        tested += w.lastStep().pairsTested;
        VERIFY(w.lastStep().contacts == static_cast<std::int64_t>(touching.size()));
    }
    forcelab::test::report("300 balls all asleep after %d steps; 120 steps later: %lld pairs tested, %zu touching",
                           steps, static_cast<long long>(tested), touching.size());
    VERIFY(tested == 0);
    VERIFY(std::abs(w.time() - t0 - 120.0 / 60.0) < 1e-9);
    VERIFY(w.balls().position == position); // to the bit
    VERIFY(w.balls().velocity == velocity);
    VERIFY(w.contacts().size() == touching.size());
    for (std::size_t k = 0; k < touching.size(); ++k)
        VERIFY(w.contacts()[k].a == touching[k].a && w.contacts()[k].b == touching[k].b);

    // A ball laid on the pile wakes it: the next step finds pairs again.
    Ball dropped;
    dropped.radius = 5.0;
    dropped.position = Vec2(0.5 * w.settings().box.width, 20.0);
    w.mutableBalls().append(dropped);
    VERIFY(w.collisionSystem().sleepingCount() == 0);
    w.step();
    VERIFY(w.lastStep().pairsTested > 0);
}


namespace {

// A pile of 30 balls of r = 10 px in four close-packed rows (8, 7, 8, 7)
// wedged between the walls of a box 160 px wide, under g = 980 px/s², with
// ball and wall restitution e and the given integrator at 60 Hz and one
// sub-step. The pile settles for 2 s (it falls asleep), then a ball is
// dropped from rest, centred over the middle ball of the top row, with its
// bottom h0 above that ball's top.
struct PileBounce {
    double fall = 0.0;      // px, the height the ball's energy came from, just before it hit
    double rebound = 0.0;   // px, apex of the rise above the point where the balls touch
    double topMoved = 0.0;  // px, how far the top ball had moved when the dropped one turned back
};

PileBounce bounceOnSmallPile(double e, IntegratorKind integrator, double h0)
{
    const double r = 10.0, g = 980.0;
    const int across = 8;
    Scene s;
    s.settings.box = BoxSettings{2.0 * r * across, 800.0};
    s.settings.walls = WallSettings{true, true, true, true, WallModel::Clamp, e};
    s.settings.gravity.enabled = true;
    s.settings.gravity.g = Vec2(0.0, g);
    s.settings.time.integrator = integrator;
    s.settings.collisions.response = Response::Impulse2D;
    s.settings.collisions.restitution = e;
    Ball ball;
    ball.radius = r;
    for (int row = 0; row < 4; ++row) {
        const bool odd = row % 2 == 1;
        for (int i = 0; i < (odd ? across - 1 : across); ++i) {
            ball.position = Vec2((odd ? 2.0 * r : r) + 2.0 * r * i, s.settings.box.height - r - row * std::sqrt(3.0) * r);
            s.balls.push_back(ball);
        }
    }
    World settle(s);
    for (int step = 0; step < 120; ++step)
        settle.step();
    const BallState& pile = settle.balls();
    const double middle = 0.5 * s.settings.box.width;
    int top = 0;
    for (int i = 0; i < pile.size(); ++i)
        if (std::abs(pile.position(0, i) - middle) < r && pile.position(1, i) < pile.position(1, top))
            top = i;
    for (int i = 0; i < pile.size(); ++i) {
        s.balls[static_cast<std::size_t>(i)].position = pile.position.col(i);
        s.balls[static_cast<std::size_t>(i)].velocity = pile.velocity.col(i);
    }
    const double top0 = pile.position(1, top);
    ball.position = Vec2(pile.position(0, top), top0 - 2.0 * r - h0);
    ball.velocity = Vec2(0.0, 0.0);
    s.balls.push_back(ball);
    World w(s);
    const int id = w.balls().size() - 1;
    PileBounce b;
    for (int step = 0; step < 120; ++step) {
        w.step();
        const double y = w.balls().position(1, id), vy = w.balls().velocity(1, id);
        const double topY = w.balls().position(1, top);
        if (vy < 0.0) { // turned back: from here it flies free
            b.topMoved = std::abs(topY - top0);
            b.rebound = (topY - 2.0 * r) - (y - vy * vy / (2.0 * g));
            break;
        }
        b.fall = (topY - 2.0 * r) - (y - vy * vy / (2.0 * g)); // still falling: the apex its energy came from
    }
    return b;
}

} // namespace

// Issue #31, item 6: a ball dropped on a resting pile bounces as from a
// floor, rising e² times its fall (within 5%) at e = 1, 0.8 and 0.5 with
// every fixed-step integrator at one sub-step. h0 = 200 px is the drop of
// the ball's bottom onto the top ball's top. The fall is measured from the
// state the step before it hits (the apex its energy came from, y − v²/2g
// above the touching point: 200 px for verlet, rk4 and yoshida4, 195 px for
// semi-implicit Euler, which loses v·h/2 on the way down) and the rise from
// where the two touch to the apex of the free flight the ball starts on, so
// the integrators' own errors on the way down and up are not the bounce's.
// Before the fix the ball rose 89-90% of e²·h0 with semi-implicit Euler,
// 41-46% with verlet, rk4 and yoshida4, 2-25% with Euler; now 95.5-96.8% of
// e² times its fall with all five. The top ball moves less than 1 px
// meanwhile.
TEST_CASE("TestCollisionWorld::ballBouncesOnRestingPileWithEveryIntegrator")
{
    const std::pair<const char*, IntegratorKind> integrators[] = {
        {"euler", IntegratorKind::Euler},   {"semi-implicit-euler", IntegratorKind::SemiImplicitEuler},
        {"verlet", IntegratorKind::Verlet}, {"rk4", IntegratorKind::Rk4},
        {"yoshida4", IntegratorKind::Yoshida4}};
    const double h0 = 200.0;
    double worst = 0.0, mostMoved = 0.0;
    for (const auto& [name, kind] : integrators)
        for (const double e : {1.0, 0.8, 0.5}) {
            const PileBounce b = bounceOnSmallPile(e, kind, h0);
            const double expected = e * e * b.fall;
            forcelab::test::report("%s, e = %.1f: fell %.1f px, rises %.1f px, e^2 fall = %.1f px (%.3f; %.3f of e^2 h0), "
                                   "top ball moved %.2f px",
                                   name, e, b.fall, b.rebound, expected, b.rebound / expected,
                                   b.rebound / (e * e * h0), b.topMoved);
            worst = std::max(worst, std::abs(b.rebound - expected) / expected);
            mostMoved = std::max(mostMoved, b.topMoved);
        }
    VERIFY2(worst <= 0.05, Text(Text::number(worst)).c_str());
    VERIFY2(mostMoved < 1.0, Text(Text::number(mostMoved)).c_str());
}

// The broad-phase overlay draws the detector's own cells and rows: before the
// first step the layout worked out for drawing is the one the detector then
// uses (balls at rest, no margins), and after a step it is the detector's,
// bit for bit. Before, the overlay drew rows as tall as the tallest ball
// (20 px) where the detector's are 20.5 px, so lesson 25's picture showed
// rows the search did not use.
TEST_CASE("TestCollisionWorld::drawnBroadPhaseIsTheDetectors")
{
    std::vector<Ball> balls;
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> x(20.0, 580.0), y(20.0, 380.0), r(3.0, 12.0);
    for (int i = 0; i < 60; ++i)
        balls.push_back(ballAt(x(rng), y(rng), 0.0, 0.0, r(rng)));
    for (const Detection detection : {Detection::Grid, Detection::Sweep}) {
        Scene s = openScene(balls);
        s.settings.collisions.response = Response::Flag;
        s.settings.collisions.detection = detection;
        World w(s);
        const BroadPhaseGeometry before = broadPhaseGeometry(w);
        w.step();
        const CollisionSystem& system = w.collisionSystem();
        const BroadPhaseGeometry after = broadPhaseGeometry(w);
        if (detection == Detection::Grid) {
            REQUIRE_SAME(before.cellSize, system.grid().cellSize());
            REQUIRE_SAME(before.originX, system.grid().originX());
            REQUIRE_SAME(before.originY, system.grid().originY());
            REQUIRE_SAME(after.cellSize, system.grid().cellSize());
        } else {
            REQUIRE_SAME(before.rowHeight, system.sweepAndPrune().rowHeight());
            REQUIRE_SAME(after.rowHeight, system.sweepAndPrune().rowHeight());
        }
    }
}

// Issue #39: two balls that meet fast in mid-air, under gravity with the
// resting solver on, are a free island (contact_islands.h): no solver rows,
// and the exact impulse at the moment they meet (free_impacts.h). Equal
// balls 2 px apart closing at 400 px/s meet 5 ms into the 1/60 s sub-step
// and leave at e·400 = 360 px/s, so they end 360·(h − 5 ms) = 4.2 px apart.
TEST_CASE("TestCollisionWorld::fastPairInMidAirGetsTheExactImpulse")
{
    const double r = 5.0, gap = 2.0, speed = 200.0, h = 1.0 / 60.0, g = 980.0, e = 0.9;
    Scene s = openScene({ballAt(500.0, 300.0, speed, 0.0, r), ballAt(500.0 + 2.0 * r + gap, 300.0, -speed, 0.0, r)});
    s.settings.box = BoxSettings{1000.0, 1000.0};
    s.settings.collisions.response = Response::Impulse2D;
    s.settings.collisions.restitution = e;
    s.settings.collisions.detection = Detection::Sweep;
    BallState b = World(s).balls();
    // Where the integrator (semi-implicit Euler) leaves them after one sub-step.
    const Matrix2X start = b.position;
    for (int i = 0; i < 2; ++i) {
        b.velocity(1, i) += g * h;
        b.position.col(i) += b.velocity.col(i) * h;
    }
    CollisionSystem sys;
    sys.setProfiling(true);
    sys.step(b, start, s.settings.collisions, s.settings.box, s.settings.walls, h, Vec2(0.0, g));
    VERIFY(sys.profile().rows == 0);
    const double met = gap / (2.0 * speed);
    VERIFY(std::abs((b.velocity(0, 0)) - (-e * speed)) <= 1e-9);
    VERIFY(std::abs((b.velocity(0, 1)) - (e * speed)) <= 1e-9);
    VERIFY(std::abs((b.velocity(1, 0)) - (g * h)) <= 1e-12);
    VERIFY(std::abs((b.velocity(1, 1)) - (g * h)) <= 1e-12);
    VERIFY(std::abs((b.position(0, 0)) - (500.0 + speed * met - e * speed * (h - met))) <= 1e-9);
    VERIFY(std::abs((b.position(0, 1) - b.position(0, 0) - 2.0 * r) - (2.0 * e * speed * (h - met))) <= 1e-9);
    VERIFY(std::abs((b.position(1, 0)) - (300.0 + g * h * h)) <= 1e-9);
}

// Under gravity alone two touching balls in mid-air fall as one: nothing
// presses them together, so a slow pair between them is an impact (it
// bounces at e) and needs no rows. With drag on, the balls' accelerations
// differ, and the same slow pair rests (e = 0 below v_rest, in rows).
TEST_CASE("TestCollisionWorld::slowPairFallingFreelyIsAnImpact")
{
    const double r = 5.0, gap = 0.01, speed = 1.0, e = 0.9;
    auto scene = [&](bool drag) {
        Scene s = openScene({ballAt(500.0, 300.0, speed, 0.0, r), ballAt(500.0 + 2.0 * r + gap, 300.0, -speed, 0.0, r)});
        s.settings.box = BoxSettings{1000.0, 1000.0};
        s.settings.gravity.enabled = true;
        s.settings.drag.enabled = drag;
        s.settings.collisions.response = Response::Impulse2D;
        s.settings.collisions.restitution = e;
        s.settings.collisions.detection = Detection::Sweep;
        return s;
    };
    // v_rest = 2·|g|·h = 32.7 px/s: the pair (2 px/s) is far slower, and its
    // gap closes within the step (2 px/s · h = 0.033 px > 0.01 px).
    World free(scene(false));
    free.collisionSystem().setProfiling(true);
    free.step();
    VERIFY(free.collisionSystem().profile().rows == 0);
    VERIFY(std::abs(free.balls().velocity(0, 0) - (-e * speed)) <= 1e-9);
    VERIFY(std::abs(free.balls().velocity(0, 1) - (e * speed)) <= 1e-9);
    VERIFY(std::abs(free.balls().velocity(1, 0) - free.balls().velocity(1, 1)) <= 1e-12);

    World dragged(scene(true));
    dragged.collisionSystem().setProfiling(true);
    dragged.step();
    VERIFY(dragged.collisionSystem().profile().rows > 0);
    // Resting: the pair no longer approaches, and does not bounce either.
    const double along = dragged.balls().velocity(0, 1) - dragged.balls().velocity(0, 0);
    VERIFY(std::abs(along) <= 0.05);
}
