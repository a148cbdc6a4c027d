#include "sim/forces/close_pass.h"

#include "sim/forces/force_model.h"
#include "sim/forces/custom_force.h"
#include "sim/integrators/integrator_info.h"

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <limits>

namespace forcelab::sim {
namespace {

std::string format(double v, int digits = 2)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.*g", digits, v);
    return text;
}

} // namespace

std::optional<ClosePass> shortestFallTime(const WorldSettings& s, const BallState& b, Pulls pulls)
{
    std::optional<ClosePass> best;
    auto consider = [&](int i, int j, double d, double mu) {
        if (!(mu > 0.0))
            return;
        const double tau = std::sqrt(d * d * d / mu);
        if (!best || tau < best->fallTime)
            best = ClosePass{i, j, d, tau};
    };
    const int n = b.size();
    if (s.mutualGravity.enabled && s.mutualGravity.G > 0.0) {
        // With Plummer softening the pull changes as if the bodies were never
        // closer than √(r² + ε²).
        const double eps2 = s.mutualGravity.softening * s.mutualGravity.softening;
        const double G = s.mutualGravity.G;
        for (int i = 0; i < n; ++i)
            for (int j = i + 1; j < n; ++j) {
                const double r2 = (b.position.col(j) - b.position.col(i)).squaredNorm();
                const double tau2 = std::pow(r2 + eps2, 1.5) / (G * (b.mass[i] + b.mass[j]));
                if (!best || tau2 < best->fallTime * best->fallTime)
                    best = ClosePass{i, j, std::sqrt(r2), std::sqrt(tau2)};
            }
    }
    const bool point = pulls == Pulls::PairsAndPoint ||
                       (pulls == Pulls::PairsAndUnclampedPoint && !(s.point.maxAccel > 0.0));
    if (point && s.point.enabled && s.point.kind == PointKind::Attract) {
        // a = S c / d², or maxAccel where the clamp holds: μ = min(S c, maxAccel d²).
        const VectorX scale = scaleFactors(s.point.scale, b);
        for (int i = 0; i < n; ++i) {
            const double d = (b.position.col(i) - s.point.position).norm();
            double mu = s.point.strength * scale[i];
            if (s.point.maxAccel > 0.0)
                mu = std::min(mu, s.point.maxAccel * d * d);
            consider(i, -1, d, mu);
        }
    }
    return best;
}

PairEnergy pairEnergy(const MutualGravitySettings& g, const BallState& b, int i, int j)
{
    const double mi = b.mass[i], mj = b.mass[j];
    const double kinetic = 0.5 * (mi * mj / (mi + mj)) * (b.velocity.col(j) - b.velocity.col(i)).squaredNorm();
    const double s2 = (b.position.col(j) - b.position.col(i)).squaredNorm() + g.softening * g.softening;
    const double potential = s2 > 0.0 ? -g.G * mi * mj / std::sqrt(s2) : 0.0;
    return PairEnergy{kinetic + potential, kinetic + std::abs(potential)};
}

std::string describeClosePass(const ClosePass& pass, const WorldSettings& s, double subStep)
{
    std::string who = pass.second >= 0 ? "balls " + std::to_string(pass.first) + " and " +
                                             std::to_string(pass.second) + " came within " + format(pass.distance) +
                                             " px of each other"
                                       : "ball " + std::to_string(pass.first) + " came within " +
                                             format(pass.distance) + " px of the attracting point at (" +
                                             format(s.point.position.x(), 6) + ", " +
                                             format(s.point.position.y(), 6) + ")";
    std::string fix = pass.second >= 0 ? "add softening (models.mutual_gravity.softening)"
                                       : "set max_accel (the clamp of models.point)";
    if (integratorInfo(s.time.integrator).adaptive) {
        // An adaptive integrator already shortened its sub-steps as far as
        // they go: neither dt nor another integrator helps, only a pull that
        // stays finite.
        return who + ", where a free fall takes " + format(pass.fallTime) +
               " s: the pull there is singular, or nearly, and no sub-step can follow the fall. Fix: " + fix;
    }
    // A step that follows a free fall of τ in four sub-steps or more.
    const double safeDt = 0.25 * pass.fallTime * s.time.substeps;
    return who + ", where a free fall takes " + format(pass.fallTime) + " s against a sub-step of " +
           format(subStep) + " s, so the step cannot follow the pass. Fix: " + fix +
           ", lower dt below " + format(safeDt) + " s, or pick an adaptive integrator (rk45 or ias15)";
}

