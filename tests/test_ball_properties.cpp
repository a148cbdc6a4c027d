// Per-ball properties of issue #35: a pinned ball never moves and the balls
// that hit it bounce as off an infinite mass. Tolerances: 1e-12 relative on
// closed forms (one impulse and a few hundred drift steps round to ~1e-15).

#include "sim/world/names.h"
#include "sim/world/scene.h"
#include "sim/world/world.h"

#include "sim_check.h"
#include "sim_test_util.h"

#include <cmath>
#include <string>
#include <vector>

using forcelab::test::Text;

using namespace forcelab::sim;

namespace {

constexpr double kRel = 1e-12;

const IntegratorKind kIntegrators[] = {IntegratorKind::Euler, IntegratorKind::SemiImplicitEuler,
                                       IntegratorKind::Verlet, IntegratorKind::Rk4,
                                       IntegratorKind::Yoshida4, IntegratorKind::Rk45,
                                       IntegratorKind::Exact, IntegratorKind::Ias15};

Ball pinnedAt(double x, double y, double r = 20.0)
{
    Ball b = ballAt(x, y, 0.0, 0.0, r, 0.0);
    b.pinned = true;
    return b;
}

// A ball of radius 10 coming at a pinned one head-on along x at `speed`, no
// walls, no forces: a textbook bounce off an immovable ball.
Scene headOnScene(double speed, CollisionSettings collisions)
{
    Scene s = openScene({ballAt(100.0, 200.0, speed, 0.0, 10.0, 0.0), pinnedAt(300.0, 200.0, 10.0)});
    s.settings.collisions = collisions;
    return s;
}

} // namespace

// Under gravity, with walls, collisions and a free ball dropping onto it,
// a pinned ball stays where it was, to the bit, with every integrator; so
// does one that overlaps the floor (the walls leave it alone too). With the
// resting solver and with continuous detection (exact walls, in time order).
TEST_CASE("TestBallProperties::pinnedBallStaysPutWithEveryIntegrator")
{
    for (const bool continuous : {false, true}) {
        for (const IntegratorKind kind : kIntegrators) {
            const std::string what = std::string(toString(kind)) + (continuous ? ", continuous" : ", resting solver");
            INFO(what);
            Scene s;
            s.settings.gravity.enabled = true;
            s.settings.collisions.response = Response::Impulse2D;
            s.settings.collisions.continuous = continuous;
            if (continuous)
                s.settings.walls.model = WallModel::Exact;
            const double floorY = s.settings.box.height;
            s.balls = {pinnedAt(400.0, 300.0), ballAt(405.0, 200.0, 0.0, 0.0, 10.0, 0.0),
                       pinnedAt(200.0, floorY - 5.0), ballAt(195.0, 100.0, 30.0, 0.0, 8.0, 0.0)};
            World world;
            REQUIRE(!forcelab::test::runFor(world, s, kind, 1.0 / 60.0, 1000));
            REQUIRE(!world.halted());
            REQUIRE(world.stepCount() == 1000);
            const BallState& b = world.balls();
            for (const int i : {0, 2}) {
                REQUIRE_SAME(b.position.col(i).x(), s.balls[std::size_t(i)].position.x());
                REQUIRE_SAME(b.position.col(i).y(), s.balls[std::size_t(i)].position.y());
                VERIFY(b.velocity.col(i).isZero(0.0));
            }
            // The free balls did move (the scene is not trivially at rest).
            VERIFY((b.position.col(1) - s.balls[1].position).norm() > 10.0);
        }
    }
}

// Head-on at u onto a pinned ball with e = 1: the ball comes back at −u, the
// pinned ball has not moved, the kinetic energy is what it was. The same
// for the one textbook pass, the resting solver's path and continuous detection.
TEST_CASE("TestBallProperties::headOnBounceOffPinnedBall")
{
    const double u = 240.0;
    struct Case {
        const char* name;
        bool resting, continuous;
        bool gravity;
    };
    for (const Case c : {Case{"one pass", false, false, false}, Case{"continuous", true, true, false},
                         Case{"resting solver", true, false, true}}) {
        INFO(c.name);
        CollisionSettings cs;
        cs.response = Response::Impulse2D;
        cs.restitution = 1.0;
        cs.resting = c.resting;
        cs.continuous = c.continuous;
        Scene s = headOnScene(u, cs);
        if (c.gravity) { // the resting solver runs under gravity only: one far too weak to bend the path by 1e-12
            s.settings.gravity.enabled = true;
            s.settings.gravity.g = Vec2(0.0, 1e-20);
        }
        World world(s);
        const double before = world.energy().kinetic;
        for (int k = 0; k < 90; ++k) // 1.5 s: 180 px to the contact, then back
            world.step();
        REQUIRE(!world.halted());
        const BallState& b = world.balls();
        REQUIRE_SAME(b.position(0, 1), 300.0);
        REQUIRE_SAME(b.position(1, 1), 200.0);
        VERIFY(b.velocity.col(1).isZero(0.0));
        VERIFY2(std::abs(b.velocity(0, 0) + u) <= kRel * u, Text("vx = %1").arg(b.velocity(0, 0)).c_str());
        VERIFY(std::abs(b.velocity(1, 0)) <= kRel * u);
        VERIFY(b.position(0, 0) < 290.0 - 10.0); // on its way back
        const double after = world.energy().kinetic;
        VERIFY2(std::abs(after - before) <= kRel * before, Text("E %1 -> %2").arg(before).arg(after).c_str());
    }
}
