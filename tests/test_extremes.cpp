// Every integrator × wall model × response at the extremes a classroom
// reaches: tiny and huge time steps, enormous gravity and G, restitution 0
// and 1, drag beyond 1/dt, mass ratios of 10^12, speeds of 10^6 px/s, radii
// from 0.1 px to half the box, and 0, 1 or 2 balls. Whatever happens, no NaN
// or Inf reaches the state; with all four walls on (and continuous collision
// detection), every ball stays inside the box; where nothing adds energy it
// does not grow. A world may stop itself (halted) — then with a message and a
// finite state.

#include "sim_test_util.h"

#include "sim/world/names.h"
#include "sim/world/step_plan.h"

#include "sim_check.h"

#include <cmath>
#include <functional>

#include <string>
#include <vector>

using forcelab::test::Text;

using namespace forcelab;
using namespace forcelab::sim;
using forcelab::test::ballAt;
using forcelab::test::openScene;

namespace {

struct Extreme {
    const char* name;
    std::function<void(Scene&)> apply;
    bool addsEnergy; // a model that adds energy on purpose (or whose potential is not counted)
};

// Four balls of mixed sizes moving in the box; the extremes change them.
Scene baseScene()
{
    Scene s;
    s.settings.box = BoxSettings{600, 400};
    s.balls = {ballAt(100, 100, 120, -80, 10), ballAt(300, 200, -60, 40, 20), ballAt(450, 300, 30, 90, 5),
               ballAt(520, 80, -150, 10, 12)};
    return s;
}

std::vector<Extreme> extremes()
{
    return {
        {"dt 1e-6", [](Scene& s) { s.settings.time.dt = 1e-6; }, false},
        {"dt 0.5", [](Scene& s) { s.settings.time.dt = 0.5; }, false},
        {"dt 0.1 gravity", [](Scene& s) { s.settings.time.dt = 0.1; s.settings.gravity.enabled = true; }, false},
        {"gravity 1e6", [](Scene& s) { s.settings.gravity = GravitySettings{true, Vec2(3e5, 1e6)}; }, false},
        {"G 1e9 no softening", [](Scene& s) { s.settings.mutualGravity = MutualGravitySettings{true, 1e9, 0.0}; }, false},
        {"G 1e9 softening 5", [](Scene& s) { s.settings.mutualGravity = MutualGravitySettings{true, 1e9, 5.0}; }, false},
        {"G -1e9", [](Scene& s) { s.settings.mutualGravity = MutualGravitySettings{true, -1e9, 1.0}; }, true},
        {"restitution 0", [](Scene& s) { s.settings.walls.restitution = 0; s.settings.collisions.restitution = 0; }, false},
        {"drag k = 1/dt", [](Scene& s) { s.settings.drag = DragSettings{true, DragLaw::Linear, 60.0}; }, false},
        {"drag k = 10/dt", [](Scene& s) { s.settings.drag = DragSettings{true, DragLaw::Linear, 600.0}; }, false},
        {"quadratic drag 10", [](Scene& s) { s.settings.drag = DragSettings{true, DragLaw::Quadratic, 10.0}; }, false},
        {"mass ratio 1e12",
         [](Scene& s) {
             s.balls[0].mass = 1e-6;
             s.balls[1].mass = 1e6;
             s.balls[0].velocity = Vec2(3000, 0);
         },
         false},
        {"speed 1e6",
         [](Scene& s) {
             s.balls[0].velocity = Vec2(1e6, -7e5);
             s.balls[2].velocity = Vec2(-9e5, 1e6);
         },
         false},
        {"radius 0.1", [](Scene& s) { for (Ball& b : s.balls) b.radius = 0.1; }, false},
        {"radius half the box",
         [](Scene& s) {
             s.balls[1].radius = 200;
             s.balls[1].position = Vec2(300, 200);
         },
         false},
        {"no balls", [](Scene& s) { s.balls.clear(); }, false},
        {"one ball", [](Scene& s) { s.balls.resize(1); }, false},
        {"two balls on one point",
         [](Scene& s) {
             s.balls.resize(2);
             s.balls[1].position = s.balls[0].position;
         },
         false},
        {"point attract 1e12 no clamp",
         [](Scene& s) {
             s.settings.point = PointForceSettings{true, PointKind::Attract, Vec2(300, 200), 1e12, 0.0, ForceScale::None};
         },
         true},
        {"spring k 1e5", [](Scene& s) { s.settings.spring = SpringSettings{true, Vec2(300, 200), 1e5}; }, false},
        // Fast enough to cross the box hundreds of times a step, into the corners.
        {"speed 1e7 into corners",
         [](Scene& s) {
             s.balls[0].velocity = Vec2(-1e7, -1e7);
             s.balls[1].velocity = Vec2(1e7, 1e7);
             s.balls[3].velocity = Vec2(1e7, -9.99e6);
         },
         false},
        // The same scene 10^6 px from the origin, in the largest box allowed.
        {"coordinates near 1e7",
         [](Scene& s) {
             s.settings.box = BoxSettings{1e7, 1e7};
             for (Ball& b : s.balls)
                 b.position += Vec2(9.99e6 - 600, 9.99e6 - 400);
         },
         false},
        // The same scene shrunk 30,000 times: a box of 0.02 × 0.013 px.
        {"coordinates near 1e-2",
         [](Scene& s) {
             constexpr double k = 1.0 / 30000;
             s.settings.box = BoxSettings{600 * k, 400 * k};
             for (Ball& b : s.balls) {
                 b.position *= k;
                 b.velocity *= k;
                 b.radius *= k;
             }
         },
         false},
        {"tolerance 1e-15 gravity",
         [](Scene& s) {
             s.settings.time.tolerance = 1e-15;
             s.settings.gravity.enabled = true;
         },
         false},
        // The loosest tolerance: rk45 and ias15 may be as wrong as they were
        // told to be, and the fixed-step methods carry their own energy error
        // on a spring (semi-implicit Euler's swings by ω dt / 2 = 6% here), so
        // energy is not held here; finiteness and the box are.
        {"tolerance 1 spring",
         [](Scene& s) {
             s.settings.time.tolerance = 1.0;
             s.settings.spring = SpringSettings{true, Vec2(300, 200), 50.0};
         },
         true},
        {"masses 1e-6 to 1e6 with G",
         [](Scene& s) {
             s.balls[0].mass = 1e-6;
             s.balls[1].mass = 1e6;
             s.balls[2].mass = 1.0;
             s.balls[3].mass = 1e3;
             s.settings.mutualGravity = MutualGravitySettings{true, 1e3, 0.0};
         },
         false},
    };
}

bool finite(const World& w)
{
    return w.balls().position.allFinite() && w.balls().velocity.allFinite();
}

} // namespace


