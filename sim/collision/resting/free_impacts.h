#pragma once
// The pairs of free islands (contact_islands.h): balls that meet fast, or
// overlap while they separate, with no resting contact, wall, sleeper or
// pinned ball among them (under gravity alone, balls that meet at any
// speed, with no wall, sleeper or pinned ball). They do not need the
// resting solver's rows, stages and passes: each gets the exact impulse of
// two free balls, at the moment it meets within the sub-step.
//
// Per pair, in (a, b) order, with n the line of impact at the start of the
// sub-step and v_n = (v_b − v_a)·n:
//   - approaching (v_n < 0): the impulse j = −(1 + e)·v_n / (w_a + w_b)
//     along n, so the pair separates at e·|v_n|; it met at τ = gap/|v_n|
//     into the sub-step (0 when it overlapped at the start), so each ball
//     moves on by its change of velocity times h − τ. Gravity is the same
//     for both balls, so τ and the bounce are those of the exact motion.
//   - then, if the pair still overlaps (it began the sub-step overlapping),
//     positional correction pushes it apart, as the one-pass step does.

#include "sim/world/ball_state.h"
#include "sim/collision/resting/sub_step_context.h"

#include <vector>

namespace forcelab::sim {

// A pair of a free island: its balls, the line of impact and the gap at the
// start of the sub-step (px; below 0: it overlapped then).
struct FreePair {
    int a, b;
    double nx, ny, gapStart;
};

/// Gives every pair of `pairs` (in (a, b) order) its exact impulse and moves
/// its balls as the bounce would have in the rest of the sub-step; returns
/// whether any pair bounced.
bool resolveFreePairs(BallState& balls, const SubStepContext& c, const std::vector<FreePair>& pairs);

} // namespace forcelab::sim
