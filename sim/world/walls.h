#pragma once
// The box's walls: after the integrator has moved the balls, a ball whose
// edge is past an enabled wall is bounced back. Each axis is handled on its
// own (x: left and right, y: top and bottom), so a corner is two bounces.

#include "sim/world/world_settings.h"

#include <cstdint>

namespace forcelab::sim {

/// The balls at the start of the sub-step. Every model reads them to tell a
/// ball lying still on a wall (it stays there) from one that fell onto it
/// (it bounces); the `exact` model follows the path from them, the middle
/// wall needs the positions to know each ball's side. The caller keeps them
/// whenever a wall is on; matrices of another size than the state are taken
/// as not kept and the resting check is skipped.
struct StepStart {
    const Matrix2X& position; ///< px
    const Matrix2X& velocity; ///< px/s
};

/// The balls as the walls see them: their radii and, where a scene has
/// them, which are pinned (null: none; a pinned ball is left where it is)
/// and their own restitutions (null: none; see effectiveRestitution).
struct WallBalls {
    const VectorX& radius; ///< px
    const unsigned char* pinned = nullptr;
    const double* restitution = nullptr;
};

/// Bounces the balls off the enabled walls of `settings` (walls, box; the
/// integrator tells the `exact` model the shape of the path inside the
/// sub-step of length h). x, v are the state after integration and are
/// corrected in place. Returns the number of bounces.
std::int64_t applyWalls(const WorldSettings& settings, const WallBalls& balls, const StepStart& start, double h,
                        Matrix2X& x, Matrix2X& v);

/// s, the first moment in [0, tMax] at which a coordinate moving as
/// p0 + u t + ½ a t² reaches `wall` while moving into it (`into` +1 for the
/// high wall, −1 for the low one), or NaN. A root with no speed counts only
/// when the acceleration presses into the wall. The exact wall model and
/// continuous detection's wall impacts share it.
double wallContactTime(double p0, double u, double a, double wall, double into, double tMax);

/// Whether a ball that has just bounced off a wall at `speed` (px/s, after
/// the bounce), pulled back to it at `pull` (px/s²) with restitution e < 1,
/// makes all its bounces within `within` s: they add up to
/// 2 |speed| / (pull (1 − e)). Never when it is pushed away or could reach
/// the opposite wall (`otherWall` on, `span` px away). The exact wall model
/// and continuous detection's wall impacts share it.
bool bouncesSettleWithin(double speed, double pull, double e, bool otherWall, double span, double within);

} // namespace forcelab::sim
