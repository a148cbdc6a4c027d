// Integrators against closed forms: Kepler orbits (convergence order, energy
// behaviour), free fall (exact), and rk45's tolerance.

#include "sim_test_util.h"

#include "sim/integrators/integrator_info.h"
#include "sim/integrators/stability.h"

#include "sim/studies/kepler.h"

#include "sim/world/names.h"

#include "sim_check.h"

#include <cmath>
#include <numbers>

#include <string>
#include <vector>

using forcelab::test::Text;

using namespace forcelab;
using namespace forcelab::sim;
using forcelab::test::ballAt;
using forcelab::test::fittedOrder;
using forcelab::test::openScene;

namespace {

// The Kepler orbit of sim/studies/kepler.h: a = 100 px, period 1 s, e = 0.5 unless
// changed, starting at periapsis; its position at any time comes from
// Kepler's equation.
using Kepler = KeplerOrbit;

// Largest relative energy error over `orbits` orbits, sampled every step.
double maxEnergyError(World& world, std::int64_t steps, double e0)
{
    double worst = 0.0;
    for (std::int64_t k = 0; k < steps; ++k) {
        world.step();
        worst = std::max(worst, std::abs((world.energy().total() - e0) / e0));
    }
    return worst;
}

} // namespace


namespace {

struct KeplerOrderRow {
    Text tag;
    int integrator;
    double order;
};

std::vector<KeplerOrderRow> keplerOrderRows()
{
    std::vector<KeplerOrderRow> rows;
    rows.push_back({Text("euler"), int(IntegratorKind::Euler), 1.0});
    rows.push_back({Text("semi-implicit-euler"), int(IntegratorKind::SemiImplicitEuler), 1.0});
    rows.push_back({Text("verlet"), int(IntegratorKind::Verlet), 2.0});
    rows.push_back({Text("rk4"), int(IntegratorKind::Rk4), 4.0});
    rows.push_back({Text("yoshida4"), int(IntegratorKind::Yoshida4), 4.0});
    return rows;
}

} // namespace


// Position error against Kepler's equation at t = 0.30078125 P, for
// dt = P / 2^k, k = 8..12. Not a whole number of orbits: at whole orbits some
// errors cancel and semi-implicit Euler would look second order. Inside the
// first orbit: by 2.3 orbits explicit Euler's error at these steps is the size
// of the orbit itself, no longer in the range where the error shrinks as dt^p.
TEST_CASE("TestIntegrators::keplerOrder")
{
    for (const KeplerOrderRow& row : keplerOrderRows()) {
        SUBCASE(row.tag.c_str())
        {
            const auto& integrator = row.integrator;
            const auto& order = row.order;
            const Kepler kepler;
            const double end = 0.30078125 * kepler.period; // a whole number of steps for every dt below
            std::vector<double> dts, errors;
            for (int k = 8; k <= 12; ++k) {
                const double dt = kepler.period / std::ldexp(1.0, k);
                World world;
                VERIFY(!world.reset(kepler.scene(static_cast<IntegratorKind>(integrator), dt)));
                const auto steps = static_cast<std::int64_t>(std::llround(end / dt));
                for (std::int64_t s = 0; s < steps; ++s)
                    world.step();
                REQUIRE_SAME(world.time(), end);
                const double err = (world.balls().position.col(0) - kepler.position(end)).norm();
                VERIFY(std::isfinite(err));
                dts.push_back(dt);
                errors.push_back(err);
            }
            const double fitted = fittedOrder(dts, errors);
            REQUIRE_SAME(integratorInfo(static_cast<IntegratorKind>(integrator)).order, order);
            forcelab::test::report("%s: errors %.3g .. %.3g px, fitted order %.3f", row.tag.c_str(), errors.front(), errors.back(),
                  fitted);
            VERIFY2(std::abs(fitted - order) <= 0.15, Text(Text("fitted order %1").arg(fitted)).c_str());
        }
    }
}

namespace {

struct SymplecticEnergyBoundedRow {
    Text tag;
    int integrator;
    bool symplectic;
    int stepsPerOrbit;
};

std::vector<SymplecticEnergyBoundedRow> symplecticEnergyBoundedRows()
{
    std::vector<SymplecticEnergyBoundedRow> rows;
    // Explicit Euler needs a small step, or the orbit is destroyed within ten
    // orbits and there is nothing left to drift.
    rows.push_back({Text("euler"), int(IntegratorKind::Euler), false, 16384});
    rows.push_back({Text("semi-implicit-euler"), int(IntegratorKind::SemiImplicitEuler), true, 512});
    rows.push_back({Text("verlet"), int(IntegratorKind::Verlet), true, 512});
    rows.push_back({Text("rk4"), int(IntegratorKind::Rk4), false, 512});
    rows.push_back({Text("yoshida4"), int(IntegratorKind::Yoshida4), true, 512});
    return rows;
}

} // namespace


