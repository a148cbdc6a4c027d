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
        const std::string what = c.name;
        INFO(what);
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
        world.setAccounting(true); // the pinned ball's push is booked, as a wall's is
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
        const double p = b.mass[0] * u;
        VERIFY2(world.momentumDrift().norm() <= kRel * p, Text("drift %1").arg(world.momentumDrift().norm()).c_str());
        VERIFY(std::abs(world.energyDrift()) <= kRel * before);
    }
}

// Two equal balls head-on at ±u, their own restitutions 0.5 and 1 in a world
// of e = 1: the pair takes the smaller, so they separate at half the approach
// speed, 2u → u, with the momentum (0) kept. The same with the second ball's
// e unset (the world's 1), on each collision path.
TEST_CASE("TestBallProperties::pairTakesTheSmallerRestitution")
{
    const double u = 150.0;
    struct Case {
        const char* name;
        bool resting, continuous, gravity;
    };
    for (const double otherE : {1.0, kWorldRestitution}) {
        for (const Case c : {Case{"one pass", false, false, false}, Case{"continuous", true, true, false},
                             Case{"resting solver", true, false, true}}) {
            const std::string what = std::string(c.name) + (otherE < 0.0 ? ", world's e" : ", own e 1");
            INFO(what);
            Ball a = ballAt(100.0, 200.0, u, 0.0, 10.0, 0.0);
            Ball b = ballAt(300.0, 200.0, -u, 0.0, 10.0, 0.0);
            a.restitution = 0.5;
            b.restitution = otherE;
            Scene s = openScene({a, b});
            s.settings.collisions.response = Response::Impulse2D;
            s.settings.collisions.restitution = 1.0;
            s.settings.collisions.resting = c.resting;
            s.settings.collisions.continuous = c.continuous;
            if (c.gravity) { // the resting solver runs under gravity only: one far too weak to bend the path
                s.settings.gravity.enabled = true;
                s.settings.gravity.g = Vec2(0.0, 1e-20);
            }
            World world(s);
            for (int k = 0; k < 60; ++k) // they meet after 0.6 s
                world.step();
            REQUIRE(!world.halted());
            const BallState& st = world.balls();
            const double separating = st.velocity(0, 1) - st.velocity(0, 0);
            VERIFY2(std::abs(separating - 0.5 * (2.0 * u)) <= kRel * 2.0 * u,
                    Text("separating at %1 px/s").arg(separating, 0, 'g', 17).c_str());
            VERIFY(std::abs(st.velocity(0, 0) + st.velocity(0, 1)) <= kRel * 2.0 * u); // momentum 0
            VERIFY(st.position(0, 1) - st.position(0, 0) > 20.0);                      // apart again
        }
    }
}

// A ball with its own e = 0 in a world whose walls have e = 1 stops its
// normal speed at the wall and keeps the tangential one, with every wall
// model and with the walls in time order.
TEST_CASE("TestBallProperties::ownRestitutionZeroStopsAtTheWall")
{
    const double u = 300.0, along = 12.0;
    struct Case {
        const char* name;
        WallModel model;
        bool continuous;
    };
    for (const Case c : {Case{"clamp", WallModel::Clamp, false}, Case{"mirror", WallModel::Mirror, false},
                         Case{"reverse", WallModel::Reverse, false}, Case{"exact", WallModel::Exact, false},
                         Case{"exact, in time order", WallModel::Exact, true}}) {
        const std::string what = c.name;
        INFO(what);
        Ball b = ballAt(500.0, 200.0, u, along, 10.0, 0.0);
        b.restitution = 0.0;
        Scene s;
        s.balls = {b, ballAt(100.0, 200.0, -u, 0.0, 10.0, 0.0)}; // a world-e ball bounces off the left wall
        s.settings.walls.model = c.model;
        s.settings.walls.restitution = 1.0;
        s.settings.collisions.response = Response::Impulse2D;
        s.settings.collisions.continuous = c.continuous;
        World world(s);
        for (int k = 0; k < 30; ++k) // both reach their walls within 0.3 s
            world.step();
        REQUIRE(!world.halted());
        const BallState& st = world.balls();
        VERIFY2(std::abs(st.velocity(0, 0)) <= kRel * u, Text("vx = %1").arg(st.velocity(0, 0)).c_str());
        VERIFY(std::abs(st.velocity(1, 0) - along) <= kRel * along);
        // Clamp and exact leave it on the wall; mirror puts it back by its
        // overshoot, reverse leaves it in the wall (they are the naive tries).
        if (c.model == WallModel::Clamp || c.model == WallModel::Exact)
            VERIFY2(std::abs(st.position(0, 0) - (s.settings.box.width - 10.0)) <= kRel * s.settings.box.width,
                    Text("x = %1").arg(st.position(0, 0), 0, 'g', 17).c_str());
        VERIFY(std::abs(st.velocity(0, 1) - u) <= kRel * u); // the other ball bounced at the wall's e = 1
    }
}

// A ball's own restitution outside [0, 1] is refused, naming the field.
TEST_CASE("TestBallProperties::ownRestitutionIsChecked")
{
    Ball b = ballAt(100.0, 100.0, 0.0, 0.0, 10.0, 0.0);
    b.restitution = 1.5;
    const auto error = validateBalls(std::vector<Ball>{b});
    REQUIRE(error.has_value());
    VERIFY(toString(*error).find("balls.0.restitution") != std::string::npos);
    b.restitution = kWorldRestitution;
    VERIFY(!validateBalls(std::vector<Ball>{b}));
}
