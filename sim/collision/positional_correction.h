#pragma once
// Positional correction: after the velocities are fixed, two balls that still
// overlap are pushed apart along the line of impact until they just touch.
// The push is shared in proportion to inverse mass (a heavy ball moves less),
// so the centre of mass stays put. Only positions change, never velocities,
// so no kinetic energy is added.
//
// Near an enabled wall a ball that was inside is not pushed through it: it
// stops on the wall and its partner takes the rest of the push.

#include "../types.h"
#include "../world_settings.h"

namespace forcelab::sim {

/// The line of impact from a to b: d/|d|, or, when the centres are too close
/// to give a direction (|d| ≤ 1e-12 · s, e.g. balls spawned on one point), a
/// fixed direction that depends only on (a, b). Different pairs get directions
/// spread around the circle, so a heap of balls on one point spreads out in
/// two dimensions, the same way every run.
Vec2 lineOfImpact(const Vec2& d, double s, int a, int b);

/// Pushes pa and pb apart along n by their overlap r_a + r_b − |pb − pa| (if
/// positive), shared as wa : wb. Returns the overlap that was removed.
double separate(Vec2& pa, Vec2& pb, double ra, double rb, const Vec2& n, double wa, double wb, const BoxSettings& box,
                const WallSettings& walls);

/// Pushes pa and pb apart along n by `depth`, shared as wa : wb, stopping a
/// ball at a wall it was inside (its partner then takes the rest).
void pushApart(Vec2& pa, Vec2& pb, double ra, double rb, const Vec2& n, double wa, double wb, double depth,
               const BoxSettings& box, const WallSettings& walls);

/// A ball whose centre was inside the walls at `before` and is outside them at
/// `after` is put back on the wall (position only). Returns whether it was.
bool keepInsideWalls(const Vec2& before, Vec2& after, double r, const BoxSettings& box, const WallSettings& walls);

} // namespace forcelab::sim
