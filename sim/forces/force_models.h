#pragma once
// One record per force model: how to tell it is on, its acceleration of every
// ball, its potential energy if it has one, and what the stability check and
// the `exact` integrator need to know about it. ForceModel adds up the models
// that are on, in table order; the energy accounting, the stability check, the
// exact integrator's check and the Inspector's per-source breakdown walk the
// same table, so a new force is its settings, its row of parameters and one
// record here.

#include "sim/world/ball_state.h"
#include "sim/forces/wind.h"
#include "sim/world/world_settings.h"

#include <span>
#include <string_view>

namespace forcelab::sim {

struct StepInputs;

/// What a model's functions see: the settings, the balls (masses, homes), the
/// step's inputs (pointer, wind, random values) and the per-ball factors that
/// ForceModel works out once.
struct ForceContext {
    const WorldSettings& settings;
    const BallState& balls;
    const StepInputs& inputs;
    const VectorX& windScale;  ///< per-ball factor of the wind
    const VectorX& pointScale; ///< per-ball factor of the point force (empty: 1)
    const VectorX& dragScale;  ///< per-ball factor of the drag (empty: 1)
};

struct ForceModelInfo {
    std::string_view name; ///< as people call it: "gravity", "drag", "between balls"
    bool (*on)(const WorldSettings&);
    /// Adds the model's acceleration of every ball at (x, v, t) to a.
    void (*add)(const ForceContext&, const Matrix2X& x, const Matrix2X& v, double t, Matrix2X& a);
    /// Its potential energy at x; nullptr when it has none (its work is booked
    /// by the accounting instead).
    double (*potential)(const ForceContext&, const Matrix2X& x) = nullptr;
    /// Turns `s` into the settings of the model's conservative part: off when
    /// it has no potential (drag, wind), unclamped for the point force;
    /// nullptr when the whole model is conservative (or, like the magnetic
    /// field, does no work). The accounting books what the rest does.
    void (*conservativePart)(WorldSettings& s) = nullptr;
    /// Switches the model off.
    void (*switchOff)(WorldSettings& s);
    /// Why its acceleration changes during a step (what the `exact`
    /// integrator cannot follow), or nullptr when it does not.
    const char* (*notConstant)(const WorldSettings&) = nullptr;
    bool velocityDependent = false; ///< its acceleration depends on the velocity
    /// Adds its part to the stability test motion x'' = −ω² x − c x': ω² in
    /// 1/s², c in 1/s. `dragFactor` and `dragSpeed` (px/s) are those of the
    /// ball drag slows fastest: the largest per-ball factor for linear drag,
    /// the largest factor × speed for quadratic drag (0 speed: not known).
    void (*stiffness)(const WorldSettings&, double dragFactor, double dragSpeed, double& omega2,
                      double& damping) = nullptr;
    /// On a ball at rest it depends on where the ball is alone (not on time,
    /// an input or other balls), so a resting ball may sleep while it is on
    /// (contact_solver.h, point 7).
    bool steadyAtRest = false;
    /// It gives every ball the same acceleration, wherever it is and however
    /// it moves (uniform gravity), so it never pushes two balls together: a
    /// group of touching balls that only such forces act on falls as one, and
    /// none of its contacts rests (contact_solver.h, point 8).
    bool sameForEveryBall = false;
};

/// Every force model, in the order their accelerations are added.
std::span<const ForceModelInfo> forceModels();

} // namespace forcelab::sim
