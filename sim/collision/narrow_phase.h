#pragma once
// The narrow phase: the exact test every broad phase ends with. One function
// decides whether two balls touch, so that all four detectors agree to the bit.
//
// Touching means strictly overlapping: |x_b − x_a| < r_a + r_b, tested as
//   dx² + dy² < (r_a + r_b)².
// Two balls whose edges meet exactly (distance == r_a + r_b) do not touch.
// The test is symmetric bit for bit: swapping a and b negates dx and dy, which
// is exact in floating point, and squares and sums do not see the sign.

#include "time_of_impact.h"

namespace forcelab::sim {

inline bool circlesOverlap(double xa, double ya, double ra, double xb, double yb, double rb)
{
    const double dx = xb - xa;
    const double dy = yb - ya;
    const double s = ra + rb;
    return dx * dx + dy * dy < s * s;
}

/// Static test on the balls' current positions (structure of arrays). A ball
/// that must not take part has x = NaN, which makes every comparison false.
struct OverlapTest {
    const double* x;
    const double* y;
    const double* r;
    bool operator()(int a, int b) const { return circlesOverlap(x[a], y[a], r[a], x[b], y[b], r[b]); }
};

/// Continuous test: the balls touch at the end of the step, or their straight
/// paths from (x0, y0) to (x, y) bring them into contact during it.
struct SweptTest {
    const double* x0;
    const double* y0;
    const double* x;
    const double* y;
    const double* r;
    bool operator()(int a, int b) const
    {
        if (circlesOverlap(x[a], y[a], r[a], x[b], y[b], r[b]))
            return true;
        const double d0x = x0[b] - x0[a];
        const double d0y = y0[b] - y0[a];
        const double ddx = (x[b] - x0[b]) - (x[a] - x0[a]);
        const double ddy = (y[b] - y0[b]) - (y[a] - y0[a]);
        return timeOfImpact(d0x, d0y, ddx, ddy, r[a] + r[b]) >= 0.0;
    }
};

} // namespace forcelab::sim
