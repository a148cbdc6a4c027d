// The timeline (sim/world/timeline.h): going back and forward again gives the
// world that never went back, bit for bit, for every integrator and every
// collision detector; an edit in the past cuts the future and restoreCut
// brings it back; the budget covers 60 s of a 2,000-ball world.

#include "sim/world/timeline.h"

#include "sim/integrators/integrator_info.h"
#include "sim/world/names.h"

#include "sim_check.h"

#include <cstring>
#include <string>
#include <vector>

#ifdef __GLIBC__
#include <malloc.h>
#endif

using namespace forcelab;
using namespace forcelab::sim;
using forcelab::test::report;

namespace {

constexpr double kDt = 1.0 / 60.0; // s

// The numbers a step leaves behind, kept to compare bits.
struct Snapshot {
    Matrix2X position; // px
    Matrix2X velocity; // px/s
    double time = 0.0; // s
    std::int64_t steps = 0;
};

Snapshot snap(const World& w)
{
    return {w.balls().position, w.balls().velocity, w.time(), w.stepCount()};
}

bool sameBits(const Matrix2X& a, const Matrix2X& b)
{
    return a.cols() == b.cols() &&
           std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

bool sameBits(double a, double b)
{
    return std::memcmp(&a, &b, sizeof a) == 0;
}

// Checks every number bit for bit; `where` names the check in the output.
void requireSame(const World& w, const Snapshot& s, const std::string& where)
{
    INFO(where);
    REQUIRE(w.stepCount() == s.steps);
    REQUIRE(sameBits(w.time(), s.time));
    REQUIRE(sameBits(w.balls().position, s.position));
    REQUIRE(sameBits(w.balls().velocity, s.velocity));
}

// Five balls in a box with walls, thrown at each other under gravity, so
// they collide with each other and the walls; drag and the pointer's pull on
// where the integrator allows them (exact needs a constant force).
Scene collisionScene(IntegratorKind integrator, Detection detection, bool continuous)
{
    Scene s = openScene({ballAt(100, 100, 220, -50, 12), ballAt(300, 120, -180, 30, 10), ballAt(200, 300, 60, -240, 14),
                         ballAt(450, 250, -90, 120, 9), ballAt(520, 80, -260, 0, 11)});
    s.settings.box = BoxSettings{600.0, 400.0};
    s.settings.walls = WallSettings{};
    s.settings.walls.restitution = 0.9;
    s.settings.gravity.enabled = true;
    s.settings.time.integrator = integrator;
    s.settings.time.dt = kDt;
    s.settings.collisions.detection = detection;
    s.settings.collisions.response = Response::Impulse2D;
    s.settings.collisions.restitution = 0.8;
    s.settings.collisions.continuous = continuous;
    if (integrator != IntegratorKind::Exact) {
        s.settings.drag.enabled = true;
        s.settings.drag.k = 0.05;
        s.settings.pointer.enabled = true;
    }
    return s;
}

// What the owner does with the pointer before step k: moves now and then,
// and sometimes moves and comes back before the step (the integrator still
// starts afresh, so the replay must know).
void movePointer(World& w, std::int64_t k)
{
    if (k % 17 == 3)
        w.setPointer({true, k % 34 == 3, Vec2(100.0 + 3.0 * static_cast<double>(k % 150), 180.0)});
    if (k % 40 == 10) {
        const PointerInput was = w.pointer();
        w.setPointer({true, true, Vec2(10.0, 10.0)});
        w.setPointer(was);
    }
}

// Steps `w` to `steps` the way an owner does: pointer, step, afterStep.
void runRecorded(World& w, Timeline& t, std::int64_t steps, std::vector<Snapshot>* out = nullptr)
{
    while (w.stepCount() < steps) {
        movePointer(w, w.stepCount());
        w.step();
        REQUIRE(!w.halted());
        t.afterStep(w);
        if (out)
            out->push_back(snap(w));
    }
}

// The world that never goes back, with the same inputs.
std::vector<Snapshot> reference(const Scene& scene, std::int64_t steps)
{
    World w(scene);
    std::vector<Snapshot> s{snap(w)};
    while (w.stepCount() < steps) {
        movePointer(w, w.stepCount());
        w.step();
        s.push_back(snap(w));
    }
    return s;
}

// Up to 20 checkpoints of this scene, every 24 steps: seeks re-run up to 23 steps.
Timeline smallTimeline()
{
    return Timeline(20 * Timeline::worldBytes(5), 4.0);
}

} // namespace

TEST_CASE("a copied world steps to the same bits as the original, for every integrator")
{
    for (const IntegratorInfo& info : integrators()) {
        INFO(std::string(info.name));
        World a(collisionScene(info.kind, Detection::Grid, false));
        for (int k = 0; k < 50; ++k)
            a.step();
        World b = a;
        for (int k = 0; k < 80; ++k) {
            a.step();
            b.step();
        }
        requireSame(b, snap(a), "copy after 50 steps, both stepped 80");
        b.mutableBalls().position(0, 0) += 1.0; // the copy is its own: a change stays in it
        CHECK(a.balls().position(0, 0) != b.balls().position(0, 0));
    }
}

TEST_CASE("seeking back and forth and stepping on gives the world that never went back, bit for bit")
{
    constexpr std::int64_t kSteps = 240;
    for (const IntegratorInfo& info : integrators())
        for (const Detection detection : {Detection::Brute, Detection::Halved, Detection::Sweep, Detection::Grid})
            for (const bool continuous : {false, true}) {
                const std::string name = std::string(info.name) + " / " + std::string(toString(detection)) +
                                         (continuous ? " / continuous" : "");
                INFO(name);
                const Scene scene = collisionScene(info.kind, detection, continuous);
                const std::vector<Snapshot> never = reference(scene, kSteps + 60);
                World w(scene);
                Timeline t = smallTimeline();
                t.start(w);
                runRecorded(w, t, kSteps);
                REQUIRE(t.earliestStep() == 0);
                REQUIRE(t.latestStep() == kSteps);
                REQUIRE(t.checkpointCount() == 11); // 0, 24, …, 240
                for (const std::int64_t s : {std::int64_t{0}, std::int64_t{7}, std::int64_t{80}, std::int64_t{239},
                                             std::int64_t{24}, std::int64_t{131}, kSteps}) {
                    REQUIRE(t.seek(s, w));
                    requireSame(w, never[static_cast<std::size_t>(s)], name + ": seek " + std::to_string(s));
                }
                // Back one step at a time, then forward by re-running the record.
                for (int k = 0; k < 30; ++k)
                    REQUIRE(t.stepBack(w));
                requireSame(w, never[kSteps - 30], name + ": 30 steps back");
                for (int k = 0; k < 30; ++k)
                    REQUIRE(t.replayStep(w));
                requireSame(w, never[kSteps], name + ": re-run to the latest");
                CHECK(!t.replayStep(w));
                CHECK(!t.seek(kSteps + 1, w));
                CHECK(!t.seek(-1, w));
                // Stepping on after going back is stepping on without having gone back.
                REQUIRE(t.seek(100, w));
                REQUIRE(t.seek(kSteps, w));
                runRecorded(w, t, kSteps + 60);
                requireSame(w, never[kSteps + 60], name + ": 60 steps on after going back");
                REQUIRE(t.seek(kSteps - 5, w));
                requireSame(w, never[kSteps - 5], name + ": the record is unchanged");
            }
}

TEST_CASE("a step taken behind the latest with the recorded inputs keeps the record")
{
    // No pointer moves: the owner stepping on from 40 gives every recorded input.
    const Scene scene = collisionScene(IntegratorKind::Rk4, Detection::Sweep, false);
    World never(scene);
    for (int k = 0; k < 120; ++k)
        never.step();
    World w(scene);
    Timeline t = smallTimeline();
    t.start(w);
    for (int k = 0; k < 120; ++k) {
        w.step();
        t.afterStep(w);
    }
    REQUIRE(t.seek(40, w));
    for (int k = 40; k < 100; ++k) {
        w.step();
        t.afterStep(w);
    }
    CHECK(t.latestStep() == 120);
    CHECK(t.lastCut() == -1);
    REQUIRE(t.seek(120, w));
    requireSame(w, snap(never), "stepped live from 40, then re-run to 120");
}

TEST_CASE("an edit in the past cuts the future; restoreCut brings it back bit for bit")
{
    for (const bool settingsEdit : {true, false}) {
        INFO(std::string(settingsEdit ? "settings edit" : "balls moved by hand"));
        const Scene scene = collisionScene(IntegratorKind::Ias15, Detection::Sweep, false);
        const std::vector<Snapshot> never = reference(scene, 180);
        World w(scene);
        Timeline t = smallTimeline();
        t.start(w);
        runRecorded(w, t, 150);
        REQUIRE(t.seek(60, w));

        // The edit, and 30 steps with it.
        const WorldSettings before = w.settings();
        const Vec2 ballBefore = w.balls().position.col(2);
        if (settingsEdit) {
            WorldSettings s = before;
            s.gravity.g = Vec2(0.0, -500.0);
            REQUIRE(!w.setSettings(s));
            t.settingsEdited(w);
        } else {
            w.mutableBalls().position.col(2) = Vec2(420.0, 200.0);
            t.edited(w);
        }
        const int cut = t.lastCut();
        REQUIRE(cut >= 0);
        CHECK(t.hasCut(cut));
        CHECK(t.latestStep() == 60);
        CHECK(!t.seek(61, w));
        runRecorded(w, t, 89);
        const Snapshot edited = snap(w);
        CHECK(!sameBits(edited.position, never[89].position));
        runRecorded(w, t, 90);

        // Undo: the owner puts its own values back, then asks for the future.
        if (settingsEdit) {
            REQUIRE(!w.setSettings(before));
            t.settingsEdited(w);
        } else {
            w.mutableBalls().position.col(2) = ballBefore;
            t.edited(w);
        }
        REQUIRE(t.restoreCut(cut, w));
        CHECK(!t.hasCut(cut));
        requireSame(w, never[60], "the world at the edit's step, before the edit");
        CHECK(t.latestStep() == 150);
        REQUIRE(t.seek(150, w));
        requireSame(w, never[150], "the old future, at its latest");
        runRecorded(w, t, 180);
        requireSame(w, never[180], "stepped on from the old future");

        // The edited future was put aside in turn: a redo brings it back (up
        // to the undo's own change at step 90, which it holds too).
        const int redo = t.lastCut();
        REQUIRE(t.seek(60, w));
        if (settingsEdit) {
            WorldSettings s = before;
            s.gravity.g = Vec2(0.0, -500.0);
            REQUIRE(!w.setSettings(s));
            t.settingsEdited(w);
        } else {
            w.mutableBalls().position.col(2) = Vec2(420.0, 200.0);
            t.edited(w);
        }
        REQUIRE(t.restoreCut(redo, w));
        REQUIRE(t.seek(89, w));
        requireSame(w, edited, "the edited future, redone");
    }
}

TEST_CASE("the pointer input is logged and replayed")
{
    // Pointer pull on: where the pointer was changes the motion, so a replay
    // that lost a move would differ.
    Scene scene = collisionScene(IntegratorKind::Verlet, Detection::Grid, false);
    scene.settings.pointer.strength = 5e6;
    const std::vector<Snapshot> never = reference(scene, 200);
    World w(scene);
    Timeline t = smallTimeline();
    t.start(w);
    runRecorded(w, t, 200);
    // Without the moves the run is another run: the moves matter.
    World still(scene);
    for (int k = 0; k < 200; ++k)
        still.step();
    CHECK(!sameBits(still.balls().position, never[200].position));
    // Away from the record's pointer, a seek puts the logged one back.
    w.setPointer({true, true, Vec2(5.0, 5.0)});
    REQUIRE(t.seek(150, w));
    requireSame(w, never[150], "seek with the owner's pointer elsewhere");
    for (int k = 150; k < 200; ++k)
        REQUIRE(t.replayStep(w));
    requireSame(w, never[200], "re-run with the logged pointer");
    // A move made while behind and then stepped ends the recorded history.
    REQUIRE(t.seek(120, w));
    w.setPointer({true, false, Vec2(590.0, 390.0)});
    w.step();
    t.afterStep(w);
    CHECK(t.latestStep() == 121);
    CHECK(t.lastCut() >= 0);
}

TEST_CASE("a pointer moved away and back before a step is replayed: the integrator starts afresh there too")
{
    // One ball on a spring, far from every wall, no collisions: nothing but
    // the pointer's change resets ias15's predictor and rk45's step guess.
    for (const IntegratorKind kind : {IntegratorKind::Ias15, IntegratorKind::Rk45}) {
        INFO(std::string(integratorInfo(kind).name));
        Scene scene = openScene({ballAt(300, 150, 120, 0)});
        scene.settings.spring.enabled = true; // a force of the position alone: nothing else resets it
        scene.settings.spring.k = 2000.0;     // 1/s², ω h = 0.75: both take several sub-steps a step
        scene.settings.time.integrator = kind;
        scene.settings.time.dt = kDt;
        const auto awayAndBack = [](World& w) {
            const PointerInput was = w.pointer();
            w.setPointer({true, true, Vec2(10.0, 10.0)});
            w.setPointer(was);
        };
        World never(scene);
        World untouched(scene);
        World w(scene);
        Timeline t = smallTimeline();
        t.start(w);
        std::vector<Snapshot> nevers{snap(never)};
        for (int k = 0; k < 100; ++k) {
            if (k == 30 || k == 31 || k == 70) {
                awayAndBack(never);
                awayAndBack(w);
            }
            never.step();
            untouched.step();
            w.step();
            t.afterStep(w);
            nevers.push_back(snap(never));
        }
        CHECK(!sameBits(untouched.balls().position, never.balls().position)); // the resets matter
        REQUIRE(t.checkpointCount() > 4); // the seeks below re-run over the resets
        for (const std::int64_t s : {39, 79, 35, 71}) {
            REQUIRE(t.seek(s, w));
            requireSame(w, nevers[static_cast<std::size_t>(s)], "seek " + std::to_string(s));
        }
        REQUIRE(t.seek(100, w));
        requireSame(w, snap(never), "the latest");
    }
}

TEST_CASE("the budget covers 60 s of a 2,000-ball world")
{
    const Timeline::Plan p = Timeline::plan(Timeline::kCoverBalls, kDt);
    report("2,000 balls: %zu B a checkpoint, %d fit in %zu B, every %lld steps, %lld steps = %.2f s covered",
           p.worldBytes, p.maxCheckpoints, Timeline::kDefaultBudget, static_cast<long long>(p.interval),
           static_cast<long long>(p.coveredSteps), p.coveredSeconds);
    CHECK(p.worldBytes == Timeline::kWorldFixedBytes + 2000 * Timeline::kWorldBytesPerBall);
    CHECK(static_cast<std::size_t>(p.maxCheckpoints) * p.worldBytes <= Timeline::kDefaultBudget);
    CHECK(p.coveredSeconds >= Timeline::kCoverSeconds);
    // The regular checkpoints the cover needs, the edits' reserve and the
    // span's start fit the budget.
    const std::int64_t regular = (p.coveredSteps + p.interval - 1) / p.interval;
    CHECK(regular + Timeline::kForcedReserve + 1 <= p.maxCheckpoints);
    CHECK(static_cast<double>(regular * p.interval) * kDt >= 60.0);
    // Fewer balls, a shorter interval: a seek re-runs fewer steps.
    CHECK(Timeline::plan(200, kDt).interval < p.interval);
    CHECK(Timeline::plan(1, kDt).interval == 1);
}

#ifdef __GLIBC__
TEST_CASE("a world's copy takes no more memory than the estimate")
{
    // The heaviest state: ias15's 46 matrices and the resting solver's pile.
    std::vector<Ball> balls;
    for (int i = 0; i < Timeline::kCoverBalls; ++i)
        balls.push_back(ballAt(10.0 + 12.0 * (i % 95), 20.0 + 12.0 * (i / 95), 0.0, 0.0, 5.0));
    Scene scene = openScene(balls);
    scene.settings.box = BoxSettings{1200.0, 800.0};
    scene.settings.gravity.enabled = true;
    scene.settings.collisions.response = Response::Impulse2D;
    scene.settings.time.integrator = IntegratorKind::Ias15;
    World w(scene);
    // Every scratch a world keeps: rk4's and rk45's stages, then ias15's state.
    for (const IntegratorKind kind : {IntegratorKind::Rk4, IntegratorKind::Rk45, IntegratorKind::Ias15}) {
        WorldSettings s = w.settings();
        s.time.integrator = kind;
        REQUIRE(!w.setSettings(s));
        w.step();
    }
    const auto used = [] {
        const struct mallinfo2 m = mallinfo2();
        return m.uordblks + m.hblkhd;
    };
    const std::size_t before = used();
    const World copy = w;
    const std::size_t after = used();
    const std::size_t bytes = after - before + sizeof(World);
    report("a 2,000-ball world's copy: %zu B measured, %zu B estimated", bytes, Timeline::worldBytes(2000));
    CHECK(copy.stepCount() == 3);
    CHECK(sameBits(copy.balls().position, w.balls().position));
    CHECK(bytes <= Timeline::worldBytes(Timeline::kCoverBalls));
}
#endif

TEST_CASE("past the budget the oldest checkpoints go, and the covered span stays")
{
    // A budget of 14 checkpoints and a 1 s cover: 5 regular intervals of 13 steps.
    const Scene scene = collisionScene(IntegratorKind::SemiImplicitEuler, Detection::Sweep, false);
    const std::size_t budget = 14 * Timeline::worldBytes(5);
    const Timeline::Plan p = Timeline::plan(5, kDt, budget, 1.0);
    REQUIRE(p.coveredSeconds >= 1.0);
    const std::vector<Snapshot> never = reference(scene, 600);
    World w(scene);
    Timeline t(budget, 1.0);
    t.start(w);
    runRecorded(w, t, 600);
    CHECK(t.bytes() <= budget);
    CHECK(t.earliestStep() > 0);
    CHECK(t.latestStep() - t.earliestStep() >= p.coveredSteps);
    CHECK(t.latestTime() - t.earliestTime() >= 1.0);
    REQUIRE(t.seek(t.earliestStep(), w));
    requireSame(w, never[static_cast<std::size_t>(t.earliestStep())], "the earliest step kept");
    CHECK(!t.seek(t.earliestStep() - 1, w));
    REQUIRE(t.seek(600, w));
    requireSame(w, never[600], "back to the latest");
}
