#include "stability.h"

#include "ball_state.h"
#include "force_model.h"
#include "force_models.h"
#include "integrator_info.h"
#include "integrators.h"
#include "names.h"
#include "parameters.h"

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

LinearModel linearModel(const WorldSettings& s, double dragFactor)
{
    LinearModel m;
    for (const ForceModelInfo& model : forceModels())
        if (model.on(s) && model.stiffness)
            model.stiffness(s, dragFactor, m.omega2, m.damping);
    return m;
}

// One step's growth: the largest |λ| of the step matrix, and whether the step
// matrix is defective there (a double eigenvalue with a single eigenvector).
// Then the motion grows like n λⁿ: at |λ| = 1 that is linear growth, which no
// spectral radius shows (semi-implicit Euler at exactly ω h = 2).
struct Growth {
    double rho = 0.0;
    bool linear = false;
};

Growth growth(IntegratorKind kind, const LinearModel& model, double h, double tolerance)
{
    // The test problem as a world of its own: a spring of stiffness ω² to the
    // origin and linear drag c. Ball 0 starts at x = 1, ball 1 with v = 1, so
    // after one step their x-components are the columns of the step matrix.
    WorldSettings s;
    s.spring = SpringSettings{model.omega2 > 0.0, Vec2(0.0, 0.0), model.omega2};
    s.drag = DragSettings{model.damping > 0.0, DragLaw::Linear, model.damping, ForceScale::None};
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
    // Eigenvalues of [[a, b], [c, d]]: (tr ± √(tr² − 4 det)) / 2, with
    // tr² − 4 det written as (a − d)² + 4bc: near a double eigenvalue 1 (weak
    // drag, short steps) tr² and 4 det are both about 4, and their difference
    // would be rounding noise that looks like growth.
    const double tr = a + d;
    const double disc = (a - d) * (a - d) + 4.0 * b * c;
    const std::complex<double> root = std::sqrt(std::complex<double>(disc, 0.0));
    Growth g;
    g.rho = std::max(std::abs(0.5 * (tr + root)), std::abs(0.5 * (tr - root)));
    // A double root λ = tr/2 has one eigenvector only when N = A − λ I is not
    // zero (then N is nilpotent). disc = (a − d)² + 4bc = −4 det N is measured
    // against 4 |N|², so "zero" means zero to rounding. N is measured in the
    // variables (x, v/ω), where every entry is of order ω h whatever the units:
    // a soft spring's two eigenvalues e^(±iωh) are then as far apart as N is
    // large, and are not taken for one. Without a spring (ω = 0) a double
    // eigenvalue can only be 1, the drift x + v t of the motion itself, which
    // is no fault of the method.
    if (model.omega2 > 0.0) {
        const double omega = std::sqrt(model.omega2);
        const double n2 = 0.5 * (a - d) * (a - d) + b * omega * b * omega + c / omega * c / omega; // |N|², Frobenius
        g.linear = n2 > 0.0 && std::abs(disc) <= 4e-9 * n2 && g.rho >= 1.0 - 1e-9;
    }
    return g;
}

// True when the test motion doubles within kDoublingSeconds at sub-step h, or
// grows without end (linearly, at a defective |λ| = 1).
bool blowsUp(IntegratorKind kind, const LinearModel& model, double h, double tolerance)
{
    const Growth g = growth(kind, model, h, tolerance);
    const double rho = g.rho;
    if (!std::isfinite(rho) || g.linear)
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

// A limit to 3 significant figures, rounded down so that what the message
// advises is really below the limit (0.28284 → 0.282, not 0.283).
std::string formatBelow(double v)
{
    if (!(v > 0.0) || !std::isfinite(v))
        return format(v);
    const double unit = std::pow(10.0, std::floor(std::log10(v)) - 2.0);
    double shown = std::floor(v / unit) * unit;
    if (shown > v) // the division rounded up
        shown -= unit;
    return format(shown);
}

// The current value with as many figures as it takes to differ from `other`.
std::string formatApart(double v, const std::string& other)
{
    for (int digits = 3; digits <= 17; ++digits) {
        char text[40];
        std::snprintf(text, sizeof text, "%.*g", digits, v);
        if (text != other)
            return text;
    }
    return format(v);
}

} // namespace