bool SteepForce::followedBy(double h) const
{
    const double h2 = h * h;
    const double low = std::min(start, end);
    const double high = largest();
    if (!(h2 * high <= 4.0)) // also for +∞ and NaN
        return false;
    return h2 * high <= 0.5 || high <= 1.5 * low;
}

namespace {

// |∂a/∂x| of the custom force at every ball. The law acts on each ball alone
// (its formulas see only that ball), so moving every ball at once by its own
// small step gives every ball's derivative in one evaluation per direction.
// The step is scaled to the position: small against any distance the law
// changes over, large against its rounding. +∞ where the law is not finite.
VectorX customStiffness(const WorldSettings& s, const BallState& b, double t)
{
    const int n = b.size();
    const VectorX delta = 1e-7 * b.position.cwiseAbs().colwise().maxCoeff().transpose().cwiseMax(1.0);
    Matrix2X base = Matrix2X::Zero(2, n);
    addCustomAcceleration(s, b, b.position, b.velocity, t, base);
    Matrix2X column[2];
    for (int axis = 0; axis < 2; ++axis) {
        Matrix2X moved = b.position;
        moved.row(axis) += delta.transpose();
        column[axis] = Matrix2X::Zero(2, n);
        addCustomAcceleration(s, b, moved, b.velocity, t, column[axis]);
    }
    VectorX stiffness(n);
    for (int i = 0; i < n; ++i) {
        Eigen::Matrix2d jacobian;
        jacobian.col(0) = (column[0].col(i) - base.col(i)) / delta[i];
        jacobian.col(1) = (column[1].col(i) - base.col(i)) / delta[i];
        stiffness[i] = std::numeric_limits<double>::infinity();
        if (jacobian.allFinite() && base.col(i).allFinite()) {
            // The largest singular value of a 2×2 matrix, in closed form.
            const double frobenius2 = jacobian.squaredNorm();
            const double det = jacobian(0, 0) * jacobian(1, 1) - jacobian(0, 1) * jacobian(1, 0);
            stiffness[i] =
                std::sqrt(0.5 * (frobenius2 + std::sqrt(std::max(0.0, frobenius2 * frobenius2 - 4.0 * det * det))));
        }
    }
    return stiffness;
}

} // namespace

std::optional<SteepForce> steepestCustomForce(const WorldSettings& s, const BallState& before, double tBefore,
                                              const BallState& b, double t, double h)
{
    if (!s.custom.enabled || b.size() == 0 || before.size() != b.size())
        return std::nullopt;
    const VectorX start = customStiffness(s, before, tBefore);
    const VectorX end = customStiffness(s, b, t);
    // The ball followed worst: not followed first, then the stiffest.
    std::optional<SteepForce> worst;
    for (int i = 0; i < b.size(); ++i) {
        const SteepForce candidate{i, start[i], end[i]};
        if (!worst || (!candidate.followedBy(h) && worst->followedBy(h)) ||
            (candidate.followedBy(h) == worst->followedBy(h) && candidate.largest() > worst->largest()))
            worst = candidate;
    }
    return worst;
}

std::string describeSteepForce(const SteepForce& steep, const WorldSettings& s, const BallState& b, double subStep)
{
    const Vec2 at = b.position.col(steep.ball);
    std::string where = "ball " + std::to_string(steep.ball) + " at (" + format(at.x(), 6) + ", " +
                        format(at.y(), 6) + ") px";
    const std::string law = describeCustomLaw(s.custom);
    const std::string singularFix = "keep its denominator away from zero (add a small constant to the distance "
                                    "squared, as softening does)";
    if (!std::isfinite(steep.largest()))
        return law + " is not finite next to " + where + ". Fix: " + singularFix;
    const double omega = std::sqrt(steep.largest());
    // h ω = 2 at the limit; a sub-step of 1/ω follows the law with room to spare.
    const std::string lower = "lower dt below " + format(s.time.substeps / omega) +
                              " s, or pick an adaptive integrator (rk45 or ias15)";
    if (subStep * omega > 2.0)
        return law + " changes faster than the step can follow at " + where + ": it stiffens by " +
               format(steep.largest()) + " px/s² per px there, so a sub-step of " + format(subStep) +
               " s overshoots (h ω = " + format(subStep * omega) + ", above 2). Fix: if the law is singular there, " +
               singularFix + "; otherwise " + lower;
    return law + " stiffens from " + format(steep.start) + " to " + format(steep.end) +
           " px/s² per px within one step at " + where + ", as a pull does near a point where it is singular: the " +
           "next step would jump past that point. Fix: " + singularFix + "; lower dt (that helps a ball that " +
           "passes the point at a distance, not one that falls straight in), or pick an adaptive integrator (rk45 " +
           "or ias15)";
}

} // namespace forcelab::sim
