// Positional correction and the walls it stops at (positional_correction.h).

#include "sim/collision/response/positional_correction.h"

#include <cmath>
#include <numbers>

namespace forcelab::sim {

Vec2 spreadDirection(int a, int b)
{
    // The R2 low-discrepancy sequence in (a, b): well spread angles, no randomness.
    const double u = static_cast<double>(a) * 0.7548776662466927 + static_cast<double>(b) * 0.5698402909980532;
    const double angle = 2.0 * std::numbers::pi * (u - std::floor(u));
    return {std::cos(angle), std::sin(angle)};
}

bool keepInsideWalls(const Vec2& before, Vec2& after, double r, const BoxSettings& box, const WallSettings& walls)
{
    const bool on[2][2] = {{walls.left, walls.right}, {walls.top, walls.bottom}};
    const double size[2] = {box.width, box.height};
    bool moved = false;
    for (int k = 0; k < 2; ++k) {
        double lo = r, hi = size[k] - r;
        if (lo > hi) // wider than the box: it can only sit in the middle
            lo = hi = 0.5 * size[k];
        if (on[k][0] && before[k] >= lo && after[k] < lo) {
            after[k] = lo;
            moved = true;
        }
        if (on[k][1] && before[k] <= hi && after[k] > hi) {
            after[k] = hi;
            moved = true;
        }
    }
    return moved;
}

double separate(Vec2& pa, Vec2& pb, const PairShape& pair, const BoxSettings& box, const WallSettings& walls)
{
    const double depth = (pair.ra + pair.rb) - (pb - pa).norm();
    if (!(depth > 0.0))
        return 0.0;
    pushApart(pa, pb, pair, depth, box, walls);
    return depth;
}

void pushApart(Vec2& pa, Vec2& pb, const PairShape& pair, double depth, const BoxSettings& box,
               const WallSettings& walls)
{
    const auto& [ra, rb, n, wa, wb] = pair;
    const double w = wa + wb;
    if (w == 0.0) // two pinned balls: neither moves
        return;
    const double shareA = (w > 0.0 && std::isfinite(w)) ? wa / w : 0.5;
    // Move a by its share and b by the rest. A ball stops at a wall it was
    // inside; then its partner takes what it could not, and if b is the one
    // stopped, a takes the rest. A pinned ball (inverse mass 0) takes nothing.
    const bool bMoves = wb != 0.0;
    const double moveA = depth * shareA;
    Vec2 qa = pa - moveA * n;
    const double movedA = keepInsideWalls(pa, qa, ra, box, walls) ? (pa - qa).dot(n) : moveA;
    Vec2 qb = bMoves ? Vec2(pb + (depth - movedA) * n) : pb;
    if (bMoves && keepInsideWalls(pb, qb, rb, box, walls)) {
        const double missing = depth - movedA - (qb - pb).dot(n);
        if (missing > 0.0 && wa != 0.0) {
            Vec2 qa2 = qa - missing * n;
            keepInsideWalls(qa, qa2, ra, box, walls);
            qa = qa2;
        }
    }
    pa = qa;
    pb = qb;
}

} // namespace forcelab::sim