namespace {

struct GridRow {
    Text tag;
    int integrator;
    int wallModel;
    int response;
    int extreme;
};

std::vector<GridRow> gridRows()
{
    std::vector<GridRow> rows;
    const auto list = extremes();
    for (IntegratorKind i : {IntegratorKind::Euler, IntegratorKind::SemiImplicitEuler, IntegratorKind::Verlet,
                             IntegratorKind::Rk4, IntegratorKind::Yoshida4, IntegratorKind::Rk45,
                             IntegratorKind::Ias15})
        for (WallModel m : {WallModel::Clamp, WallModel::Mirror, WallModel::Exact})
            for (Response r : {Response::None, Response::Impulse2D})
                for (std::size_t e = 0; e < list.size(); ++e)
                    rows.push_back({forcelab::test::format_row("%s %s %s %s", toString(i).data(), toString(m).data(), toString(r).data(),
                                  list[e].name), int(i), int(m), int(r), int(e)});
    return rows;
}

} // namespace


TEST_CASE("TestExtremes::grid")
{
    for (const GridRow& row : gridRows()) {
        SUBCASE(row.tag.c_str())
        {
            const auto& integrator = row.integrator;
            const auto& wallModel = row.wallModel;
            const auto& response = row.response;
            const auto& extreme = row.extreme;
            const Extreme x = extremes()[static_cast<std::size_t>(extreme)];
            Scene s = baseScene();
            s.settings.walls.model = static_cast<WallModel>(wallModel);
            s.settings.collisions = CollisionSettings{Detection::Sweep, static_cast<Response>(response), 1.0, true};
            s.settings.time.integrator = static_cast<IntegratorKind>(integrator);
            x.apply(s);
            World w;
            const auto refused = w.reset(s);
            VERIFY2(!refused, refused ? toString(*refused).c_str() : "");
            // Positional correction moves overlapping balls apart without touching
            // their velocities; against a strong conservative force that pulls them
            // together (the 1e5 spring, mutual gravity of a 1e6 mass) that lifts
            // their potential energy: measured 3.3× with clamp walls on the spring,
            // up to 9.8× with rk45 on the masses row. A known limit of the model
            // (docs/reliability.md), so that combination is not held to "energy
            // never grows".
            const bool pullsTogether = s.settings.spring.enabled ||
                                       (s.settings.mutualGravity.enabled && s.settings.mutualGravity.G > 0.0);
            const bool correctionAgainstSpring = pullsTogether && s.settings.collisions.response != Response::None;
            // Under gravity, clamp and mirror walls lift a ball that overshot the
            // floor without slowing it down (what lesson 09 shows: measured up to
            // 6.3× in 20 steps at g = 1e6 px/s²), and the two Euler methods' energy
            // error under a constant force is of order dt: only exact walls with an
            // integrator that is exact for a constant force are held to it there.
            const auto kind = static_cast<IntegratorKind>(integrator);
            const bool eulerMethod = kind == IntegratorKind::Euler || kind == IntegratorKind::SemiImplicitEuler;
            const bool gravityModelError =
                s.settings.gravity.enabled && (s.settings.walls.model != WallModel::Exact || eulerMethod);
            // The exact wall model bounces a ball on a parabola fitted to the step;
            // under mutual gravity of G = 1e9 the force changes so much within
            // rk45's and ias15's steps that the fitted path is wrong, and the bounce
            // adds energy: measured up to +131% in 20 steps. A
            // known limit (docs/reliability.md); every other integrator and wall
            // model is held to it there, stopping where the step cannot follow a pass.
            const bool adaptiveKind = kind == IntegratorKind::Rk45 || kind == IntegratorKind::Ias15;
            const bool fittedPathUnderG = adaptiveKind && s.settings.walls.model == WallModel::Exact &&
                                          s.settings.mutualGravity.enabled;
            const bool energyMayGrow = x.addsEnergy || gravityModelError || correctionAgainstSpring || fittedPathUnderG;
            const double e0 = w.energy().total();
            const double scale = std::max(std::abs(e0), 1e-300);
            const int steps = s.settings.time.dt < 1e-3 ? 50 : 20;
            for (int k = 0; k < steps && !w.halted(); ++k) {
                w.step();
                VERIFY2(finite(w), Text(Text("step %1: NaN or Inf").arg(k)).c_str());
                const BallState& b = w.balls();
                const double width = s.settings.box.width, height = s.settings.box.height;
                for (int i = 0; i < b.size(); ++i) {
                    // Inside the box, with 1e-9 of the box for rounding; a ball wider
                    // than the box sits in its middle.
                    const double r = std::min(b.radius[i], 0.5 * std::min(width, height));
                    const double tol = 1e-9 * std::max(width, height);
                    VERIFY2(b.position(0, i) >= r - tol && b.position(0, i) <= width - r + tol &&
                                 b.position(1, i) >= r - tol && b.position(1, i) <= height - r + tol,
                             Text(Text("step %1: ball %2 outside at (%3, %4)")
                                            .arg(k)
                                            .arg(i)
                                            .arg(b.position(0, i))
                                            .arg(b.position(1, i))).c_str());
                }
            }
            if (w.halted())
                VERIFY(!w.halted()->empty());
            if (!energyMayGrow && !w.halted()) {
                // Nothing adds energy: it may only fall (drag, restitution 0) or stay
                // (e = 1). Allowed growth: the integrator's error on these few steps;
                // explicit Euler gains energy by design (documented), so it is allowed
                // 1% here, the others 1e-6.
                const double allowed = integrator == int(IntegratorKind::Euler) ? 1e-2 : 1e-6;
                const double growth = (w.energy().total() - e0) / scale;
                VERIFY2(growth <= allowed, Text(Text("energy grew by %1 of its start").arg(growth)).c_str());
            }
        }
    }
}

