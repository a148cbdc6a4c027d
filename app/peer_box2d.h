#pragma once
// forcelab-peer-box2d in two halves: peer_box2d.cpp runs ForceLab and prints
// the rows; peer_box2d_v2.cpp or peer_box2d_v3.cpp (whichever Box2D CMake
// found) runs the same scene in Box2D.

#include "sim/studies/peer_scene.h"

namespace forcelab::peer {

inline constexpr int kSteps = 600; ///< steps of 1/60 s: 10 s of the scene

/// Wall-clock milliseconds since an arbitrary start.
double nowMilliseconds();

/// Milliseconds per step over all kSteps and over the last kSteps / 2 (a
/// pile at rest: what sleeping saves).
struct StepTimes {
    double all = 0.0;
    double lastHalf = 0.0;
};

/// Runs `step` kSteps times and times it.
template <typename Step>
StepTimes timeSteps(Step&& step)
{
    const double t0 = nowMilliseconds();
    double half = t0;
    for (int s = 0; s < kSteps; ++s) {
        if (s == kSteps / 2)
            half = nowMilliseconds();
        step();
    }
    const double t1 = nowMilliseconds();
    return StepTimes{(t1 - t0) / kSteps, (t1 - half) / (kSteps - kSteps / 2)};
}

/// One row of the table: engine, N, ms per step and the end-state measures.
void print(const char* engine, int n, const StepTimes& ms, const sim::PileMeasures& m);

/// "Box2D 2.4" or "Box2D 3", for the table's heading.
const char* box2dName();

/// Runs `scene` for kSteps in Box2D on one thread and prints its row(s).
void runBox2D(const sim::Scene& scene);

} // namespace forcelab::peer
