// Claims against closed forms: each measurement of sim/studies/claims.h on a scene
// whose answer is known, and the verdicts (holds, fails, cannot be measured).

#include "sim/studies/claims.h"
#include "sim/world/scene_keys.h"

#include "sim_check.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <numbers>

#include <string>
#include <vector>

using forcelab::test::Text;

using namespace forcelab::sim;

namespace {

// A ball of radius 10 dropped from rest with its bottom 300 px above the floor
// of a 600 × 400 box; g = 1000 px/s², the exact integrator and exact walls,
// so every bounce and apex is the closed form's to rounding.
Scene drop(double restitution)
{
    Scene s = openScene({ballAt(300, 400 - 10 - 300)});
    s.settings.walls = WallSettings{};
    s.settings.walls.model = WallModel::Exact;
    s.settings.walls.restitution = restitution;
    s.settings.gravity.enabled = true;
    s.settings.gravity.g = {0.0, 1000.0};
    s.settings.time.integrator = IntegratorKind::Exact;
    return s;
}

Claim near(std::string measure, double value, double tolerance, double at = 10.0)
{
    Claim c;
    c.text = "test";
    c.measure = std::move(measure);
    c.value = value;
    c.tolerance = tolerance;
    c.at = at;
    return c;
}

} // namespace


// Each row has its line in docs/lessons.md's table, word for word.
TEST_CASE("TestClaims::everyMeasureIsDocumented")
{
    std::ifstream doc(FORCELAB_SOURCE_DIR "/docs/lessons.md");
    VERIFY(doc);
    const std::string text((std::istreambuf_iterator<char>(doc)), std::istreambuf_iterator<char>());
    for (const ClaimMeasure& m : claimMeasures()) {
        VERIFY(!m.name.empty() && !m.unit.empty() && m.doc.size() > 20);
        REQUIRE_SAME(findClaimMeasure(m.name), &m);
        std::string row = "| `";
        row.append(m.name).append("` | ").append(m.unit).append(" | ").append(m.doc).append(" |");
        VERIFY2(text.find(row) != std::string::npos, ("docs/lessons.md lacks the row\n" + row).c_str());
    }
    VERIFY(!findClaimMeasure("apogee"));
}

// h₁ = e² h₀: the speed at the floor is √(2 g h₀), e times that after the
// bounce, and it rises (e v)²/(2g) = e² h₀. Apex n is e^(2n) h₀.
TEST_CASE("TestClaims::apexAfterABounceIsESquaredTimesTheDrop")
{
    for (const double e : {0.8, 0.5, 1.0}) {
        Claim c = near("apex", e * e * 300.0, 1e-6);
        const ClaimResult first = checkClaim(drop(e), c);
        VERIFY2(first.holds, first.explanation.c_str());
        c.occurrence = 3;
        c.value = std::pow(e, 6) * 300.0;
        const ClaimResult third = checkClaim(drop(e), c);
        VERIFY2(third.holds, third.explanation.c_str());
    }
}

// Thrown up at 600 px/s from the floor: it turns after v/g = 0.6 s, at
// v²/(2g) = 180 px.
TEST_CASE("TestClaims::turnTimeOfAThrowIsVOverG")
{
    Scene s = drop(1.0);
    s.balls[0].position.y() = 400 - 10;
    s.balls[0].velocity.y() = -600.0;
    const ClaimResult t = checkClaim(s, near("turn_time", 0.6, 1e-12, 2.0));
    VERIFY2(t.holds, t.explanation.c_str());
    const ClaimResult h = checkClaim(s, near("max_height", 180.0, 1.0 / 60 * 600, 2.0)); // sampled once a step
    VERIFY2(h.holds, h.explanation.c_str());
    const ClaimResult apex = checkClaim(s, near("apex", 180.0, 1e-9, 2.0)); // found between two steps
    VERIFY2(apex.holds, apex.explanation.c_str());
}