double linearGrowthPerStep(const WorldSettings& settings, double h, double dragFactor)
{
    return growth(settings.time.integrator, linearModel(settings, dragFactor), h, settings.time.tolerance).rho;
}

std::optional<std::string> stabilityProblem(const WorldSettings& s, double dragFactor)
{
    const IntegratorKind kind = s.time.integrator;
    if (std::isinf(integratorInfo(kind).springLimit)) // adapts its own step, or has no such model
        return std::nullopt;
    const LinearModel model = linearModel(s, dragFactor);
    if (!model.any())
        return std::nullopt;
    const double h = (s.time.perFrame ? kFrameSeconds : s.time.dt) / s.time.substeps;
    if (!blowsUp(kind, model, h, s.time.tolerance))
        return std::nullopt;

    // The largest sub-step at which the motion does not grow at all (not the
    // one where it merely grows slowly), by bisection on a log scale: advice
    // below it is safe however long the run.
    const auto growsAt = [&](double step) {
        const Growth g = growth(kind, model, step, s.time.tolerance);
        return !(g.rho <= 1.0 + 1e-12) || g.linear;
    };
    double lo = h * 1e-9, hi = h;
    for (int i = 0; i < 60; ++i) {
        const double mid = std::sqrt(lo * hi);
        (growsAt(mid) ? hi : lo) = mid;
    }
    const Growth g = growth(kind, model, h, s.time.tolerance);
    const double perSecond = std::exp(std::log(g.rho) / h);
    const std::string safe = formatBelow(lo * s.time.substeps); // the dt of that sub-step

    std::string what = model.omega2 > 0.0 && model.damping > 0.0 ? "this spring with drag"
                       : model.omega2 > 0.0                      ? "this spring"
                                                                 : "this drag";
    // Per-frame steps ignore dt, so the message names the frame instead, and
    // the fix is more sub-steps per frame: dt would change nothing.
    std::string message = std::string(toString(kind)) + " is unstable for " + what +
                          (s.time.perFrame ? " with per-frame steps of 1/60 s (dt is ignored)"
                                           : " at dt = " + formatApart(s.time.dt, safe) + " s");
    if (model.omega2 > 0.0)
        message += " (ω = √k = " + format(std::sqrt(model.omega2)) + " rad/s)";
    if (model.damping > 0.0) {
        // The number that decides is k times the sub-step h, which is dt only
        // without sub-steps and per-frame steps.
        const bool wholeStep = s.time.substeps == 1 && !s.time.perFrame;
        const std::string step = wholeStep ? "dt" : "h";
        const std::string ofStep = wholeStep ? "" : ", h the sub-step";
        if (std::abs(dragFactor - 1.0) <= 1e-12) {
            message += " (k·" + step + " = " + format(model.damping * h) + ofStep + ")";
        } else { // the ball drag slows fastest: the lightest (c = k m₁₀ / m) or, by radius, the smallest (c = k r₁₀ / r)
            const bool byRadius = s.drag.scale == ForceScale::Radius;
            message += " (c·" + step + " = " + format(model.damping * h) +
                       (byRadius ? " for the smallest ball, c = k × 10 px / r = "
                                 : " for the lightest ball, c = k × m₁₀ / m = ") +
                       format(model.damping) + "/s" + ofStep + ")";
        }
    }
    const std::string grows = g.linear && g.rho <= 1.0 + 1e-9
                                  ? std::string("a little more every step, without end")
                              : perSecond > 1e6 ? std::string("more than a million times every second")
                                                : format(perSecond) + " times every second";
    message += ": the motion grows " + grows + ". ";
    if (!s.time.perFrame) {
        message += "Lower dt below " + safe + " s";
    } else {
        // frame / n ≤ lo: n sub-steps of the frame do not grow.
        const double substeps = std::ceil(kFrameSeconds / lo);
        const Parameter* row = findParameter("time.substeps");
        if (row && substeps <= row->hi)
            message += "Raise substeps to " + std::to_string(static_cast<long long>(substeps)) + " or more";
        else
            message += "Switch per-frame steps off and lower dt below " + safe + " s";
    }
    if (kind == IntegratorKind::Euler && model.omega2 > 0.0)
        message += " or pick verlet";
    else if (model.damping > 0.0)
        message += " or lower the drag";
    return message;
}

} // namespace forcelab::sim
