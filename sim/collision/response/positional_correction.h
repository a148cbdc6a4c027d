#pragma once
// Positional correction: after the velocities are fixed, two balls that still
// overlap are pushed apart along the line of impact until they just touch.
// The push is shared in proportion to inverse mass (a heavy ball moves less),
// so the centre of mass stays put. Only positions change, never velocities,
// so no kinetic energy is added.
//
// Near an enabled wall a ball that was inside is not pushed through it: it
// stops on the wall and its partner takes the rest of the push.

#include "sim/world/types.h"
#include "sim/world/world_settings.h"

#include <cmath>

namespace forcelab::sim {

/// The line of impact from a to b: d/|d|, or, when the centres are too close
/// to give a direction (|d| ≤ 1e-12 · s, e.g. balls spawned on one point), a
/// fixed direction that depends only on (a, b). Different pairs get directions
/// spread around the circle, so a heap of balls on one point spreads out in
/// two dimensions, the same way every run.
inline Vec2 lineOfImpact(const Vec2& d, double s, int a, int b);
/// The fixed direction lineOfImpact gives the pair (a, b) when its centres
/// are too close.
Vec2 spreadDirection(int a, int b);

/// The two balls of a pair that is pushed apart: their radii, the line of
/// impact n from a to b, and their inverse masses.
struct PairShape {
    double ra = 0.0; ///< px
    double rb = 0.0; ///< px
    Vec2 n{1.0, 0.0}; ///< unit vector from a to b
    double wa = 0.0; ///< 1/mass
    double wb = 0.0; ///< 1/mass
};

/// Whether a ball of radius r at (px, py) is inside every enabled wall: the
/// common case, where a push needs no wall handling.
struct WallCheck {
    bool on[2][2];  ///< [x, y][low side, high side]
    double size[2]; ///< px, the box's width and height
    bool inside(double px, double py, double r) const
    {
        return (!on[0][0] || px >= r) && (!on[0][1] || px <= size[0] - r) && (!on[1][0] || py >= r) &&
               (!on[1][1] || py <= size[1] - r);
    }
};

/// Pushes pa and pb apart along n by their overlap r_a + r_b − |pb − pa| (if
/// positive), shared as wa : wb. Returns the overlap that was removed.
double separate(Vec2& pa, Vec2& pb, const PairShape& pair, const BoxSettings& box, const WallSettings& walls);

/// Pushes pa and pb apart along n by `depth`, shared as wa : wb, stopping a
/// ball at a wall it was inside (its partner then takes the rest). A ball of
/// inverse mass 0 (pinned) is never moved.
void pushApart(Vec2& pa, Vec2& pb, const PairShape& pair, double depth, const BoxSettings& box,
               const WallSettings& walls);

/// pushApart with the common case inline: when both balls end inside every
/// enabled wall (`check`), they move by their shares and no wall is looked
/// at; otherwise pushApart. The same positions either way.
inline void pushApartWithin(Vec2& pa, Vec2& pb, const PairShape& pair, double depth, const WallCheck& check,
                            const BoxSettings& box, const WallSettings& walls)
{
    const double w = pair.wa + pair.wb;
    if (w == 0.0) // two pinned balls: neither moves
        return;
    const double shareA = (w > 0.0 && std::isfinite(w)) ? pair.wa / w : 0.5;
    const double moveA = depth * shareA;
    const Vec2 qa = pa - moveA * pair.n, qb = pb + (depth - moveA) * pair.n;
    if (check.inside(qa.x(), qa.y(), pair.ra) && check.inside(qb.x(), qb.y(), pair.rb)) {
        pa = qa;
        pb = qb;
    } else {
        pushApart(pa, pb, pair, depth, box, walls); // stops at the walls
    }
}

/// A ball whose centre was inside the walls at `before` and is outside them at
/// `after` is put back on the wall (position only). Returns whether it was.
bool keepInsideWalls(const Vec2& before, Vec2& after, double r, const BoxSettings& box, const WallSettings& walls);

inline Vec2 lineOfImpact(const Vec2& d, double s, int a, int b)
{
    const double len = d.norm();
    if (len > 1e-12 * s && std::isfinite(len))
        return d / len;
    return spreadDirection(a, b);
}

} // namespace forcelab::sim
