#pragma once
// The peer scene of the collision benchmark and the pile tests: N balls on a
// jittered grid filling 30% of a square box, gravity 980 px/s², restitution e
// for balls and walls, 60 Hz, and the measures that say whether the pile it
// makes has come to rest: the deepest and the mean overlap, the rms speed and
// the mean height. Other engines run the same initial state (peerBalls) and
// are measured the same way (measurePile on plain arrays).

#include "sim/world/world.h"

#include <cstdint>
#include <vector>

namespace forcelab::sim {

/// N balls, radii uniform in [rMin, rMax], on a jittered grid filling 30% of
/// a square box, random velocities up to `speed`, gravity on, 2d-impulse with
/// restitution e for balls and walls, semi-implicit Euler, one sub-step of 1/60 s.
Scene boxScene(int n, double rMin, double rMax, double speed, double e, Detection detection, std::uint64_t seed);

/// The peer scene: equal balls (r = 5 px) at rest, e = 0.9, grid detection.
Scene peerScene(int n);

/// How close a ball must come to another ball or the floor to count as part
/// of the pile, as a share of the smaller radius.
inline constexpr double kTouching = 0.1;

/// How still and how sound a pile is at one moment.
struct PileMeasures {
    double deepestOverlap = 0.0; ///< r, the deepest overlap of a pair over the smaller radius
    double meanOverlap = 0.0;    ///< r, the mean overlap over the pairs that overlap
    double rmsSpeed = 0.0;       ///< px/s, √(mean |v|²)
    /// px/s, the same over the balls in the pile: those within kTouching of
    /// another ball or of the floor (a ball in flight above it is left out)
    double pileRmsSpeed = 0.0;
    int inFlight = 0;            ///< 1, balls that touch no other ball and not the floor
    double meanHeight = 0.0;     ///< px, the mean height of the centres above the floor
    int overlapping = 0;         ///< 1, pairs that overlap
};

/// Measures balls given as centre x, y, speed components and radii (any
/// engine's state) in a box `height` px tall, y down; the pairs are found on
/// a uniform grid, so it is quick at any N.
PileMeasures measurePile(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& vx,
                         const std::vector<double>& vy, const std::vector<double>& r, double height);

/// The same for a world.
PileMeasures measurePile(const World& world);

} // namespace forcelab::sim