// a = −k (x − anchor): a swing lasts T = 2π/√k; rk4 at dt = 1/600 s keeps
// it to far better than 1e-6 over ten swings.
TEST_CASE("TestClaims::springPeriodIsTwoPiOverRootK")
{
    for (const double k : {4.0, 25.0}) {
        Scene s = openScene({ballAt(400, 200)});
        s.settings.spring.enabled = true;
        s.settings.spring.k = k;
        s.settings.time.integrator = IntegratorKind::Rk4;
        s.settings.time.dt = 1.0 / 600;
        Claim c = near("period", 2.0 * std::numbers::pi / std::sqrt(k), 1e-6, 60.0);
        c.relative = true;
        c.axis = 'x';
        c.occurrence = 10;
        const ClaimResult r = checkClaim(s, c);
        VERIFY2(r.holds, r.explanation.c_str());
    }
}

// Two balls meeting head on, elastic: Σ m v is kept to rounding.
TEST_CASE("TestClaims::elasticCollisionKeepsMomentum")
{
    Scene s = openScene({ballAt(100, 200, 300, 0, 20), ballAt(400, 200, -100, 0, 10)});
    s.settings.collisions.response = Response::Impulse2D;
    Claim c = near("momentum_drift", 0.0, 1e-12, 3.0);
    ClaimResult r = checkClaim(s, c);
    VERIFY2(r.holds, r.explanation.c_str());
    // And they did meet: the gap between their surfaces reached 0 (within a step's travel).
    c = near("min_gap", 0.0, 400.0 / 60, 3.0);
    r = checkClaim(s, c);
    VERIFY2(r.holds, r.explanation.c_str());
}

TEST_CASE("TestClaims::positionAtATime")
{
    // Free flight at 120 px/s: x = 100 + 120 t, at t = 1.5 s x = 280.
    Scene s = openScene({ballAt(100, 200, 120, 0)});
    Claim c = near("position", 280.0, 1e-9, 1.5);
    c.axis = 'x';
    const ClaimResult r = checkClaim(s, c);
    VERIFY2(r.holds, r.explanation.c_str());
}

TEST_CASE("TestClaims::boundsAndFailures")
{
    // A wrong number fails and says what was measured.
    ClaimResult r = checkClaim(drop(0.8), near("apex", 250.0, 1.0));
    VERIFY(!r.holds);
    VERIFY2(r.explanation.starts_with("measured 192 px, stated 250 px ± 1 px"), r.explanation.c_str());
    // Bounds.
    Claim below = near("apex", 200.0, 0.0);
    below.test = ClaimTest::Below;
    VERIFY(checkClaim(drop(0.8), below).holds);
    below.test = ClaimTest::Above;
    VERIFY(!checkClaim(drop(0.8), below).holds);
    // An event that does not come before `at` cannot be measured.
    r = checkClaim(drop(0.8), near("apex", 192.0, 1.0, 0.5));
    VERIFY(!r.holds && std::isnan(r.measured));
    VERIFY2(r.explanation.find("did not happen before t = 0.5 s") != std::string::npos, r.explanation.c_str());
    // A ball that is not there.
    Claim missing = near("speed", 0.0, 1.0);
    missing.ball = 3;
    r = checkClaim(drop(0.8), missing);
    VERIFY(!r.holds);
    VERIFY2(r.explanation == "the scene has 1 ball, so there is no ball 3", r.explanation.c_str());
    VERIFY(!checkClaim(drop(0.8), near("apogee", 0.0, 1.0)).holds);
}

