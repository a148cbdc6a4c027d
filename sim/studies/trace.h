#pragma once
// A trace of a run, step by step and ball by ball: what `forcelab-cli trace`
// writes so that a program written anywhere (the students' JavaScript) can be
// checked against the reference (trace_compare.h). Pure C++: the workbench
// may use it too.

#include "sim/world/world.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace forcelab::sim {

/// One ball at the end of one step (step 0: the start, before any step).
struct TraceRow {
    std::int64_t step = 0;
    double t = 0.0;   ///< s, the world's time
    int ball = 0;     ///< index in the world's balls
    double x = 0.0, y = 0.0;   ///< px
    double vx = 0.0, vy = 0.0; ///< px/s
    double ax = 0.0, ay = 0.0; ///< px/s², acceleration in the state at the end of the step, with the step's inputs
    std::int64_t pairTests = 0; ///< the step's narrow-phase distance tests (all balls; 0 at step 0)
    std::int64_t contacts = 0;  ///< the step's ball–ball contacts (all balls)
    double wind = 0.0;          ///< px/s², the step's wind on a reference ball
    double randomX = 0.0, randomY = 0.0; ///< px/s², the step's random acceleration of this ball (0 when off)
};

/// The column names of a trace, in the order the CSV writes them.
const std::vector<std::string>& traceColumns();

/// The rows of `world` as it is now, one per ball.
std::vector<TraceRow> traceRows(const World& world);

/// Runs `world` for `steps` steps, calling `sink` with the rows of step 0 and
/// every `every`-th step after it (and the last). Stops early when the world
/// halts; returns the halt reason then.
template <typename Sink>
std::optional<std::string> traceRun(World& world, std::int64_t steps, std::int64_t every, Sink&& sink);

/// The largest number of steps and rows a trace or a compared file may have.
inline constexpr std::int64_t kMaxTraceSteps = 1'000'000;
inline constexpr std::int64_t kMaxTraceRows = 2'000'000;

template <typename Sink>
std::optional<std::string> traceRun(World& world, std::int64_t steps, std::int64_t every, Sink&& sink)
{
    sink(traceRows(world));
    for (std::int64_t k = 1; k <= steps; ++k) {
        world.step();
        if (world.halted())
            return world.halted();
        if (k % every == 0 || k == steps)
            sink(traceRows(world));
    }
    return std::nullopt;
}

} // namespace forcelab::sim
