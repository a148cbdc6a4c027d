#include "sim/integrators/stability.h"

#include "sim/world/ball_state.h"
#include "sim/forces/force_model.h"
#include "sim/forces/force_models.h"
#include "sim/integrators/integrator_info.h"
#include "sim/integrators/integrators.h"
#include "sim/world/names.h"
#include "sim/world/parameters.h"

#include <cctype>
#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>

namespace forcelab::sim {
namespace {

// Motion that doubles in more than this is slow enough to watch, not a blow-up.
constexpr double kDoublingSeconds = 10.0;

struct LinearModel {
    double omega2 = 0.0; // 1/s², spring + homing stiffness per unit mass
    double damping = 0.0; // 1/s, drag's rate (linear drag, or quadratic drag linearised at a speed)
    bool any() const { return omega2 > 0.0 || damping > 0.0; }
};

// The ball that drag slows fastest.
struct DragBall {
    double factor = 1.0; // its drag scale factor (1 with scale none)
    double speed = 0.0;  // px/s, what quadratic drag depends on; 0 when not known
};

LinearModel linearModel(const WorldSettings& s, const DragBall& drag)
{
    LinearModel m;
    for (const ForceModelInfo& model : forceModels())
        if (model.on(s) && model.stiffness)
            model.stiffness(s, drag.factor, drag.speed, m.omega2, m.damping);
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
    // Drag alone only ever slows a ball: any growth is the step's, however
    // slow (k·dt = 2.001 makes a ball 20 times faster in 60 s).
    if (model.omega2 == 0.0)
        return true;
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

// The largest sub-step at which `grows` is false, by bisection on a log
// scale below h (where it is true).
template <class Grows>
double largestStepWithout(double h, Grows grows)
{
    double lo = h * 1e-9, hi = h;
    for (int i = 0; i < 60; ++i) {
        const double mid = std::sqrt(lo * hi);
        (grows(mid) ? hi : lo) = mid;
    }
    return lo;
}

// The numbers that decide for drag, in brackets: k (or the ball's c) times
// the sub-step h, which is dt only without sub-steps and per-frame steps;
// for quadratic drag its linearised rate 2 c |v| times h, at the speed.
std::string dragNumbers(const WorldSettings& s, const DragBall& drag, double damping, double h)
{
    const bool wholeStep = s.time.substeps == 1 && !s.time.perFrame;
    const std::string step = wholeStep ? "dt" : "h";
    const std::string ofStep = wholeStep ? "" : ", h the sub-step";
    const bool scaled = std::abs(drag.factor - 1.0) > 1e-12;
    // The Euler methods' limit is 2: k·dt = 2.001 must not read "2".
    const std::string product = formatApart(damping * h, "2");
    // The ball drag slows fastest: the lightest (c = k m₁₀ / m) or, by
    // radius, the smallest (c = k r₁₀ / r).
    const bool byRadius = s.drag.scale == ForceScale::Radius;
    if (s.drag.law == DragLaw::Linear) {
        if (!scaled)
            return " (k·" + step + " = " + product + ofStep + ")";
        return " (c·" + step + " = " + product +
               (byRadius ? " for the smallest ball, c = k × 10 px / r = " : " for the lightest ball, c = k × m₁₀ / m = ") +
               format(damping) + "/s" + ofStep + ")";
    }
    char speed[40]; // whole px/s from 100 up: "10000 px/s", not "1e+04 px/s"
    std::snprintf(speed, sizeof speed, drag.speed >= 100.0 && drag.speed < 1e12 ? "%.0f px/s" : "%.3g px/s",
                  drag.speed);
    if (!scaled)
        return " (2·k·|v|·" + step + " = " + product + " for the fastest ball, at " + std::string(speed) + ofStep + ")";
    return " (2·c·|v|·" + step + " = " + product + " for the ball drag slows most, at " + std::string(speed) +
           (byRadius ? " with c = k × 10 px / r = " : " with c = k × m₁₀ / m = ") + format(s.drag.k * drag.factor) +
           "/px" + ofStep + ")";
}

// The advice for a safe sub-step `lo`, in lower case: a dt, or with per-frame steps (which
// ignore dt) a number of sub-steps of the frame.
std::string lowerStep(const WorldSettings& s, double lo)
{
    const std::string safe = formatBelow(lo * s.time.substeps); // the dt of that sub-step
    if (!s.time.perFrame)
        return "lower dt below " + safe + " s";
    // frame / n ≤ lo: n sub-steps of the frame do not grow.
    const double substeps = std::ceil(kFrameSeconds / lo);
    const Parameter* row = findParameter("time.substeps");
    if (row && substeps <= row->hi)
        return "raise substeps to " + std::to_string(static_cast<long long>(substeps)) + " or more";
    return "switch per-frame steps off and lower dt below " + safe + " s";
}

// The advice at the start of a sentence.
std::string capitalised(std::string text)
{
    if (!text.empty())
        text[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(text[0])));
    return text;
}

std::optional<std::string> problem(const WorldSettings& s, const DragBall& drag)
{
    const IntegratorKind kind = s.time.integrator;
    if (std::isinf(integratorInfo(kind).springLimit)) // adapts its own step, or has no such model
        return std::nullopt;
    const LinearModel model = linearModel(s, drag);
    if (!model.any())
        return std::nullopt;
    const double h = (s.time.perFrame ? kFrameSeconds : s.time.dt) / s.time.substeps;
    if (!blowsUp(kind, model, h, s.time.tolerance))
        return std::nullopt;

    const Growth g = growth(kind, model, h, s.time.tolerance);
    std::string what = model.omega2 > 0.0 && model.damping > 0.0 ? "this spring with drag"
                       : model.omega2 > 0.0                      ? "this spring"
                                                                 : "this drag";
    // Per-frame steps ignore dt, so the message names the frame instead, and
    // the fix is more sub-steps per frame: dt would change nothing.
    std::string message = std::string(toString(kind)) + " is unstable for " + what +
                          (s.time.perFrame ? " with per-frame steps of 1/60 s (dt is ignored)" : "");
    // The dt is written out once the safe advice is known (formatApart).
    const std::size_t dtAt = message.size();
    if (model.omega2 > 0.0)
        message += " (ω = √k = " + format(std::sqrt(model.omega2)) + " rad/s)";
    if (model.damping > 0.0)
        message += dragNumbers(s, drag, model.damping, h);

    // Explicit Euler on an undamped spring: the step's eigenvalues are
    // 1 ± iωh, so the swing grows by √(1 + ω²h²) every step at every h. No
    // dt stops it: say how fast it grows, and where it is slow enough to
    // watch (doubling in more than kDoublingSeconds), which is what the
    // check lets run.
    if (kind == IntegratorKind::Euler && model.omega2 > 0.0 && model.damping == 0.0) {
        const double lo = largestStepWithout(h, [&](double step) { return blowsUp(kind, model, step, s.time.tolerance); });
        const double period = 2.0 * std::numbers::pi / std::sqrt(model.omega2); // s
        const double perPeriod = std::exp(std::log(g.rho) * period / h);
        const std::string grows = perPeriod > 1e6 ? std::string("more than a million times") : format(perPeriod) + " times";
        if (!s.time.perFrame)
            message.insert(dtAt, " at dt = " + format(s.time.dt) + " s");
        message += ": explicit Euler gains energy on an undamped spring at every dt, and here the swing grows " +
                   grows + " in every period of " + format(period) + " s. Pick semi-implicit-euler or verlet, "
                   "which keep the swing's size; a smaller step only slows the growth (" +
                   lowerStep(s, lo) + " and the swing takes more than " + format(kDoublingSeconds) +
                   " s to double)";
        return message;
    }

    // The largest sub-step at which the motion does not grow at all (not the
    // one where it merely grows slowly): advice below it is safe however long
    // the run.
    const double lo = largestStepWithout(h, [&](double step) {
        const Growth at = growth(kind, model, step, s.time.tolerance);
        return !(at.rho <= 1.0 + 1e-12) || at.linear;
    });
    const std::string safe = formatBelow(lo * s.time.substeps);
    if (!s.time.perFrame)
        message.insert(dtAt, " at dt = " + formatApart(s.time.dt, safe) + " s");
    if (model.omega2 == 0.0) {
        // Drag alone: the step overshoots. Quadratic drag's factor on the
        // speed is not the linearised one (an Euler step keeps 1 − c|v|h of
        // it), so only the Euler steps are said to turn the ball round.
        const bool eulerStep = kind == IntegratorKind::Euler || kind == IntegratorKind::SemiImplicitEuler;
        if (s.drag.law == DragLaw::Linear)
            message += ": one step turns the ball round or speeds it up instead of slowing it, which real drag never "
                       "does. ";
        else if (eulerStep) // v ← v (1 − c |v| h): turned round exactly when 2 c |v| h > 2
            message += ": at this speed one step would turn the ball round instead of slowing it, which real drag "
                       "never does. ";
        else
            message += ": at this speed the step is too long for the drag, and the motion would grow instead of "
                       "dying away, which real drag never does. ";
    } else {
        const double perSecond = std::exp(std::log(g.rho) / h);
        const std::string grows = g.linear && g.rho <= 1.0 + 1e-9
                                      ? std::string("a little more every step, without end")
                                  : perSecond > 1e6 ? std::string("more than a million times every second")
                                                    : format(perSecond) + " times every second";
        message += ": the motion grows " + grows + ". ";
    }
    message += capitalised(lowerStep(s, lo));
    if (kind == IntegratorKind::Euler && model.omega2 > 0.0)
        message += " or pick verlet";
    else if (model.damping > 0.0)
        message += " or lower the drag";
    return message;
}

} // namespace

double linearGrowthPerStep(const WorldSettings& settings, double h, double dragFactor)
{
    return growth(settings.time.integrator, linearModel(settings, DragBall{dragFactor, 0.0}), h,
                  settings.time.tolerance)
        .rho;
}

std::optional<std::string> stabilityProblem(const WorldSettings& s, double dragFactor)
{
    return problem(s, DragBall{dragFactor, 0.0});
}

std::optional<std::string> stabilityProblem(const WorldSettings& s, const BallState& balls)
{
    DragBall drag;
    if (s.drag.enabled && !balls.empty()) {
        const VectorX factor = s.drag.scale == ForceScale::None ? VectorX::Ones(balls.size())
                                                                : scaleFactors(s.drag.scale, balls);
        if (s.drag.law == DragLaw::Linear) {
            drag.factor = factor.maxCoeff();
        } else {
            // Quadratic drag slows fastest where c |v| is largest.
            const VectorX rate = factor.cwiseProduct(balls.velocity.colwise().norm().transpose());
            Eigen::Index i = 0;
            rate.maxCoeff(&i);
            drag.factor = factor[i];
            drag.speed = balls.velocity.col(i).norm();
        }
    }
    return problem(s, drag);
}

} // namespace forcelab::sim
