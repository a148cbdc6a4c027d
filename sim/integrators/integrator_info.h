#pragma once
// One row per integrator: everything the rest of the program needs to know
// about a method, in one place. The names, the stability check, the exact
// wall model, the accuracy tools and the docs read this table instead of
// listing integrators, so a new method is its `advance` code plus one row.

#include "sim/world/world_settings.h"

#include <span>
#include <string_view>

namespace forcelab::sim {

/// How a ball moves inside one step, as the integrator really moves it (the
/// exact wall model finds the moment of impact on this path).
enum class StepPath {
    DriftKick, ///< a straight drift at the start's velocity, then one velocity kick (explicit Euler)
    KickDrift, ///< one velocity kick, then a straight drift at the new velocity (semi-implicit Euler)
    Parabola,  ///< x₀ + v₀ t + ½ a t² with a = (v₁ − v₀)/h: exact under a constant force
};

struct IntegratorInfo {
    IntegratorKind kind;
    std::string_view name;       ///< as in lesson files, on the command line and in menus
    double order;                ///< global order of the position error in dt (0: exact for what it allows)
    bool symplectic;             ///< keeps a nearby energy for ever on conservative forces
    bool adaptive;               ///< chooses its own sub-steps to meet time.tolerance
    int evaluationsPerStep;      ///< force evaluations per step (adaptive: per sub-step try, at least)
    StepPath path;               ///< its path inside a step
    /// ω h beyond which an undamped spring grows (0: any h, explicit Euler;
    /// infinity: adaptive or exact, no fixed limit). Checked against
    /// sim/integrators/stability.h by test_stability.
    double springLimit;
    std::string_view summary;    ///< one line for people
};

/// Every integrator, in the order of IntegratorKind.
std::span<const IntegratorInfo> integrators();
const IntegratorInfo& integratorInfo(IntegratorKind kind);

} // namespace forcelab::sim