// Linear drag with one Euler step: v ← v (1 − k dt). |1 − k dt| > 1 once
// k dt > 2: the speed grows, and the world stops itself instead of running.
TEST_CASE("TestClaims::dragStopsTheWorldWhenKTimesDtPassesTwo")
{
    Scene s = openScene({ballAt(300, 200, 100, 0)});
    s.settings.drag.enabled = true;
    s.settings.drag.scale = ForceScale::None;
    Claim c = near("stopped", 1.0, 0.0, 1.0);
    for (const auto& [k, stops] : {std::pair{150.0, true}, std::pair{90.0, false}}) { // k dt = 2.5 and 1.5
        s.settings.drag.k = k;
        const ClaimResult r = checkClaim(s, c);
        VERIFY2(r.holds == stops, r.explanation.c_str());
    }
    // At k dt = 1.5 each step multiplies v by −0.5: after one step vx = −50 px/s.
    c = near("velocity", -50.0, 1e-12, 1.0 / 60);
    c.axis = 'x';
    const ClaimResult r = checkClaim(s, c);
    VERIFY2(r.holds, r.explanation.c_str());
}

TEST_CASE("TestClaims::accelerationRatioOfTwoBallsInAPointForce")
{
    // A repelling point at (100, 200) acting as a force (scale mass): a = S (m₁₀/m) / d².
    // Ball 0 (r = 5, so m₁₀/m = 8) at d = 100, ball 1 (r = 10) at d = 200, both to its right:
    // a₀ / a₁ = 8 × (200/100)² = 32 along x.
    Scene s = openScene({ballAt(200, 200, 0, 0, 5), ballAt(300, 200, 0, 0, 10)});
    s.settings.point.enabled = true;
    s.settings.point.kind = PointKind::Repel;
    s.settings.point.position = {100.0, 200.0};
    s.settings.point.scale = ForceScale::Mass;
    Claim c = near("acceleration_ratio", 32.0, 1e-9, 0.0);
    c.axis = 'x';
    ClaimResult r = checkClaim(s, c);
    VERIFY2(r.holds, r.explanation.c_str());
    // The other way round, and with scale none only the distance counts: 1/4.
    c.ball = 1;
    c.other = 0;
    c.value = 1.0 / 32.0;
    r = checkClaim(s, c);
    VERIFY2(r.holds, r.explanation.c_str());
    s.settings.point.scale = ForceScale::None;
    c.value = 0.25;
    r = checkClaim(s, c);
    VERIFY2(r.holds, r.explanation.c_str());
    // Along y both are 0: nothing to divide by, so it cannot be measured.
    c.axis = 'y';
    r = checkClaim(s, c);
    VERIFY(!r.holds && std::isnan(r.measured));
    // A second ball that is not there.
    c.axis = 'x';
    c.other = 2;
    r = checkClaim(s, c);
    VERIFY2(r.explanation == "the scene has 2 balls, so there is no ball 2", r.explanation.c_str());
}

// N balls far apart from each other: brute force tests every ordered pair,
// N (N − 1); halved tests each pair once, N (N − 1) / 2; sort and sweep tests
// none, as no two x intervals overlap.
TEST_CASE("TestClaims::testsPerStepCountPairs")
{
    std::vector<Ball> balls;
    for (int i = 0; i < 7; ++i)
        balls.push_back(ballAt(40.0 + 70.0 * i, 200.0, 0.0, 0.0, 10.0));
    Scene s = openScene(balls);
    s.settings.collisions.response = Response::Flag;
    const int n = static_cast<int>(balls.size());
    const std::pair<Detection, double> expected[] = {
        {Detection::Brute, n * (n - 1.0)}, {Detection::Halved, n * (n - 1.0) / 2.0}, {Detection::Sweep, 0.0}};
    for (const auto& [detection, tests] : expected) {
        s.settings.collisions.detection = detection;
        const ClaimResult r = checkClaim(s, near("tests_per_step", tests, 0.0, 0.5));
        VERIFY2(r.holds, r.explanation.c_str());
    }
    // Collisions off: nothing is tested.
    s.settings.collisions.response = Response::None;
    const ClaimResult off = checkClaim(s, near("tests_per_step", 0.0, 0.0, 0.5));
    VERIFY2(off.holds, off.explanation.c_str());
}