// The most balls a world may hold, with collisions on: a few steps stay
// finite and inside the box.
TEST_CASE("TestExtremes::twoHundredThousandBalls")
{
    Scene s;
    s.settings.box = BoxSettings{8000, 6000};
    s.settings.gravity.enabled = true;
    s.settings.collisions = CollisionSettings{Detection::Grid, Response::Impulse2D, 0.9, false};
    s.spawn.count = kMaxBalls;
    s.spawn.minRadius = 2;
    s.spawn.maxRadius = 4;
    World w;
    VERIFY(!w.reset(s));
    REQUIRE_SAME(w.balls().size(), kMaxBalls);
    for (int k = 0; k < 3; ++k)
        w.step();
    VERIFY(finite(w));
    const BallState& b = w.balls();
    VERIFY(((b.position.row(0).transpose() - b.radius).array() >= -1e-6).all());
    VERIFY(((b.position.row(1).transpose() + b.radius).array() <= 6000 + 1e-6).all());
}

// Two bodies of mass 1000 (G = 1000, no softening) 200 px apart, moving
// sideways at ±5 px/s, fall towards each other on a thin ellipse whose
// closest approach is h²/(2 G (m₁ + m₂)) ≈ 1 px (h = 200 px × 10 px/s).
// Their energy, ½ μ v² − G m²/d, is conserved; at 1 px a free fall takes
// √(d³ / (G · 2m)) = 0.7 ms, far less than a step. Before, the fixed-step
// methods ran on through the pass and the pair left with energy from
// nowhere (exit 0). Now the world stops one step before, with a message that names
// the two balls and the fixes, and the state it keeps has the energy it had,
// give or take the method's own error on the way in (within 10% of the size
// of the pair's energy, ½ μ v² + G m²/d: explicit Euler gains 6% by then). With softening 20
// px the same pass is smooth and runs for 20 s; ias15 follows the unsoftened
// pass itself and keeps the energy to 1e-6.
namespace {

struct ClosePassStopsAndNamesThePairRow {
    Text tag;
    int integrator;
    double softening;
    bool stops;
};

std::vector<ClosePassStopsAndNamesThePairRow> closePassStopsAndNamesThePairRows()
{
    std::vector<ClosePassStopsAndNamesThePairRow> rows;
    for (IntegratorKind kind : {IntegratorKind::Euler, IntegratorKind::SemiImplicitEuler, IntegratorKind::Verlet,
                                IntegratorKind::Rk4, IntegratorKind::Yoshida4})
        rows.push_back({forcelab::test::format_row("%s", toString(kind).data()), int(kind), 0.0, true});
    rows.push_back({Text("verlet softening 20"), int(IntegratorKind::Verlet), 20.0, false});
    rows.push_back({Text("ias15"), int(IntegratorKind::Ias15), 0.0, false});
    return rows;
}

} // namespace


