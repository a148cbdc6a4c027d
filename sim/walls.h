#pragma once
// The box's walls: after the integrator has moved the balls, a ball whose
// edge is past an enabled wall is bounced back. Each axis is handled on its
// own (x: left and right, y: top and bottom), so a corner is two bounces.

#include "world_settings.h"

#include <cstdint>

namespace forcelab::sim {

/// Bounces the balls off the enabled walls. x0, v0 are the positions and
/// velocities at the start of the step of length h (the `exact` model needs
/// both, the middle wall needs x0 to know each ball's side; otherwise they are
/// not read); x, v are the state after integration and are corrected in place.
/// Returns the number of bounces.
/// `integrator` tells the `exact` model the shape of the path inside the step.
std::int64_t applyWalls(const WallSettings& walls, const BoxSettings& box, IntegratorKind integrator,
                        const VectorX& radius, const Matrix2X& x0, const Matrix2X& v0, double h, Matrix2X& x,
                        Matrix2X& v);

} // namespace forcelab::sim
