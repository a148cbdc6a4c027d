// Energy and momentum accounting: everything done on purpose is booked, so
// what is left is the integrator's error. Checked where that error is known:
// zero for the exact integrator, tiny for rk4, first order for Euler.

#include "sim_test_util.h"

#include "sim/studies/kepler.h"

#include "sim_check.h"

#include <cmath>

#include <string>
#include <vector>

using forcelab::test::Text;

using namespace forcelab;
using namespace forcelab::sim;
using forcelab::test::ballAt;
using forcelab::test::openScene;

namespace {

Scene dragFall(IntegratorKind integrator)
{
    Scene s = openScene({ballAt(100, 50, 200, -300), ballAt(300, 80, -100, 0, 5)});
    s.settings.gravity.enabled = true;
    s.settings.drag = DragSettings{true, DragLaw::Linear, 0.8};
    s.settings.time.integrator = integrator;
    s.settings.time.dt = 1.0 / 240;
    return s;
}

double kineticScale(const World& w)
{
    return std::max(w.energy().kinetic, 1e-300);
}

} // namespace


// An orbit: nothing acts on purpose, so the drift is all of E − E0.
TEST_CASE("TestAccounting::nothingBookedWithoutNonConservativeModels")
{
    World w;
    VERIFY(!w.reset(KeplerOrbit{}.scene(IntegratorKind::SemiImplicitEuler, 1.0 / 256)));
    w.setAccounting(true);
    for (int k = 0; k < 300; ++k)
        w.step();
    REQUIRE_SAME(w.bookedEnergy(), 0.0);
    REQUIRE_SAME(w.energyDrift(), w.energy().total() - w.startEnergy());
    VERIFY(std::abs(w.energyDrift()) > 0.0); // semi-implicit Euler's energy wobbles
}

// Free fall with linear drag: drag takes energy away all the time. Booked by
// the trapezoid rule, the rest is the integrator's error: rk4's is far below
// semi-implicit Euler's, and both shrink with dt (rk4's to the booking's own
// second-order error).
TEST_CASE("TestAccounting::dragWorkIsBooked")
{
    double drift[2] = {};
    int i = 0;
    for (IntegratorKind kind : {IntegratorKind::SemiImplicitEuler, IntegratorKind::Rk4}) {
        World w;
        VERIFY(!w.reset(dragFall(kind)));
        w.setAccounting(true);
        const double e0 = w.energy().total();
        for (int k = 0; k < 480; ++k)
            w.step();
        VERIFY(w.bookedEnergy() < 0.0); // drag removed energy
        drift[i++] = std::abs(w.energyDrift()) / std::abs(e0 - w.energy().total());
    }
    forcelab::test::report("energy drift as a share of what drag removed: semi-implicit-euler %.3g, rk4 %.3g", drift[0], drift[1]);
    VERIFY(drift[0] < 0.05);
    VERIFY(drift[1] < 1e-4);
    VERIFY(drift[1] < drift[0] / 100.0);
}

// A ball bouncing with e = 0.8 on exact walls with the exact integrator: the
// walls take away 36% of the energy each bounce; all of it is booked and the
// drift stays at rounding level.
TEST_CASE("TestAccounting::wallLossesAreBooked")
{
    Scene s;
    s.settings.walls = WallSettings{true, true, true, true, WallModel::Exact, 0.8};
    s.settings.gravity.enabled = true;
    s.settings.time.integrator = IntegratorKind::Exact;
    s.balls = {ballAt(300, 100, 50, 0)};
    World w;
    VERIFY(!w.reset(s));
    w.setAccounting(true);
    while (w.totals().wallHits < 8)
        w.step();
    const double lost = w.startEnergy() - w.energy().total();
    VERIFY(lost > 0.0);
    VERIFY(std::abs(w.bookedEnergy() + lost) <= 1e-9 * std::abs(w.startEnergy()));
    VERIFY(std::abs(w.energyDrift()) <= 1e-9 * std::abs(w.startEnergy()));
    // Walls change momentum on purpose too: booked, so the drift is rounding.
    VERIFY(w.momentumDrift().norm() <= 1e-9 * w.balls().mass[0] * 1000.0);
}

// A gas of balls with restitution 0.9 and no forces: collisions and walls
// lose energy, all booked; momentum is changed only by the walls (booked).
TEST_CASE("TestAccounting::collisionLossesAreBooked")
{
    Scene s;
    s.settings.collisions = CollisionSettings{Detection::Sweep, Response::Impulse2D, 0.9, false};
    s.spawn.count = 200;
    World w;
    VERIFY(!w.reset(s));
    w.setAccounting(true);
    for (int k = 0; k < 600; ++k)
        w.step();
    VERIFY(w.totals().contacts > 100);
    VERIFY(w.bookedEnergy() < 0.0);
    VERIFY2(std::abs(w.energyDrift()) <= 1e-9 * w.startEnergy(),
             Text(Text("drift %1 of %2").arg(w.energyDrift()).arg(w.startEnergy())).c_str());
    VERIFY(w.momentumDrift().norm() <= 1e-9 * std::sqrt(2.0 * w.startEnergy() * w.balls().mass.sum()));
}

// Turning gravity up between steps changes the potential energy at once:
// that is the student's doing, booked, not the integrator's.
TEST_CASE("TestAccounting::editsBetweenStepsAreBooked")
{
    Scene s = dragFall(IntegratorKind::Exact);
    s.settings.drag.enabled = false;
    World w;
    VERIFY(!w.reset(s));
    w.setAccounting(true);
    for (int k = 0; k < 10; ++k)
        w.step();
    WorldSettings edited = w.settings();
    edited.gravity.g = Vec2(0, 2000);
    const double before = w.energy().total();
    VERIFY(!w.setSettings(edited));
    const double jump = w.energy().total() - before;
    VERIFY(jump != 0.0);
    for (int k = 0; k < 10; ++k)
        w.step();
    VERIFY(std::abs(w.bookedEnergy() - jump) <= 1e-9 * std::abs(jump));
    VERIFY(std::abs(w.energyDrift()) <= 1e-9 * kineticScale(w));
}

// Off by default, and then the step pays for nothing: the same force
// evaluations as without it.
TEST_CASE("TestAccounting::offCostsNothing")
{
    World plain, booked;
    VERIFY(!plain.reset(dragFall(IntegratorKind::Rk4)));
    VERIFY(!booked.reset(dragFall(IntegratorKind::Rk4)));
    VERIFY(!plain.accounting());
    booked.setAccounting(true);
    for (int k = 0; k < 10; ++k) {
        plain.step();
        booked.step();
    }
    REQUIRE_SAME(plain.totals().forceEvaluations, std::int64_t(40));
    REQUIRE_SAME(booked.totals().forceEvaluations, std::int64_t(40)); // the books' evaluations are not the step's
    REQUIRE_SAME(plain.balls().position, booked.balls().position);    // and they change nothing
}