// A claim's "set" may move a listed ball or change the number of random
// balls: the run starts from the scene the sentence describes.
TEST_CASE("TestClaims::setMovesABallAndAddsRandomBalls")
{
    // Free flight at 120 px/s from x = 250 instead of 100: x(1.5 s) = 430.
    Scene s = openScene({ballAt(100, 200, 120, 0)});
    Claim c = near("position", 430.0, 1e-9, 1.5);
    c.axis = 'x';
    c.set = {{"balls.0.x", 250.0}};
    ClaimResult r = checkClaim(s, c);
    VERIFY2(r.holds, r.explanation.c_str());
    // And with vx = −60: x = 250 − 90 = 160.
    c.set.push_back({"balls.0.vx", -60.0});
    c.value = 160.0;
    r = checkClaim(s, c);
    VERIFY2(r.holds, r.explanation.c_str());
    // The random balls come after the listed one.
    s.settings.walls = WallSettings{};
    Claim count = near("ball_count", 6.0, 0.0, 0.0);
    count.set = {{"spawn.count", 5.0}};
    r = checkClaim(s, count);
    VERIFY2(r.holds, r.explanation.c_str());
    // Keys that name nothing are refused with the reason.
    count.set = {{"balls.1.x", 0.0}};
    r = checkClaim(s, count);
    VERIFY(!r.holds);
    VERIFY2(r.explanation.find("no listed ball 1") != std::string::npos, r.explanation.c_str());
    count.set = {{"spawn.count", 2.5}};
    r = checkClaim(s, count);
    VERIFY2(!r.holds && r.explanation.find("not a whole number") != std::string::npos, r.explanation.c_str());
    count.set = {{"balls.0.colour", 1.0}};
    VERIFY(!checkClaim(s, count).holds);
}

// Two balls 15 px apart with radii 10 overlap; a third far away does not.
TEST_CASE("TestClaims::overlappingCountsBallsThatTouchAnother")
{
    Scene s = openScene({ballAt(100, 100), ballAt(115, 100), ballAt(300, 100)});
    ClaimResult r = checkClaim(s, near("overlapping", 2.0, 0.0, 0.0));
    VERIFY2(r.holds, r.explanation.c_str());
    // Moving the far ball onto the second makes it three.
    Claim c = near("overlapping", 3.0, 0.0, 0.0);
    c.set = {{"balls.2.x", 130.0}};
    r = checkClaim(s, c);
    VERIFY2(r.holds, r.explanation.c_str());
}

// Linear drag: v(t) = v₀ e^(−k t), so the kinetic energy falls as e^(−2 k t).
// rk4 at dt = 1/600 s is exact to about (k dt)⁵ per step; 1e-9 relative is ample.
// Without a force the energy stays exactly.
TEST_CASE("TestClaims::energyRatioFollowsDrag")
{
    Scene s = openScene({ballAt(300, 200, 100, 0)});
    s.settings.time.integrator = IntegratorKind::Rk4;
    s.settings.time.dt = 1.0 / 600.0;
    ClaimResult r = checkClaim(s, near("energy_ratio", 1.0, 1e-12, 2.0));
    VERIFY2(r.holds, r.explanation.c_str());
    s.settings.drag.enabled = true;
    s.settings.drag.k = 0.5;
    Claim c = near("energy_ratio", std::exp(-2.0 * 0.5 * 2.0), 0.0, 2.0);
    c.relative = true;
    c.tolerance = 1e-9;
    r = checkClaim(s, c);
    VERIFY2(r.holds, r.explanation.c_str());
}

// Two balls meet head-on once and fly apart: one contact, found in one step.
TEST_CASE("TestClaims::contactsCountsAHeadOnMeetingOnce")
{
    Scene s = openScene({ballAt(100, 200, 100, 0), ballAt(300, 200, -100, 0)});
    s.settings.collisions.response = Response::Elastic1D;
    ClaimResult r = checkClaim(s, near("contacts", 1.0, 0.0, 3.0));
    VERIFY2(r.holds, r.explanation.c_str());
    s.settings.collisions.response = Response::None;
    r = checkClaim(s, near("contacts", 0.0, 0.0, 3.0));
    VERIFY2(r.holds, r.explanation.c_str());
}

