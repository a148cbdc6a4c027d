#include "sim/integrators/integrator_info.h"

#include <array>
#include <limits>

namespace forcelab::sim {
namespace {

constexpr double kNone = std::numeric_limits<double>::infinity();

// Yoshida's fourth-order method is three Verlet steps of w₁ h, w₀ h, w₁ h with
// w₁ = 1 / (2 − 2^(1/3)) = 1.3512 and w₀ = 1 − 2 w₁; its spring limit is where
// the product of the three Verlet matrices leaves the unit circle.
constexpr std::array<IntegratorInfo, 8> kIntegrators{{
    {IntegratorKind::Euler, "euler", 1.0, false, false, 1, StepPath::DriftKick, 0.0,
     "explicit Euler: move with the old velocity, then change the velocity; gains energy on every orbit"},
    {IntegratorKind::SemiImplicitEuler, "semi-implicit-euler", 1.0, true, false, 1, StepPath::KickDrift, 2.0,
     "semi-implicit Euler: change the velocity first, then move with the new one"},
    {IntegratorKind::Verlet, "verlet", 2.0, true, false, 1, StepPath::Parabola, 2.0,
     "velocity Verlet: half a kick, a drift, half a kick"},
    {IntegratorKind::Rk4, "rk4", 4.0, false, false, 4, StepPath::Parabola, 2.0 * 1.4142135623730951,
     "classical Runge-Kutta: four slopes averaged"},
    {IntegratorKind::Yoshida4, "yoshida4", 4.0, true, false, 3, StepPath::Parabola, 1.5734,
     "Yoshida: three Verlet steps of weights 1.35, -1.70, 1.35"},
    {IntegratorKind::Rk45, "rk45", 5.0, false, true, 6, StepPath::Parabola, kNone,
     "Dormand-Prince 5(4): adaptive sub-steps to a tolerance"},
    {IntegratorKind::Exact, "exact", 0.0, true, false, 1, StepPath::Parabola, kNone,
     "the closed-form parabola, for scenes whose only forces are constant"},
    {IntegratorKind::Ias15, "ias15", 15.0, false, true, 8, StepPath::Parabola, kNone,
     "the reference: 15th-order Gauss-Radau with adaptive sub-steps"},
}};

constexpr bool inKindOrder()
{
    for (std::size_t i = 0; i < kIntegrators.size(); ++i)
        if (static_cast<std::size_t>(kIntegrators[i].kind) != i)
            return false;
    return true;
}
static_assert(inKindOrder(), "rows must follow IntegratorKind");

} // namespace

std::span<const IntegratorInfo> integrators() { return kIntegrators; }

const IntegratorInfo& integratorInfo(IntegratorKind kind) { return kIntegrators.at(static_cast<std::size_t>(kind)); }

} // namespace forcelab::sim