TEST_CASE("TestExtremes::closePassStopsAndNamesThePair")
{
    for (const ClosePassStopsAndNamesThePairRow& row : closePassStopsAndNamesThePairRows()) {
        SUBCASE(row.tag.c_str())
        {
            const auto& integrator = row.integrator;
            const auto& softening = row.softening;
            const auto& stops = row.stops;
            Scene s;
            s.settings.walls = WallSettings{false, false, false, false, WallModel::Clamp, 1.0};
            s.settings.mutualGravity = MutualGravitySettings{true, 1000.0, softening};
            s.settings.time.integrator = static_cast<IntegratorKind>(integrator);
            s.balls = {ballAt(100, 200, 0, 5, 5, 1000), ballAt(300, 200, 0, -5, 5, 1000)};
            // Without the check (measured): verlet runs the 20 s and ends with
            // |E − E₀| = 13 |E₀|, the pair flying apart.
            World w;
            VERIFY(!w.reset(s));
            const double e0 = w.energy().total();
            for (int k = 0; k < 20 * 60 && !w.halted(); ++k)
                w.step();
            // The error against the size of the pair's energy, ½ μ v² + G m² / d,
            // which is what a step's rounding and truncation scale with.
            const double drift = std::abs(w.energy().total() - e0) / pairEnergy(s.settings.mutualGravity, w.balls(), 0, 1).size;
            forcelab::test::report("%s: %s at t = %.4g s, |dE/E| = %.3g", row.tag.c_str(), w.halted() ? "stopped" : "ran", w.time(),
                  drift);
            VERIFY(finite(w));
            if (stops) {
                VERIFY(w.halted());
                const Text message = Text(*w.halted());
                forcelab::test::report("%s", Text(message).c_str());
                VERIFY2(message.contains("balls 0 and 1"), Text(message).c_str());
                VERIFY(message.contains("softening") && message.contains("dt") && message.contains("ias15"));
                VERIFY2(drift <= 0.1, Text(Text::number(drift)).c_str());
            } else {
                VERIFY2(!w.halted(), w.halted() ? w.halted()->c_str() : "");
                VERIFY2(drift <= (softening > 0 ? 1e-3 : 1e-9), Text(Text::number(drift)).c_str());
            }
        }
    }
}

