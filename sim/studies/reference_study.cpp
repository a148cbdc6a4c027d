#include "sim/studies/reference_study.h"

#include "sim/integrators/integrator_info.h"
#include "sim/studies/kepler.h"
#include "sim/world/names.h"
#include "sim/studies/work_precision.h"
#include "sim/world/world.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace forcelab::sim {
namespace {

constexpr double kPi = std::numbers::pi;

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    const std::size_t m = v.size() / 2;
    return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

} // namespace

// The reference problems. Each builds a scene for a time step and knows the
// exact positions at its end time and, when it has one, the exact energy.




// Kepler's problem (sim/studies/kepler.h): a = 100 px, period 1 s, starting at
// periapsis. The end is 5/16 of an orbit past the whole orbits: at whole
// orbits some errors cancel.
ReferenceProblem keplerProblem(double e, int orbits)
{
    KeplerOrbit orbit;
    orbit.e = e;
    std::ostringstream name;
    name << "kepler-e" << e << "-" << orbits;
    ReferenceProblem p;
    p.name = name.str();
    p.what = "Kepler orbit, e = " + std::to_string(e).substr(0, 3) + ", " + std::to_string(orbits) + " orbits";
    p.endTime = orbits + 5.0 / 16.0;
    p.length = orbit.a;
    p.scene = [=] {
        Scene s = orbit.scene(IntegratorKind::SemiImplicitEuler, 1.0 / 60); // integrator and dt: set by the sweep
        s.settings.box = BoxSettings{600.0, 400.0};
        return s;
    };
    p.exact = [=](double t) {
        Matrix2X x(2, 1);
        x.col(0) = orbit.position(t);
        return x;
    };
    const double energy = orbit.energyPerMass(); // the ball's mass is 1
    p.energyError = [=](const World& w) { return std::abs((w.energy().total() - energy) / energy); };
    return p;
}

// Falling from rest with linear drag: v = (g/k)(1 − e^(−kt)),
// y = y₀ + (g/k) t − (g/k²)(1 − e^(−kt)). No energy to conserve. The
// closed form is per unit mass, so the drag acts the same on every ball
// (scale none); as a force it would be k·m₁₀/m on this mass-1 ball.
ReferenceProblem dragFallProblem()
{
    const double g = 980.0, k = 1.5, y0 = 0.0;
    ReferenceProblem p;
    p.name = "drag";
    p.what = "free fall with linear drag, k = 1.5/s, 2 s";
    p.endTime = 2.0;
    p.length = g / (k * k);
    p.scene = [=] {
        Scene s = openScene({ballAt(100.0, y0, 0.0, 0.0, 10.0, 1.0)});
        s.settings.gravity = GravitySettings{true, Vec2(0.0, g)};
        s.settings.drag = DragSettings{true, DragLaw::Linear, k, ForceScale::None};
        return s;
    };
    p.exact = [=](double t) {
        Matrix2X x(2, 1);
        x.col(0) = Vec2(100.0, y0 + g / k * t - g / (k * k) * (1.0 - std::exp(-k * t)));
        return x;
    };
    return p;
}

// A spring to an anchor, ω = √k = 2 rad/s: an ellipse x = A cos ωt,
// y = (v₀/ω) sin ωt around the anchor. About 3.3 periods.
ReferenceProblem springProblem()
{
    const double k = 4.0, w = 2.0, A = 100.0, v0 = 120.0;
    const Vec2 anchor(300.0, 200.0);
    ReferenceProblem p;
    p.name = "spring";
    p.what = "spring (harmonic oscillator), omega = 2 rad/s, 3.3 periods";
    p.endTime = 10.3125;
    p.length = A;
    p.scene = [=] {
        Scene s = openScene({ballAt(anchor.x() + A, anchor.y(), 0.0, v0, 10.0, 1.0)});
        s.settings.spring = SpringSettings{true, anchor, k};
        return s;
    };
    p.exact = [=](double t) {
        Matrix2X x(2, 1);
        x.col(0) = anchor + Vec2(A * std::cos(w * t), v0 / w * std::sin(w * t));
        return x;
    };
    const double energy = 0.5 * v0 * v0 + 0.5 * k * A * A;
    p.energyError = [=](const World& wd) { return std::abs((wd.energy().total() - energy) / energy); };
    return p;
}

