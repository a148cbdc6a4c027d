#pragma once
// forcelab-peer-box2d in two halves: peer_box2d.cpp runs ForceLab and prints
// the rows; peer_box2d_v2.cpp or peer_box2d_v3.cpp (whichever Box2D CMake
// found) runs the same scene in Box2D.

#include "sim/studies/peer_scene.h"

namespace forcelab::peer {

inline constexpr int kSteps = 600; ///< steps of 1/60 s: 10 s of the scene

/// Wall-clock milliseconds since an arbitrary start.
double nowMilliseconds();

/// One row of the table: engine, N, ms per step and the end-state measures.
void print(const char* engine, int n, double ms, const sim::PileMeasures& m);

/// "Box2D 2.4" or "Box2D 3", for the table's heading.
const char* box2dName();

/// Runs `scene` for kSteps in Box2D on one thread and prints its row(s).
void runBox2D(const sim::Scene& scene);

} // namespace forcelab::peer