// Relative energy error sampled at every step (many times inside each orbit):
// symplectic methods keep it bounded, so its maximum over 100 orbits is at most
// 1.5× the maximum over the first 10; euler and rk4 drift, so it keeps growing.
TEST_CASE("TestIntegrators::symplecticEnergyBounded")
{
    for (const SymplecticEnergyBoundedRow& row : symplecticEnergyBoundedRows()) {
        SUBCASE(row.tag.c_str())
        {
            const auto& integrator = row.integrator;
            const auto& symplectic = row.symplectic;
            const auto& stepsPerOrbit = row.stepsPerOrbit;
            const Kepler kepler;
            World world;
            VERIFY(!world.reset(kepler.scene(static_cast<IntegratorKind>(integrator), kepler.period / stepsPerOrbit)));
            const double e0 = world.energy().total();
            const double first10 = maxEnergyError(world, 10 * stepsPerOrbit, e0);
            const double upTo100 = std::max(first10, maxEnergyError(world, 90 * stepsPerOrbit, e0));
            const double growth = upTo100 / first10;
            forcelab::test::report("%s: max |dE/E| over 10 orbits %.3g, over 100 orbits %.3g, growth %.2f", row.tag.c_str(), first10,
                  upTo100, growth);
            if (symplectic)
                VERIFY2(growth <= 1.5, Text(Text("growth %1").arg(growth)).c_str());
            else
                VERIFY2(growth >= 3.0, Text(Text("growth %1").arg(growth)).c_str());
        }
    }
}

// rk45 adapts its sub-steps to keep each one's error below the tolerance, so
// the error after 2.3 orbits (outer steps of P/16) scales with the tolerance:
// measured about 14–20 × tol × a for tol = 1e-6 … 1e-10, asserted ≤ 50 × tol × a.
// A tighter tolerance buys a smaller error with more sub-steps.
TEST_CASE("TestIntegrators::rk45MeetsTolerance")
{
    const Kepler kepler;
    double previousError = 1e300;
    std::int64_t previousSteps = 0;
    for (double tol : {1e-6, 1e-8, 1e-10}) {
        Scene s = kepler.scene(IntegratorKind::Rk45, kepler.period / 16);
        s.settings.time.tolerance = tol;
        World world;
        VERIFY(!world.reset(s));
        for (int k = 0; k < 16 * 2 + 5; ++k)
            world.step();
        const double err = (world.balls().position.col(0) - kepler.position(world.time())).norm();
        const std::int64_t accepted = world.totals().acceptedSteps;
        forcelab::test::report("rk45 tol %.0e: error %.3g px, %lld accepted, %lld rejected sub-steps", tol, err,
              static_cast<long long>(accepted), static_cast<long long>(world.totals().rejectedSteps));
        VERIFY2(err <= 50.0 * tol * kepler.a, Text(Text("error %1 at tol %2").arg(err).arg(tol)).c_str());
        VERIFY(err < previousError);
        VERIFY(accepted > previousSteps);
        previousError = err;
        previousSteps = accepted;
    }
}

namespace {

struct ExactFreeFallRow {
    Text tag;
    double dt;
};

std::vector<ExactFreeFallRow> exactFreeFallRows()
{
    std::vector<ExactFreeFallRow> rows;
    rows.push_back({Text("1/30"), 1.0 / 30});
    rows.push_back({Text("1/60"), 1.0 / 60});
    rows.push_back({Text("1/1000"), 1.0 / 1000});
    return rows;
}

} // namespace


// y(t) = y0 + vy0 t + ½ g t² exactly (to 1e-12 relative) at every step.
TEST_CASE("TestIntegrators::exactFreeFall")
{
    for (const ExactFreeFallRow& row : exactFreeFallRows()) {
        SUBCASE(row.tag.c_str())
        {
            const auto& dt = row.dt;
            Scene s = openScene({ballAt(100.0, 50.0, 30.0, -200.0)});
            s.settings.gravity.enabled = true;
            s.settings.gravity.g = Vec2(0.0, 980.0);
            s.settings.time.integrator = IntegratorKind::Exact;
            s.settings.time.dt = dt;
            World world;
            VERIFY(!world.reset(s));
            for (int k = 0; k < 2.0 / dt; ++k) {
                world.step();
                const double t = world.time();
                const Vec2 expected(100.0 + 30.0 * t, 50.0 - 200.0 * t + 0.5 * 980.0 * t * t);
                const Vec2 got = world.balls().position.col(0);
                VERIFY2((got - expected).norm() <= 1e-12 * expected.norm(),
                         Text(Text("t=%1: %2 vs %3").arg(t).arg(got.y(), 0, 'g', 17).arg(expected.y(), 0, 'g', 17)).c_str());
            }
        }
    }
}

