#pragma once
// What every broad phase reads: the balls as separate arrays (x, y, r: a loop
// over one of them walks memory in order) and an axis-aligned box around each
// ball. The boxes are padded by a hair (about 1e-12 of the largest coordinate)
// so that rounding can never make a broad phase drop a pair that the narrow
// phase would accept: the broad phase may only err on the generous side.
//
// A ball takes part only if its position and radius are finite and r >= 0.
// Others get x = NaN (the narrow phase then rejects every pair with them) and
// are left out of `active`.

#include "sim/world/ball_state.h"

#include <vector>

namespace forcelab::sim {

struct BroadPhaseInput {
    // Balls, structure of arrays. x0, y0: start of the step (continuous mode only).
    std::vector<double> x, y, r, x0, y0;
    // Padded bounding box of each ball (of its whole path in continuous mode).
    std::vector<double> loX, hiX, loY, hiY;
    std::vector<int> active; ///< indices of the balls that take part, ascending
    double maxWidth = 0.0;   ///< px, widest box among active balls
    double maxHeight = 0.0;  ///< px, tallest box among active balls
    double meanSize = 0.0;   ///< px, mean of max(width, height) over active balls
    double pad = 0.0;        ///< px, the padding added on every side

    int size() const { return static_cast<int>(x.size()); }

    /// Boxes around the circles at their current positions. With `grow` (one
    /// value >= 0 per ball), ball i takes part with radius r_i + grow[i]: the
    /// pairs found are then every pair within grow[a] + grow[b] of touching.
    void loadStatic(const BallState& balls, const double* grow = nullptr);
    /// Boxes around the path of each circle from `start` to its current position.
    /// With `grow` (one value >= 0 per ball), ball i takes part with radius
    /// r_i + grow[i]: a ball whose path bends away from the straight line by
    /// up to grow[i] is still found (continuous detection, impact_events.h).
    void loadSwept(const BallState& balls, const Matrix2X& start, const double* grow = nullptr);

private:
    void copyBalls(const BallState& balls);
    void finishBounds();
};

} // namespace forcelab::sim
