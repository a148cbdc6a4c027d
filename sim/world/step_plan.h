#pragma once
// A run of a given length made of steps: how many whole steps of dt, and the
// shorter last step when dt does not divide the length, so that a run asked
// for T seconds ends at T (not at the nearest multiple of dt, and not after
// zero steps when T is shorter than one step).

#include "sim/world/world.h"

#include <cstdint>
#include <optional>
#include <string>

namespace forcelab::sim {

struct StepPlan {
    std::int64_t whole = 0; ///< steps of the world's dt
    double last = 0.0;      ///< s, one more, shorter step (0: dt divides the length)
    std::int64_t steps() const { return whole + (last > 0.0 ? 1 : 0); }
};

/// The plan for `duration` seconds at steps of `dt`. A remainder within 1e-9
/// of a step of a whole number of steps counts as none (0.3 s at dt = 0.1 s
/// is three steps, not three and a step of 5.6e-17 s). nullopt, with the
/// reason in *why, when it cannot run: a duration that is negative or not
/// finite, or more than maxSteps steps (counted before any conversion to an
/// integer, so 1e300 s is refused, not wrapped round).
std::optional<StepPlan> planSteps(double duration, double dt, std::int64_t maxSteps, std::string* why);

/// Runs the plan: the whole steps, then the last with a copy of the settings
/// whose dt is `last`, then the world's own settings back. Stops early when
/// the world halts.
void runPlan(World& world, const StepPlan& plan);

} // namespace forcelab::sim