TEST_CASE("TestIntegrators::exactRejectedWithNonConstantForces")
{
    Scene s = openScene({ballAt(100.0, 50.0)});
    s.settings.time.integrator = IntegratorKind::Exact;
    s.settings.drag.enabled = true;
    World world;
    const auto error = world.reset(s);
    VERIFY(error);
    REQUIRE_SAME(Text(toString(*error)),
             Text("time.integrator: exact needs a constant acceleration, but drag depends on velocity; "
                     "pick another integrator or switch that model off"));
    // Pushed live, the world keeps its old settings.
    World running;
    VERIFY(!running.reset(openScene({ballAt(1, 1)})));
    WorldSettings edited = running.settings();
    edited.time.integrator = IntegratorKind::Exact;
    edited.spring.enabled = true;
    VERIFY(running.setSettings(edited));
    VERIFY(running.settings().time.integrator == IntegratorKind::SemiImplicitEuler);
}

namespace {

struct ForceEvaluationsPerStepRow {
    Text tag;
    int integrator;
    int evaluationsFor10Steps;
};

std::vector<ForceEvaluationsPerStepRow> forceEvaluationsPerStepRows()
{
    std::vector<ForceEvaluationsPerStepRow> rows;
    // Verlet-type methods reuse the last acceleration: one extra at the start.
    rows.push_back({Text("euler"), int(IntegratorKind::Euler), 10});
    rows.push_back({Text("semi-implicit-euler"), int(IntegratorKind::SemiImplicitEuler), 10});
    rows.push_back({Text("verlet"), int(IntegratorKind::Verlet), 11});
    rows.push_back({Text("rk4"), int(IntegratorKind::Rk4), 40});
    rows.push_back({Text("yoshida4"), int(IntegratorKind::Yoshida4), 31});
    return rows;
}

} // namespace


TEST_CASE("TestIntegrators::forceEvaluationsPerStep")
{
    for (const ForceEvaluationsPerStepRow& row : forceEvaluationsPerStepRows()) {
        SUBCASE(row.tag.c_str())
        {
            const auto& integrator = row.integrator;
            const auto& evaluationsFor10Steps = row.evaluationsFor10Steps;
            const Kepler kepler;
            World world;
            VERIFY(!world.reset(kepler.scene(static_cast<IntegratorKind>(integrator), kepler.period / 256)));
            for (int k = 0; k < 10; ++k)
                world.step();
            REQUIRE_SAME(world.totals().forceEvaluations, std::int64_t(evaluationsFor10Steps));
            // The integrator's record says the same, give or take the one extra
            // evaluation that starts a Verlet-type run.
            const int perStep = integratorInfo(static_cast<IntegratorKind>(integrator)).evaluationsPerStep;
            VERIFY(evaluationsFor10Steps == 10 * perStep || evaluationsFor10Steps == 10 * perStep + 1);
        }
    }
}

namespace {

struct RecordsAgreeWithTheMethodsRow {
    Text tag;
    int integrator;
};

std::vector<RecordsAgreeWithTheMethodsRow> recordsAgreeWithTheMethodsRows()
{
    std::vector<RecordsAgreeWithTheMethodsRow> rows;
    for (const IntegratorInfo& info : integrators())
        rows.push_back({forcelab::test::format_row("%s", info.name.data()), int(info.kind)});
    return rows;
}

} // namespace


// Each integrator's record (sim/integrators/integrator_info.h) against the method itself:
// its name round-trips; its spring limit is where one step's growth on
// x'' = −ω² x (sim/integrators/stability.h, the eigenvalues of the step matrix) crosses 1,
// within 1e-3 of ω h on either side; explicit Euler grows at any h; the
// fitted Kepler orders (keplerOrder) match the recorded ones.
TEST_CASE("TestIntegrators::recordsAgreeWithTheMethods")
{
    for (const RecordsAgreeWithTheMethodsRow& row : recordsAgreeWithTheMethodsRows()) {
        SUBCASE(row.tag.c_str())
        {
            const auto& integrator = row.integrator;
            const IntegratorInfo& info = integratorInfo(static_cast<IntegratorKind>(integrator));
            REQUIRE_SAME(int(info.kind), integrator);
            VERIFY(parseIntegrator(info.name) == info.kind);
            REQUIRE_SAME(toString(info.kind), info.name);
            if (info.adaptive || info.kind == IntegratorKind::Exact) {
                VERIFY(std::isinf(info.springLimit));
                return;
            }
            WorldSettings s;
            s.time.integrator = info.kind;
            s.spring = SpringSettings{true, Vec2(0, 0), 1.0}; // ω = 1, so ω h = h
            if (info.springLimit == 0.0) {
                VERIFY(linearGrowthPerStep(s, 1e-3) > 1.0);
                return;
            }
            const double below = linearGrowthPerStep(s, info.springLimit * (1.0 - 1e-3));
            const double above = linearGrowthPerStep(s, info.springLimit * (1.0 + 1e-3));
            forcelab::test::report("%s: growth per step %.12f at 0.999 of ω h = %.4f, %.6f at 1.001", info.name.data(), below,
                  info.springLimit, above);
            VERIFY(below <= 1.0 + 1e-12);
            VERIFY(above > 1.0 + 1e-6);
        }
    }
}