// The smallest and largest balls a world takes have a positive, finite mass
// and inverse mass; one radius below (1e-110 px: r³ underflowed to a mass of
// exactly 0, which the world took) or an explicit mass of 1e-300 is refused
// with the ball's key path, and the world keeps what it had.
TEST_CASE("TestExtremes::everyBallHasAMass")
{
    World w;
    VERIFY(!w.reset(openScene({ballAt(100, 100, 0, 0, kMinRadius), ballAt(200, 100, 0, 0, kMaxRadius),
                                ballAt(300, 100, 0, 0, 10, kMinMass), ballAt(400, 100, 0, 0, 10, kMaxMass)})));
    const BallState& b = w.balls();
    for (int i = 0; i < b.size(); ++i) {
        VERIFY(b.mass[i] > 0.0 && std::isfinite(b.mass[i]));
        VERIFY(b.inverseMass[i] > 0.0 && std::isfinite(b.inverseMass[i]));
    }
    const auto tiny = w.reset(openScene({ballAt(100, 100, 0, 0, 1e-110)}));
    VERIFY(tiny && tiny->keyPath == "balls.0.r" && tiny->message == "1e-110 is outside [1e-06, 10000]");
    const auto light = w.reset(openScene({ballAt(100, 100), ballAt(100, 100, 0, 0, 10, 1e-300)}));
    VERIFY(light && light->keyPath == "balls.1.mass");
    REQUIRE_SAME(w.balls().size(), 4); // refused scenes change nothing
    // A world cannot be built on an invalid scene: the constructor refuses it
    // loudly with the same structured error, instead of running an empty world.
    try {
        const World refusedWorld(openScene({ballAt(100, 100, 0, 0, 1e-110)}));
        FAIL("World(scene) accepted a radius of 1e-110 px");
    } catch (const InvalidInput& e) {
        REQUIRE_SAME(e.error().keyPath, std::string("balls.0.r"));
        REQUIRE_SAME(std::string(e.what()), std::string("balls.0.r: 1e-110 is outside [1e-06, 10000]"));
    }
}


// Issue #31 item 10: the time a world reports is the time its state is at.
// Added plainly, dt = 0.001 s rounds the sum by up to half an ulp a step and
// the roundings do not cancel: 6283.185307179586 s (2000π) was reported as
// 6283.185308000889 s after its 6,283,185 steps and a shorter last one, while
// the state matched 2000π. Here, 628.3185307179586 s (200π) in 628,318 steps
// and a last one of 0.0005307 s, in an empty world (the time is all there is
// to check): plain sums were 7.9e-9 s short; now within 4 ulps of 200π
// (measured: 0), and after the whole steps alone equal to the correctly
// rounded product 628,318 × dt.
TEST_CASE("TestExtremes::timeAfterHundredsOfThousandsOfSteps")
{
    constexpr double kDuration = 200.0 * 3.141592653589793;
    Scene s = openScene({});
    s.settings.time.dt = 0.001;
    World world;
    REQUIRE(!world.reset(s));
    std::string why;
    const auto plan = planSteps(kDuration, s.settings.time.dt, 1'000'000'000, &why);
    REQUIRE(plan);
    REQUIRE_SAME(plan->whole, std::int64_t(628318));
    for (std::int64_t k = 0; k < plan->whole; ++k)
        world.step();
    const double wholeSteps = static_cast<double>(plan->whole) * s.settings.time.dt; // one rounding
    forcelab::test::report("after %lld steps: time %.17g s, whole steps × dt %.17g s", static_cast<long long>(plan->whole),
                           world.time(), wholeSteps);
    CHECK(std::abs(world.time() - wholeSteps) <= std::nextafter(wholeSteps, 1e300) - wholeSteps);
    runPlan(world, StepPlan{0, plan->last});
    const double ulp = std::nextafter(kDuration, 1e300) - kDuration;
    forcelab::test::report("after the last step of %.17g s: time %.17g s, asked %.17g s, off by %.3g s", plan->last,
                           world.time(), kDuration, world.time() - kDuration);
    CHECK(std::abs(world.time() - kDuration) <= 4.0 * ulp);
}
