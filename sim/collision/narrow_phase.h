#pragma once
// The narrow phase: the exact test every broad phase ends with. One function
// decides whether two balls touch, so that all four detectors agree to the bit.
//
// Touching means strictly overlapping: |x_b − x_a| < r_a + r_b, tested as
//   dx² + dy² < (r_a + r_b)².
// Two balls whose edges meet exactly (distance == r_a + r_b) do not touch.
// The test is symmetric bit for bit: swapping a and b negates dx and dy, which
// is exact in floating point, and squares and sums do not see the sign.

#include "sim/collision/response/time_of_impact.h"

#include <cstddef>

namespace forcelab::sim {

inline bool circlesOverlap(double xa, double ya, double ra, double xb, double yb, double rb)
{
    const double dx = xb - xa;
    const double dy = yb - ya;
    const double s = ra + rb;
    return dx * dx + dy * dy < s * s;
}

/// The balls as arrays, in whatever order a broad phase keeps them (by ball
/// index, sorted by x, or copied per grid cell). x0, y0: start of the step,
/// used by the continuous test only. A ball that must not take part has
/// x = NaN, which makes every comparison false.
struct BallArrays {
    const double* x = nullptr;
    const double* y = nullptr;
    const double* r = nullptr;
    const double* x0 = nullptr;
    const double* y0 = nullptr;
};

/// Static test on the balls' current positions.
struct OverlapTest {
    static constexpr bool kSwept = false;
    BallArrays ball;
    bool operator()(std::size_t a, std::size_t b) const
    {
        return circlesOverlap(ball.x[a], ball.y[a], ball.r[a], ball.x[b], ball.y[b], ball.r[b]);
    }
};

/// Continuous test: the balls touch at the end of the step, or their straight
/// paths from (x0, y0) to (x, y) bring them into contact during it.
struct SweptTest {
    static constexpr bool kSwept = true;
    BallArrays ball;
    bool operator()(std::size_t a, std::size_t b) const
    {
        const BallArrays& p = ball;
        if (circlesOverlap(p.x[a], p.y[a], p.r[a], p.x[b], p.y[b], p.r[b]))
            return true;
        const double d0x = p.x0[b] - p.x0[a];
        const double d0y = p.y0[b] - p.y0[a];
        const double ddx = (p.x[b] - p.x0[b]) - (p.x[a] - p.x0[a]);
        const double ddy = (p.y[b] - p.y0[b]) - (p.y[a] - p.y0[a]);
        return timeOfImpact(d0x, d0y, ddx, ddy, p.r[a] + p.r[b]) >= 0.0;
    }
};

} // namespace forcelab::sim
