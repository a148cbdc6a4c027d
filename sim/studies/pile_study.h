#pragma once
// The peer scene's pile followed in time: N equal balls (r = 5 px) fall into a
// square box and settle, and every `every` seconds the pile's measures are
// taken (peer_scene.h) together with the fastest ball, how many balls move
// faster than 5 px/s, the wall-clock time per step, how many steps had a
// bounce since the row before and how many balls sleep. The solver's settings
// and the sub-steps can be changed,
// so the trade between overlap and jitter can be measured one knob at a time
// (`forcelab-cli pile`, docs/performance.md).

#include "sim/collision/resting/contact_solver.h"
#include "sim/studies/peer_scene.h"

#include <ostream>
#include <vector>

namespace forcelab::sim {

struct PileStudyOptions {
    int balls = 5000;             ///< 1, balls in the peer scene
    int substeps = 1;             ///< 1, sub-steps per 1/60 s step
    double seconds = 10.0;        ///< s, simulated time
    double every = 0.5;           ///< s, between two rows
    double restitution = 0.9;     ///< 1, e of balls and walls
    int threads = 0;              ///< 1, most threads for the solver's passes (0: every core; the bits are the same)
    ContactSolverSettings solver; ///< the resting solver's settings
};

/// The pile at one moment.
struct PileStudyRow {
    double time = 0.0;     ///< s
    PileMeasures measures; ///< overlaps (r), rms speed (px/s), mean height (px)
    double maxSpeed = 0.0; ///< px/s, the fastest ball
    int movingBalls = 0;   ///< 1, balls faster than 5 px/s
    double msPerStep = 0.0; ///< ms, wall-clock time per step since the row before
    int bounceSteps = 0;   ///< 1, steps since the row before in which a pair or a wall bounced
    int asleep = 0;        ///< 1, balls asleep now (contact_solver.h, point 7)
};

/// Runs the study; with `out`, prints each row as it is taken.
std::vector<PileStudyRow> runPileStudy(const PileStudyOptions& options, std::ostream* out);

} // namespace forcelab::sim
