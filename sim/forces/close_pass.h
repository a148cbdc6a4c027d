#pragma once
// Close passes. Mutual gravity without softening and an attracting point
// without a clamp pull as 1/d², so near a close pass the acceleration changes
// on the time scale of a free fall, τ = √(d³ / μ), where μ = G (m₁ + m₂) for a
// pair and the point's strength for a ball and the point. A fixed step longer
// than τ cannot follow the pass: the bodies jump past each other within a step
// or two and leave with energy that came from nowhere. Softening (d² → d² + ε²)
// and the clamp bound the acceleration, and τ with them. A repelling pair
// (G < 0) cannot fall into each other, so it has no such pass.

#include "sim/world/ball_state.h"
#include "sim/world/world_settings.h"

#include <algorithm>
#include <optional>
#include <string>

namespace forcelab::sim {

struct ClosePass {
    int first = -1;        ///< ball index
    int second = -1;       ///< ball index, or -1 for the attracting point
    double distance = 0.0; ///< px, centre to centre, or centre to the point
    double fallTime = 0.0; ///< s, τ = √(d³ / μ) with softening and the clamp taken into account
};

/// The energy of the relative motion of balls i and j under their mutual
/// gravity, ½ μ |v_j − v_i|² − G m_i m_j / √(r² + ε²) (μ = m_i m_j / (m_i + m_j)),
/// and its size (the sum of the two terms' magnitudes): the scale of the
/// energy errors a close pass can make.
struct PairEnergy {
    double energy = 0.0; ///< mass·px²/s²
    double size = 0.0;   ///< mass·px²/s²
};
PairEnergy pairEnergy(const MutualGravitySettings& gravity, const BallState& balls, int i, int j);

/// Which 1/d² pulls shortestFallTime() looks at.
enum class Pulls {
    Pairs,                  ///< attracting mutual gravity only (G > 0)
    PairsAndPoint,          ///< also the attracting point
    PairsAndUnclampedPoint, ///< also the attracting point, unless its clamp bounds the pull
};

/// The pair (or ball and point) with the shortest fall time, or nullopt when
/// no such pull is on. O(N²) with mutual gravity, like one force evaluation.
std::optional<ClosePass> shortestFallTime(const WorldSettings& settings, const BallState& balls, Pulls pulls);

/// "balls 0 and 1 came within 0.31 px of each other …" with what to change:
/// softening (or the clamp), a shorter dt, an adaptive integrator. With an
/// adaptive integrator (which gave up on the pass) only softening or the
/// clamp: its sub-steps already went as short as they may.
std::string describeClosePass(const ClosePass& pass, const WorldSettings& settings, double subStep);

/// How stiff a student's force law (the custom force) is over a step, at
/// the ball where a fixed sub-step h follows it worst. The stiffness is
/// |∂a/∂x|, the spectral norm of the 2×2 derivative of the law's
/// acceleration by the ball's position (forward differences), at the step's
/// start and at its end. A linear force of stiffness ω² makes semi-implicit
/// Euler and verlet grow without end once h ω > 2, so h² · stiffness > 4 is
/// never followed. A law that is singular at a point (1/d²) stiffens without
/// bound as a ball nears it: once it stiffens within one step the step jumps
/// past, so h² · stiffness > 0.5 (the bar the 1/d² pulls of the built-in
/// models meet, close_pass) with the stiffness changing by more than half
/// within the step is not followed either.
struct SteepForce {
    int ball = -1;      ///< ball index
    double start = 0.0; ///< 1/s², |∂a/∂x| at the step's start; +∞ where the law is not finite
    double end = 0.0;   ///< 1/s², the same at its end
    double largest() const { return std::max(start, end); }
    /// Whether a fixed sub-step h follows the law at this ball.
    bool followedBy(double h) const;
};
std::optional<SteepForce> steepestCustomForce(const WorldSettings& settings, const BallState& before, double tBefore,
                                              const BallState& after, double tAfter, double subStep);

/// "the custom force changes faster than the step can follow at ball 0 …"
/// with where it is and what to change.
std::string describeSteepForce(const SteepForce& steep, const WorldSettings& settings, const BallState& balls,
                               double subStep);

} // namespace forcelab::sim