// Dropped from rest H = 300 px above the floor, exact walls, restitution e:
// after bounce k the ball rises to e^(2k) H. The energy error is the height
// the ball's energy would carry it to (floor gap + v²/2g) against e^(2k) H,
// with k the bounces counted so far.
ReferenceProblem bounceProblem()
{
    const double g = 980.0, H = 300.0, e = 0.8, r = 10.0, floorY = 400.0 - r;
    ReferenceProblem p;
    p.name = "bounce";
    p.what = "ball bouncing, restitution 0.8, exact walls, 3.5 s";
    p.endTime = 3.5;
    p.length = H;
    p.scene = [=] {
        Scene s = openScene({ballAt(300.0, floorY - H, 0.0, 0.0, r, 1.0)});
        s.settings.walls = WallSettings{false, false, false, true, WallModel::Exact, e};
        s.settings.gravity = GravitySettings{true, Vec2(0.0, g)};
        return s;
    };
    p.exact = [=](double t) {
        // Flight k (k = 0 the drop) starts at the floor with speed e^k u₀
        // upwards (k ≥ 1) and lasts 2 e^k u₀ / g.
        const double u0 = std::sqrt(2.0 * g * H);
        double start = std::sqrt(2.0 * H / g); // the first impact
        Matrix2X x(2, 1);
        if (t <= start) {
            x.col(0) = Vec2(300.0, floorY - H + 0.5 * g * t * t);
            return x;
        }
        double speed = e * u0;
        while (t > start + 2.0 * speed / g) {
            start += 2.0 * speed / g;
            speed *= e;
        }
        const double s = t - start;
        x.col(0) = Vec2(300.0, floorY - speed * s + 0.5 * g * s * s);
        return x;
    };
    p.energyError = [=](const World& w) {
        const double y = w.balls().position(1, 0), vy = w.balls().velocity(1, 0);
        const double height = (floorY - y) + vy * vy / (2.0 * g);
        const double expected = H * std::pow(e, 2.0 * static_cast<double>(w.totals().wallHits));
        return std::abs(height - expected) / expected;
    };
    return p;
}

// Two balls (masses 1 and 3) meet head-on, elastic 2D impulse response, no
// forces. They touch at t_c; afterwards v₁' = ((m₁−m₂)v₁ + 2m₂v₂)/(m₁+m₂) and
// v₂' = ((m₂−m₁)v₂ + 2m₁v₁)/(m₁+m₂). The energy (kinetic) must stay.
ReferenceProblem twoBallsProblem()
{
    const double m1 = 1.0, m2 = 3.0, r = 10.0;
    const Vec2 x1(150.0, 200.0), x2(400.0, 200.0), v1(130.0, 0.0), v2(-70.0, 0.0);
    ReferenceProblem p;
    p.name = "two-balls";
    p.what = "two balls, masses 1 and 3, elastic head-on collision, 2 s";
    p.endTime = 2.0;
    p.length = 2.0 * r;
    p.scene = [=] {
        Scene s = openScene({ballAt(x1.x(), x1.y(), v1.x(), v1.y(), r, m1),
                             ballAt(x2.x(), x2.y(), v2.x(), v2.y(), r, m2)});
        s.settings.collisions.response = Response::Impulse2D;
        s.settings.collisions.restitution = 1.0;
        return s;
    };
    const double tc = ((x2.x() - x1.x()) - 2.0 * r) / (v1.x() - v2.x());
    const Vec2 w1 = ((m1 - m2) * v1 + 2.0 * m2 * v2) / (m1 + m2);
    const Vec2 w2 = ((m2 - m1) * v2 + 2.0 * m1 * v1) / (m1 + m2);
    p.exact = [=](double t) {
        Matrix2X x(2, 2);
        if (t <= tc) {
            x.col(0) = x1 + v1 * t;
            x.col(1) = x2 + v2 * t;
        } else {
            x.col(0) = x1 + v1 * tc + w1 * (t - tc);
            x.col(1) = x2 + v2 * tc + w2 * (t - tc);
        }
        return x;
    };
    const double energy = 0.5 * m1 * v1.squaredNorm() + 0.5 * m2 * v2.squaredNorm();
    p.energyError = [=](const World& w) { return std::abs((w.energy().kinetic - energy) / energy); };
    return p;
}

std::vector<ReferenceProblem> referenceProblems(bool quick)
{
    std::vector<ReferenceProblem> p{keplerProblem(0.0, 10), keplerProblem(0.5, 10)};
    if (!quick) {
        p.push_back(keplerProblem(0.0, 100));
        p.push_back(keplerProblem(0.5, 100));
    }
    p.push_back(dragFallProblem());
    p.push_back(springProblem());
    p.push_back(bounceProblem());
    p.push_back(twoBallsProblem());
    return p;
}

// One run and its measurements.



