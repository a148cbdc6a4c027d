#pragma once
// The reference study behind `forcelab-cli sweep`: problems with closed-form
// answers (Kepler orbits, a fall through drag, a spring, a bouncing ball, two
// balls colliding), one run of a problem with an integrator and a time step
// measured against its answer, the fitted order of convergence, and the plan
// of runs a sweep makes. sim/studies/work_precision.h does the same for any scene
// against a reference run instead of a closed form.

#include "sim/world/scene.h"
#include "sim/world/world_settings.h"

#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace forcelab::sim {

class World;

/// A problem with a known answer: a scene for a time step, the exact
/// positions at any time and, when it has one, the exact energy.
struct ReferenceProblem {
    std::string name;                                 ///< e.g. "kepler-e0.5-10"
    std::string what;                                 ///< one line for the table
    double endTime = 1.0;                             ///< s, a multiple of every dt swept
    double length = 1.0;                              ///< px, the problem's size (for relative errors)
    std::function<Scene()> scene;                     ///< integrator and dt are set by the sweep
    std::function<Matrix2X(double t)> exact;          ///< px, exact positions of all balls at t
    std::function<double(const World&)> energyError;  ///< |E − E_exact| / |E_exact| now; null: none
};

/// Kepler's problem (sim/studies/kepler.h): a = 100 px, period 1 s, eccentricity e,
/// `orbits` whole orbits plus 5/16 of one.
ReferenceProblem keplerProblem(double e, int orbits);
/// A fall from rest through linear drag: x(t) closed form with the terminal speed g/k.
ReferenceProblem dragFallProblem();
/// A spring: x(t) = anchor + A cos ωt, with ω = √k.
ReferenceProblem springProblem();
/// A ball bouncing on the floor with e = 1: the parabola, folded at the floor.
ReferenceProblem bounceProblem();
/// Two balls in free flight that collide head on, elastic: positions before and after.
ReferenceProblem twoBallsProblem();
/// The problems a sweep runs (fewer long Kepler runs when `quick`).
std::vector<ReferenceProblem> referenceProblems(bool quick);

/// One run and its measurements.
struct SweepRun {
    std::string problem;                 ///< the problem's name
    IntegratorKind integrator = IntegratorKind::Euler;
    double dt = 0.0;                     ///< s
    double tolerance = 0.0;              ///< 1, adaptive methods only; 0 otherwise
    std::int64_t steps = 0;
    std::int64_t evaluations = 0;        ///< force evaluations
    double positionError = 0.0;          ///< px, largest over the balls; inf when the run blew up
    double energyError = std::nan("");   ///< 1, largest |ΔE/E| sampled at every step; NaN: no energy to check
    double wallMs = 0.0;                 ///< ms, median of the repeats, stepping only
    double nsPerStepBall = 0.0;          ///< ns per step and ball
    bool blewUp = false;
};

/// Runs `p` with `kind` at `dt` (and `tolerance` for the adaptive ones, 0:
/// the scene's), `repeats` times for the timing; nullopt when the settings
/// refuse the integrator (e.g. exact with a force that is not constant).
std::optional<SweepRun> runReference(const ReferenceProblem& p, IntegratorKind kind, double dt, double tolerance,
                                     int repeats);

/// The observed order of convergence of `kind` on `p`: the slope of log error
/// against log dt over the runs in the asymptotic range (1e-10 < error / size
/// < 1e-2), where error ≈ C dtᵖ holds. NaN with fewer than 3 such runs.
struct OrderFit {
    double order = std::nan("");
    int points = 0;
};
OrderFit fitOrder(const std::vector<SweepRun>& runs, const ReferenceProblem& p, IntegratorKind kind);

/// One run a sweep makes.
struct SweepJob {
    const ReferenceProblem* problem = nullptr;
    IntegratorKind kind = IntegratorKind::Euler;
    double dt = 0.0;        ///< s
    double tolerance = 0.0; ///< 1, 0 for the fixed-step methods
};

/// The runs of a sweep over `problems`: each fixed-step method at dt = 2^-k
/// over the range where its error goes from visible to rounding; the
/// adaptive ones at their default tolerance over a few steps and over a range
/// of tolerances at dt = 1/16 s.
std::vector<SweepJob> planSweep(const std::vector<ReferenceProblem>& problems, bool quick);

} // namespace forcelab::sim
