// The events a stopwatch starts and stops on, against closed forms: the time
// between two bounces of an e = 1 ball, the top of a throw, the crossing of a
// line at constant speed, and the period of a circular orbit on a spring.
// Each at several time steps: an event that is interpolated inside the step
// is exact to rounding, a bounce to one step.

#include "sim_check.h"
#include "sim_test_util.h"

#include "sim/world/events.h"
#include "sim/world/world.h"

#include <cmath>
#include <numbers>
#include <vector>

using namespace forcelab;
using namespace forcelab::sim;
using forcelab::test::ballAt;

namespace {

// Runs `scene` until `count` events of `spec` have happened (or `limit` s).
std::vector<double> eventTimes(const Scene& scene, const EventSpec& spec, int count, double limit)
{
    World world(scene);
    EventWatch watch;
    watch.start(spec, world.balls(), world.time());
    std::vector<double> times;
    while (static_cast<int>(times.size()) < count && world.time() < limit) {
        world.step();
        if (const auto t = watch.update(world.balls(), world.time()))
            times.push_back(*t);
    }
    return times;
}

Scene box(double dt)
{
    Scene s;
    s.settings.box = BoxSettings{600.0, 400.0};
    s.settings.time.integrator = IntegratorKind::Exact;
    s.settings.time.dt = dt;
    return s;
}

} // namespace

TEST_CASE("a ball with e = 1 bounces every 2 v0 / g, to one step")
{
    for (const double dt : {1.0 / 60, 1.0 / 240, 1.0 / 1000}) {
        CAPTURE(dt);
        Scene s = box(dt);
        s.settings.gravity.enabled = true;
        s.settings.gravity.g = Vec2(0.0, 980.0);
        s.settings.walls.model = WallModel::Exact;
        s.settings.walls.restitution = 1.0;
        // Dropped from 290 px above the floor: it lands at v0 = √(2 g h).
        s.balls = {ballAt(300.0, 100.0)};
        const double v0 = std::sqrt(2.0 * 980.0 * 290.0);
        const std::vector<double> t = eventTimes(s, {EventKind::Bounce, 0}, 3, 10.0);
        REQUIRE(t.size() == 3);
        CHECK(std::abs(t[0] - std::sqrt(2.0 * 290.0 / 980.0)) <= dt);
        CHECK(std::abs((t[1] - t[0]) - 2.0 * v0 / 980.0) <= dt);
        CHECK(std::abs((t[2] - t[1]) - 2.0 * v0 / 980.0) <= dt);
    }
}

TEST_CASE("the top of a throw comes at v / g, to rounding")
{
    for (const double dt : {1.0 / 60, 1.0 / 240}) {
        CAPTURE(dt);
        Scene s = box(dt);
        s.settings.gravity.enabled = true;
        s.settings.gravity.g = Vec2(0.0, 980.0);
        s.balls = {ballAt(300.0, 380.0, 0.0, -300.0)};
        const std::vector<double> t = eventTimes(s, {EventKind::Apex, 0}, 1, 2.0);
        REQUIRE(t.size() == 1);
        // vy = −300 + 980 t is linear in t: the interpolated zero is exact.
        CHECK(t[0] == doctest::Approx(300.0 / 980.0).epsilon(1e-12));
    }
}

TEST_CASE("a ball at 120 px/s crosses x = 250 at (250 − x0) / 120")
{
    for (const double dt : {1.0 / 60, 0.1}) {
        CAPTURE(dt);
        Scene s = box(dt);
        s.balls = {ballAt(40.0, 200.0, 120.0, 0.0)};
        const std::vector<double> t = eventTimes(s, {EventKind::CrossX, 0, 250.0}, 1, 5.0);
        REQUIRE(t.size() == 1);
        CHECK(t[0] == doctest::Approx(210.0 / 120.0).epsilon(1e-12));
    }
}

TEST_CASE("a circular orbit on a spring takes 2π / √k per turn")
{
    for (const double dt : {1.0 / 120, 1.0 / 480}) {
        CAPTURE(dt);
        Scene s = box(dt);
        s.settings.time.integrator = IntegratorKind::Rk4;
        s.settings.spring.enabled = true;
        s.settings.spring.k = 4.0;
        s.settings.spring.anchor = Vec2(300.0, 200.0);
        // r = 100 px, v = ω r = 200 px/s at right angles: a circle.
        s.balls = {ballAt(400.0, 200.0, 0.0, 200.0)};
        const std::vector<double> t = eventTimes(s, {EventKind::Orbit, 0, 0.0, Vec2(300.0, 200.0)}, 2, 10.0);
        REQUIRE(t.size() == 2);
        const double period = 2.0 * std::numbers::pi / 2.0;
        // The angle is interpolated linearly inside the step: exact to
        // (ω dt)² of a step, well under a hundredth of one.
        CHECK(std::abs(t[0] - period) < 0.01 * dt);
        CHECK(std::abs((t[1] - t[0]) - period) < 0.01 * dt);
    }
}
