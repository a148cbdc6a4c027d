#pragma once
// A work-precision study of one scene: each integrator runs the scene for the
// same simulated time at several time steps; each run's error is measured
// against a reference run (the ias15 integrator at the smallest step with a
// tight tolerance) and its cost is counted. The workbench's "Measure the
// trade-off" and convergence button use it; so do the CLI's fitted orders.

#include "sim/world/scene.h"
#include "sim/world/world_settings.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace forcelab::sim {

class World;

/// One run of the scene with one integrator and one time step.
struct PrecisionRun {
    IntegratorKind integrator = IntegratorKind::Euler;
    double dt = 0.0;                   ///< s
    double tolerance = 0.0;            ///< 1, the adaptive methods' tolerance used
    std::int64_t steps = 0;            ///< world steps taken
    double positionError = 0.0;        ///< px, largest distance between a ball and its reference at the end; inf: blew up
    double energyError = 0.0;          ///< 1, |E − E_ref| / |E_ref| at the end; inf: blew up
    std::int64_t forceEvaluations = 0; ///< calls of the force model (each evaluates all balls)
    double wallSeconds = 0.0;          ///< s, wall-clock time of the steps
    bool blewUp = false;               ///< the world halted itself before the end
    std::string refused;               ///< non-empty: the scene's settings refuse this integrator (why); not run
};

struct WorkPrecisionSettings {
    double duration = 1.0;                  ///< s of simulated time; a whole number of every dt
    std::vector<IntegratorKind> integrators;
    std::vector<double> dts;                ///< s, every integrator runs at each
    int threads = 1;                        ///< runs at once after the reference (each run is one thread's work)
    double referenceTolerance = 1e-11;      ///< 1, ias15's tolerance for the reference run (much tighter runs into rounding)
};

struct WorkPrecisionResult {
    PrecisionRun reference;          ///< ias15 at the smallest dt (its errors are 0 by definition)
    std::vector<PrecisionRun> runs;  ///< integrator-major, in the order of the settings
    bool cancelled = false;          ///< stopped early by the cancel flag: runs holds what finished
    std::optional<std::string> error; ///< the scene or the settings were refused; nothing ran
};

/// Called after each finished run with (runs done, runs in all) — the
/// reference counts as one. May be called from a worker thread (one call at a
/// time).
using ProgressCallback = std::function<void(int done, int total)>;

/// Runs the study. `cancel` (may be null) is polled every step; when it turns
/// true the study stops and returns what finished, with cancelled set.
WorkPrecisionResult measureWorkPrecision(const Scene& scene, const WorkPrecisionSettings& settings,
                                         const ProgressCallback& progress = {},
                                         const std::atomic<bool>* cancel = nullptr);

/// Largest distance between corresponding balls of two worlds, px (the
/// worlds must hold the same number of balls; otherwise inf).
double largestSeparation(const World& a, const World& b);

/// Least-squares slope of log(error) against log(dt): the observed order of
/// convergence, error ≈ C dtᵖ. Points with an error that is not positive and
/// finite are left out; NaN with fewer than two points left.
double fittedOrder(std::span<const double> dts, std::span<const double> errors);

/// The order theory gives a fixed-step method (euler 1, semi-implicit-euler 1,
/// verlet 2, rk4 4, yoshida4 4); NaN for the adaptive ones and exact.
double theoreticalOrder(IntegratorKind integrator);

/// A convergence check: one integrator at dt, dt/2, dt/4, dt/8 against the
/// reference, and the fitted order of the position errors.
struct ConvergenceResult {
    WorkPrecisionResult study;
    double order = 0.0; ///< NaN when fewer than two runs had a usable error
};
ConvergenceResult measureConvergence(const Scene& scene, IntegratorKind integrator, double dt, double duration,
                                     const ProgressCallback& progress = {},
                                     const std::atomic<bool>* cancel = nullptr);

} // namespace forcelab::sim
