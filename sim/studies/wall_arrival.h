#pragma once
// When a ball next reaches a wall, if its acceleration stays what it is now:
// x(t) = x + v t + ½ a t² solved against each wall that is on (and the
// middle wall on the ball's side). Exact for a ball under uniform gravity
// alone until it meets another ball; for other forces it is the straight
// continuation of the present motion, which the caller says is "about".
#include "sim/world/types.h"
#include "sim/world/world_settings.h"

#include <optional>

namespace forcelab::sim {

enum class WallSide { Left, Right, Top, Bottom, Middle };

struct WallArrival {
    double seconds = 0.0; ///< s from now, > 0
    WallSide side = WallSide::Bottom;
};

/// `x` px, `v` px/s, `a` px/s², `radius` px. nullopt when no wall that is on
/// is ever reached (moving away from all of them, or resting against one).
std::optional<WallArrival> nextWallArrival(const BoxSettings& box, const WallSettings& walls, const Vec2& x,
                                           const Vec2& v, const Vec2& a, double radius);

} // namespace forcelab::sim
