#pragma once
// Where the time of the collision stage goes, stage by stage (forcelab-cli
// bench --profile). Off by default: then no clock is read at all.

#include <cstdint>
#include <ctime>

namespace forcelab::sim {

/// Seconds spent in each stage, summed over every step() and detect() call
/// since the last reset.
struct CollisionProfile {
    double load = 0.0;        ///< s, copying the balls into the broad phase's arrays, boxes, finiteness
    double broadSort = 0.0;   ///< s, sweep: keys and re-sort; grid: placing the balls in cells
    double pairs = 0.0;       ///< s, finding the pairs (sweep, cells or all pairs) with the narrow phase
    double contactSort = 0.0; ///< s, putting the pairs in (a, b) order
    double build = 0.0;       ///< s, solver: contact rows (normal, effective mass, warm start) and flags
    double wallScan = 0.0;    ///< s, solver: finding the balls on or near a wall
    double velocity = 0.0;    ///< s, solver: warm start and the velocity passes
    double restitution = 0.0; ///< s, solver: the bounce pass and the last wall pass
    double position = 0.0;    ///< s, solver: moving the balls as if the impulses acted at the start
    double correction = 0.0;  ///< s, positional correction (and the one-pass response without gravity)
    double sleep = 0.0;       ///< s, sleeping: holding the sleepers, waking them near a pair, putting still balls to sleep
    std::int64_t calls = 0;   ///< step() calls
    std::int64_t passes = 0;  ///< velocity passes made, summed
    std::int64_t rows = 0;    ///< ball–ball rows of the solver (touching and speculative), summed
    std::int64_t solves = 0;  ///< ball–ball row updates in the velocity passes, summed

    double total() const
    {
        return load + broadSort + pairs + contactSort + build + wallScan + velocity + restitution + position +
               correction + sleep;
    }
};

/// Adds the processor time since the previous lap to a stage, when switched
/// on. Processor time (std::clock, 1 µs steps), not wall-clock time: on a
/// shared machine the wall clock also counts the time spent waiting for a core.
class StageClock {
public:
    explicit StageClock(bool on) : m_on(on)
    {
        if (m_on)
            m_last = std::clock();
    }
    bool on() const { return m_on; }
    void lap(double& stage)
    {
        if (!m_on)
            return;
        const std::clock_t now = std::clock();
        stage += static_cast<double>(now - m_last) / CLOCKS_PER_SEC;
        m_last = now;
    }

private:
    bool m_on;
    std::clock_t m_last = 0;
};

} // namespace forcelab::sim
