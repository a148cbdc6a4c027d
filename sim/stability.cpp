#include "stability.h"

#include "ball_state.h"
#include "force_model.h"
#include "integrators.h"
#include "names.h"

#include <cmath>
#include <complex>
#include <cstdio>

namespace forcelab::sim {
namespace {

// Motion that doubles in more than this is slow enough to watch, not a blow-up.
constexpr double kDoublingSeconds = 10.0;

struct LinearModel {
    double omega2 = 0.0; // 1/s², spring + homing stiffness per unit mass
    double damping = 0.0; // 1/s, linear drag
    bool any() const { return omega2 > 0.0 || damping > 0.0; }
};

LinearModel linearModel(const WorldSettings& s)
{
    LinearModel m;
    if (s.spring.enabled)
        m.omega2 += s.spring.k;
    if (s.homing.enabled)
        m.omega2 += s.homing.strength;
    if (s.drag.enabled && s.drag.law == DragLaw::Linear)
        m.damping = s.drag.k;
    return m;
}

double growthPerStep(IntegratorKind kind, const LinearModel& model, double h, double tolerance)
{
    // The test problem as a world of its own: a spring of stiffness ω² to the
    // origin and linear drag c. Ball 0 starts at x = 1, ball 1 with v = 1, so
    // after one step their x-components are the columns of the step matrix.
    WorldSettings s;
    s.spring = SpringSettings{model.omega2 > 0.0, Vec2(0.0, 0.0), model.omega2};
    s.drag = DragSettings{model.damping > 0.0, DragLaw::Linear, model.damping};
    BallState balls;
    balls.resize(2);
    balls.set(0, Ball{Vec2(1.0, 0.0), Vec2(0.0, 0.0), 1.0, 1.0, 0, Vec2(0.0, 0.0)});
    balls.set(1, Ball{Vec2(0.0, 0.0), Vec2(1.0, 0.0), 1.0, 1.0, 0, Vec2(0.0, 0.0)});
    const StepInputs inputs;
    const ForceModel forces(s, balls, inputs);
    Integrator integrator;
    IntegratorStats stats;
    integrator.advance(kind, forces, balls.position, balls.velocity, 0.0, h, tolerance, stats);
    const double a = balls.position(0, 0), b = balls.position(0, 1);
    const double c = balls.velocity(0, 0), d = balls.velocity(0, 1);
    // Eigenvalues of [[a, b], [c, d]]: (tr ± √(tr² − 4 det)) / 2.
    const double tr = a + d, det = a * d - b * c;
    const std::complex<double> root = std::sqrt(std::complex<double>(tr * tr - 4.0 * det, 0.0));
    return std::max(std::abs(0.5 * (tr + root)), std::abs(0.5 * (tr - root)));
}

// True when the test motion doubles within kDoublingSeconds at sub-step h.
bool blowsUp(IntegratorKind kind, const LinearModel& model, double h, double tolerance)
{
    const double rho = growthPerStep(kind, model, h, tolerance);
    if (!std::isfinite(rho))
        return true;
    if (rho <= 1.0 + 1e-12)
        return false;
    const double stepsPerSecond = 1.0 / h;
    return stepsPerSecond * std::log(rho) * kDoublingSeconds > std::log(2.0);
}

std::string format(double v)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", v);
    return text;
}

} // namespace

double linearGrowthPerStep(const WorldSettings& settings, double h)
{
    return growthPerStep(settings.time.integrator, linearModel(settings), h, settings.time.tolerance);
}

std::optional<std::string> stabilityProblem(const WorldSettings& s)
{
    const IntegratorKind kind = s.time.integrator;
    if (kind == IntegratorKind::Rk45 || kind == IntegratorKind::Ias15 || kind == IntegratorKind::Exact) // adapts its own step / has no such model
        return std::nullopt;
    const LinearModel model = linearModel(s);
    if (!model.any())
        return std::nullopt;
    const double h = (s.time.perFrame ? kFrameSeconds : s.time.dt) / s.time.substeps;
    if (!blowsUp(kind, model, h, s.time.tolerance))
        return std::nullopt;

    // The largest stable sub-step, by bisection on a log scale.
    double lo = h * 1e-9, hi = h;
    for (int i = 0; i < 60; ++i) {
        const double mid = std::sqrt(lo * hi);
        (blowsUp(kind, model, mid, s.time.tolerance) ? hi : lo) = mid;
    }
    const double safeDt = lo * s.time.substeps;
    const double rho = growthPerStep(kind, model, h, s.time.tolerance);
    const double perSecond = std::exp(std::log(rho) / h);

    std::string what = model.omega2 > 0.0 && model.damping > 0.0 ? "this spring with drag"
                       : model.omega2 > 0.0                      ? "this spring"
                                                                 : "this drag";
    std::string message = std::string(toString(kind)) + " is unstable for " + what + " at dt = " +
                          format(s.time.dt) + " s";
    if (model.omega2 > 0.0)
        message += " (ω = √k = " + format(std::sqrt(model.omega2)) + " rad/s)";
    if (model.damping > 0.0)
        message += " (k·dt = " + format(model.damping * h) + ")";
    message += ": the motion grows " + (perSecond > 1e6 ? std::string("more than a million") : format(perSecond)) +
               " times every second. Lower dt below " + format(safeDt) + " s";
    if (kind == IntegratorKind::Euler && model.omega2 > 0.0)
        message += " or pick verlet";
    else if (model.damping > 0.0)
        message += " or lower the drag";
    return message;
}

} // namespace forcelab::sim