// The progress callback sees the share of the run done, rising to 1, and
// stops the run when it returns false: the result says so and holds nothing.
TEST_CASE("TestClaims::progressReportsAndCancels")
{
    const Scene s = openScene({ballAt(100, 200, 120, 0)});
    Claim c = near("position", 280.0, 1e-9, 1.5);
    c.axis = 'x';
    std::vector<double> seen;
    ClaimResult r = checkClaim(s, c, [&](double done) {
        seen.push_back(done);
        return true;
    });
    VERIFY2(r.holds && !r.cancelled, r.explanation.c_str());
    VERIFY(seen.size() == 90); // 1.5 s at dt = 1/60 s
    VERIFY(std::is_sorted(seen.begin(), seen.end()) && seen.front() > 0.0);
    VERIFY(std::abs(seen.back() - 1.0) < 1e-12);
    int calls = 0;
    r = checkClaim(s, c, [&](double) { return ++calls < 10; });
    VERIFY(r.cancelled && !r.holds && std::isnan(r.measured) && calls == 10);
}

// Two balls at rest pulled together by their own gravity: the total momentum
// stays 0 (each pair of forces cancels), while momentum_drift, a share of
// Σ m|v| at the start, has nothing to compare with and says so.
TEST_CASE("TestClaims::momentumOfABoundPairStaysZero")
{
    Scene s = openScene({ballAt(200, 200), ballAt(400, 200, 0, 0, 20)});
    s.settings.mutualGravity.enabled = true;
    // At 0.3 s, before they meet (at 0.48 s the world stops itself: no softening).
    const ClaimResult r = checkClaim(s, near("momentum", 0.0, 1e-6, 0.3));
    VERIFY2(r.holds, r.explanation.c_str());
    Claim drift = near("momentum_drift", 0.0, 1e-6, 0.3);
    const ClaimResult d = checkClaim(s, drift);
    VERIFY(!d.holds && std::isnan(d.measured));
}

// The random balls' speed range, set by a claim: with the slowest and the
// fastest both 120 px/s every ball starts at exactly 120 px/s. A range
// turned upside down is refused, whichever key did it.
TEST_CASE("TestClaims::setChangesTheRandomBallsRanges")
{
    Scene s = openScene({});
    s.spawn.count = 20;
    Claim c = near("mean_speed", 120.0, 1e-9, 0.0);
    c.set = {{"spawn.speed.1", 120.0}, {"spawn.speed.0", 120.0}};
    ClaimResult r = checkClaim(s, c);
    VERIFY2(r.holds, r.explanation.c_str());
    c.set = {{"spawn.horizontal", 1.0}, {"spawn.speed.0", 120.0}, {"spawn.speed.1", 120.0}, {"spawn.radius.1", 4.0}};
    c.value = 0.0;
    c.measure = "velocity"; // horizontal: no ball moves along y
    r = checkClaim(s, c);
    VERIFY2(r.holds, r.explanation.c_str());
    c.set = {{"spawn.speed.0", 500.0}};
    r = checkClaim(s, c);
    VERIFY2(!r.holds && r.explanation.find("is above the fastest") != std::string::npos, r.explanation.c_str());
    c.set = {{"spawn.fully_inside", 0.5}};
    r = checkClaim(s, c);
    VERIFY2(!r.holds && r.explanation.find("not a switch") != std::string::npos, r.explanation.c_str());
}

// A value a claim sets out of its key's range names the range as every
// other message does (sim/world/number_text.h).
TEST_CASE("TestClaims::aSceneKeyOutOfRangeNamesItsRange")
{
    Scene scene;
    const auto problem = setSceneKey(scene, "spawn.count", -1.0);
    REQUIRE(problem.has_value());
    CHECK(problem->rfind("-1 is outside [0, ", 0) == 0);
    CHECK(problem->back() == ']');
    const auto half = setSceneKey(scene, "spawn.count", 2.5);
    REQUIRE(half.has_value());
    CHECK(*half == "2.5 is not a whole number");
}
