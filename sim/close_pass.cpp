#include "close_pass.h"

#include "force_model.h"
#include "integrator_info.h"

#include <cmath>
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
    if (pulls == Pulls::PairsAndPoint && s.point.enabled && s.point.kind == PointKind::Attract) {
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

} // namespace forcelab::sim
