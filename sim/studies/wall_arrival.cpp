#include "sim/studies/wall_arrival.h"

#include <cmath>

namespace forcelab::sim {

namespace {

// The first t > 0 with p + u t + ½ b t² = target, the coordinate crossing
// the target from the side it is on. +inf when it never does.
double firstCrossing(double p, double u, double b, double target)
{
    constexpr double kNow = 1e-12; // s: a ball on the line now is not "arriving"
    const double c = p - target;
    double best = INFINITY;
    auto consider = [&](double t) {
        if (t > kNow && t < best)
            best = t;
    };
    if (std::abs(b) < 1e-300) {
        if (u != 0.0)
            consider(-c / u);
        return best;
    }
    const double disc = u * u - 2.0 * b * c;
    if (disc < 0.0)
        return best;
    // The two roots of ½b t² + u t + c = 0 without cancellation:
    // q = −½(u + sign(u)√disc), t = q/(½b) and c/q.
    const double s = std::sqrt(disc);
    const double q = -0.5 * (u + std::copysign(s, u));
    consider(q / (0.5 * b));
    if (q != 0.0)
        consider(c / q);
    return best;
}

} // namespace

std::optional<WallArrival> nextWallArrival(const BoxSettings& box, const WallSettings& walls, const Vec2& x,
                                           const Vec2& v, const Vec2& a, double radius)
{
    const double r = walls.centreOnly ? 0.0 : radius;
    std::optional<WallArrival> best;
    auto consider = [&](bool on, int axis, double target, WallSide side) {
        if (!on)
            return;
        const double t = firstCrossing(x[axis], v[axis], a[axis], target);
        if (std::isfinite(t) && (!best || t < best->seconds))
            best = WallArrival{t, side};
    };
    consider(walls.left, 0, r, WallSide::Left);
    consider(walls.right, 0, box.width - r, WallSide::Right);
    consider(walls.top, 1, r, WallSide::Top);
    consider(walls.bottom, 1, box.height - r, WallSide::Bottom);
    if (walls.middle) {
        const double half = 0.5 * box.width;
        consider(true, 0, x.x() < half ? half - r : half + r, WallSide::Middle);
    }
    return best;
}

} // namespace forcelab::sim