std::optional<SweepRun> runReference(const ReferenceProblem& p, IntegratorKind kind, double dt, double tolerance, int repeats)
{
    Scene scene = p.scene();
    scene.settings.time.integrator = kind;
    scene.settings.time.dt = dt;
    if (tolerance > 0.0)
        scene.settings.time.tolerance = tolerance;
    if (validateSettings(scene.settings))
        return std::nullopt; // e.g. exact with a force that is not constant
    SweepRun row;
    row.problem = p.name;
    row.integrator = kind;
    row.dt = dt;
    row.tolerance = tolerance;
    row.steps = static_cast<std::int64_t>(std::llround(p.endTime / dt));
    std::vector<double> times;
    for (int r = 0; r < repeats; ++r) {
        World world;
        if (world.reset(scene))
            return std::nullopt;
        const bool first = r == 0;
        double worstEnergy = 0.0;
        for (std::int64_t k = 0; k < row.steps && !world.halted(); ++k) {
            world.step();
            // The energy is sampled at every step, so many times inside each
            // orbit; the sampling is outside the timed step.
            if (first && p.energyError)
                worstEnergy = std::max(worstEnergy, p.energyError(world));
        }
        if (world.halted()) {
            row.blewUp = true;
            row.positionError = std::numeric_limits<double>::infinity();
            row.energyError = std::numeric_limits<double>::infinity();
            return row;
        }
        times.push_back(world.totals().seconds * 1e3);
        if (first) {
            row.evaluations = world.totals().forceEvaluations;
            const Matrix2X exact = p.exact(world.time());
            row.positionError = (world.balls().position - exact).colwise().norm().maxCoeff();
            if (p.energyError)
                row.energyError = worstEnergy;
        }
    }
    row.wallMs = median(times);
    row.nsPerStepBall = row.wallMs * 1e6 / static_cast<double>(row.steps) / static_cast<double>(scene.balls.size());
    return row;
}

// Fitted order: least-squares slope of log(error) against log(dt), over the
// runs in the asymptotic range: error above rounding (1e-10 of the problem's
// size) and below 1e-2 of it, where error ≈ C dt^p holds.


OrderFit fitOrder(const std::vector<SweepRun>& rows, const ReferenceProblem& p, IntegratorKind kind)
{
    std::vector<double> dts, errors;
    for (const SweepRun& r : rows) {
        if (r.problem != p.name || r.integrator != kind || r.tolerance > 0.0 || r.blewUp)
            continue;
        const double rel = r.positionError / p.length;
        if (!(rel > 1e-10 && rel < 1e-2))
            continue;
        dts.push_back(r.dt);
        errors.push_back(r.positionError);
    }
    OrderFit f;
    f.points = int(dts.size());
    if (f.points >= 3)
        f.order = sim::fittedOrder(dts, errors); // the workbench's convergence button fits the same way
    return f;
}


std::vector<SweepJob> planSweep(const std::vector<ReferenceProblem>& problems, bool quick)
{
    const std::vector<double> tolerances = quick ? std::vector<double>{1e-3, 1e-6, 1e-9}
                                                   : std::vector<double>{1e-2, 1e-3, 1e-4, 1e-6, 1e-8, 1e-9, 1e-11};
    auto dtRange = [&](IntegratorKind k) -> std::pair<int, int> {
        switch (k) {
        case IntegratorKind::Euler:
            return quick ? std::pair{10, 14} : std::pair{8, 16};
        case IntegratorKind::SemiImplicitEuler:
        case IntegratorKind::Exact:
            return quick ? std::pair{8, 12} : std::pair{6, 14};
        case IntegratorKind::Verlet:
            return quick ? std::pair{7, 11} : std::pair{5, 13};
        case IntegratorKind::Rk45:
        case IntegratorKind::Ias15:
            return quick ? std::pair{3, 5} : std::pair{2, 7};
        default: // rk4, yoshida4
            return quick ? std::pair{5, 9} : std::pair{4, 11};
        }
    };
    constexpr double kAdaptiveDt = 1.0 / 16;
    constexpr double kDefaultTolerance = 1e-9;
    std::vector<SweepJob> jobs;
    for (const ReferenceProblem& p : problems) {
        for (std::size_t k = 0; k < integratorNames().size(); ++k) {
            const auto kind = static_cast<IntegratorKind>(k);
            const bool adaptive = integratorInfo(kind).adaptive;
            const auto [from, to] = dtRange(kind);
            for (int e = from; e <= to; ++e)
                jobs.push_back({&p, kind, std::ldexp(1.0, -e), adaptive ? kDefaultTolerance : 0.0});
            if (adaptive)
                for (double tol : tolerances)
                    if (tol != kDefaultTolerance)
                        jobs.push_back({&p, kind, kAdaptiveDt, tol});
        }
    }

    return jobs;
}

} // namespace forcelab::sim
