#pragma once
// The force model: the acceleration of every ball as a function of positions,
// velocities and time, composed of the models a scene enables. Multi-stage
// integrators call acceleration() at their stages; a disabled model is never
// called. Forces are written as accelerations (force / mass) because that is
// what the integrators need.

#include "sim/world/ball_state.h"
#include "sim/forces/wind.h"
#include "sim/world/world_settings.h"

#include <cstdint>
#include <vector>

namespace forcelab::sim {

/// Where the pointer is, for pointer wind and pointer attraction.
struct PointerInput {
    bool inside = false;     ///< false once the pointer leaves the canvas
    bool pressed = false;    ///< a pressed pointer repels, a hovering one attracts
    Vec2 position{0.0, 0.0}; ///< px, world coordinates
    friend bool operator==(const PointerInput&, const PointerInput&) = default;
};

/// Inputs that hold for a whole step: random values are drawn once per step
/// (so multi-stage integrators see the same wind at every stage).
struct StepInputs {
    PointerInput pointer;
    WindGenerator wind;        ///< the wind that acts (seeded from time.seed)
    WindGenerator compareWind; ///< a second wind mode, shown beside the first and acting on nothing
    Matrix2X randomAccel;      ///< px/s², per ball, for the random-acceleration model
};

class ForceModel {
public:
    ForceModel(const WorldSettings& settings, const BallState& balls, const StepInputs& inputs);

    /// a = Σ of the enabled models' accelerations at (x, v, t), 0 for a
    /// pinned ball. Counts one evaluation.
    void acceleration(const Matrix2X& x, const Matrix2X& v, double t, Matrix2X& a) const;

    /// Potential energy of the conservative models at positions x: uniform
    /// gravity, mutual gravity, spring, homing, and the point force (its
    /// unclamped inverse-square potential).
    double potential(const Matrix2X& x) const;

    /// True when no enabled model depends on velocity (drag).
    bool velocityIndependent() const { return m_velocityIndependent; }

    /// Adds one model's acceleration (it need not be on) with this model's
    /// scale factors and inputs: for per-source breakdowns. Not counted as an
    /// evaluation.
    void addOne(const struct ForceModelInfo& model, const Matrix2X& x, const Matrix2X& v, double t, Matrix2X& a) const;

    /// Horizontal wind on a reference ball at time t, px/s².
    double windAt(double t) const;

    std::int64_t evaluations() const { return m_evaluations; }

private:
    const WorldSettings& m_settings;
    const BallState& m_balls;
    const StepInputs& m_inputs;
    VectorX m_windScale;  // per-ball factor of the wind (none / radius / mass)
    VectorX m_pointScale; // per-ball factor of the point force
    VectorX m_dragScale;  // per-ball factor of the drag (empty: the same for every ball)
    std::vector<const struct ForceModelInfo*> m_active; // the models that are on, in table order
    std::vector<Eigen::Index> m_pinned; // pinned balls: no force accelerates them (empty in most scenes)
    bool m_velocityIndependent = true;
    mutable std::int64_t m_evaluations = 0;
};

/// nullptr when every enabled model gives an acceleration that does not change
/// during a step (what the `exact` integrator needs); otherwise why not.
const char* nonConstantAccelerationReason(const WorldSettings& settings);

/// Per-ball factor of a scaled model: 1, r_ref / r, or m_ref / m.
VectorX scaleFactors(ForceScale scale, const BallState& balls);

} // namespace forcelab::sim
