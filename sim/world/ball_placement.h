#pragma once
// Where a ball placed by hand may go: an edit (a new ball, a drag, a typed
// position or radius) must never leave a ball inside a wall or, when balls
// collide, inside another ball. The ball is moved the shortest way to
// touching, or the placement is refused with a reason.

#include "sim/world/ball_state.h"
#include "sim/world/world_settings.h"

#include <string>

namespace forcelab::sim {

struct Placement {
    bool ok = false;
    Vec2 position{0.0, 0.0}; ///< px, where the ball goes: the wanted point, or moved to touching
    bool moved = false;      ///< the ball was moved from the wanted point
    std::string why;         ///< when refused: why, in one sentence
};

/// Relative gap left between balls moved to touching (of the sum of their
/// radii), so the two are not counted as overlapping by rounding.
inline constexpr double kTouchingGap = 1e-9;

/// Where a ball of `radius` px wanted at `wanted` px can go among `balls`
/// (skipping ball `ignore`, the one being moved, or −1) with these settings.
/// Walls that are on push it inside the box (its centre only, for
/// walls.centreOnly) and keep it on its side of the middle wall; when balls
/// collide (collisions.response is neither None nor Flag) it is pushed out of every ball it
/// overlaps, along the line of centres, up to 32 passes. Refused when it does
/// not fit between two walls or no nearby place is free.
Placement placeBall(const BallState& balls, const WorldSettings& settings, Vec2 wanted, double radius,
                    int ignore = -1);

} // namespace forcelab::sim
