#pragma once
// Will this integrator at this time step stay stable? For the models whose
// stiffness does not depend on the state (spring, homing, linear drag) the
// answer is exact: one step of the integrator on x'' = −ω² x − c x' is a 2×2
// matrix, and the motion grows when its largest eigenvalue exceeds 1. The
// check runs the real integrator on that test problem, so it cannot disagree
// with what the world does. Quadratic drag a = −c |v| v is stiff in
// proportion to the speed: linearised along v its rate is 2 c |v|, so it is
// checked at the balls' actual speeds (stabilityProblem with the balls),
// before every step.

#include "sim/world/ball_state.h"
#include "sim/world/world_settings.h"

#include <optional>
#include <string>

namespace forcelab::sim {

/// How much the test motion (spring + homing + linear drag) grows per step:
/// the spectral radius of one step. 1 or less is stable. `dragFactor` is the
/// largest per-ball factor of the drag (m_ref / m of the lightest ball when
/// drag is a force; 1 for the tutorial's drag).
double linearGrowthPerStep(const WorldSettings& settings, double h, double dragFactor = 1.0);

/// A plain-words explanation with the fix when the settings make the
/// integrator blow up within 10 s of simulated time (the motion doubling in
/// less than that, or growing without end), or nullopt. Drag alone is
/// refused at any growth at all: real drag never speeds a ball up. The safe
/// dt it names is rounded down, so it is really safe; with per-frame steps,
/// which ignore dt, it names the number of sub-steps instead. Quadratic drag
/// is not seen here (it needs the speeds): use the overload with the balls.
std::optional<std::string> stabilityProblem(const WorldSettings& settings, double dragFactor = 1.0);

/// The same check for these balls: linear drag at the factor of the ball it
/// slows fastest, quadratic drag at the ball with the largest c |v| (its
/// linearised rate 2 c |v|, 1/s). The world calls it on reset, on new
/// settings and before every step while quadratic drag is on, since the
/// speeds change.
std::optional<std::string> stabilityProblem(const WorldSettings& settings, const BallState& balls);

} // namespace forcelab::sim
