#pragma once
// Time integrators for x'' = a(x, v, t). Each advances positions and
// velocities of all balls by h, calling the force model at its stages.
//
//   euler               explicit: x += v h, v += a(x) h             1st order, 1 evaluation
//   semi-implicit-euler v += a(x) h, then x += v h (new v)           1st order, symplectic, 1 evaluation
//   verlet              velocity Verlet (kick–drift–kick)             2nd order, symplectic, 1 evaluation*
//   rk4                 classical Runge–Kutta                         4th order, 4 evaluations
//   yoshida4            three Verlet steps of weights w1, w0, w1      4th order, symplectic, 3 evaluations*
//   rk45                adaptive Dormand–Prince 5(4) over the step    5th order, 6 per accepted step
//   exact               x += v h + ½ a h², v += a h                   exact for constant a, 1 evaluation
//   ias15               adaptive Gauss–Radau predictor–corrector     15th order, 1 + 7 per pass (ias15.h)
//
// * Verlet-type methods end a step with the acceleration at the new position,
//   which is the first acceleration of the next step. The integrator keeps it
//   until invalidate() is called: the world calls it whenever something else
//   changes the state or the forces (a bounce, a collision, new settings).

#include "sim/forces/force_model.h"
#include "sim/integrators/ias15.h"
#include "sim/world/world_settings.h"

#include <cstdint>

namespace forcelab::sim {

/// Most sub-steps (accepted and rejected) an adaptive integrator may take for
/// one world step. A close pass without softening can ask for sub-steps a
/// trillion times shorter than dt; past this budget the integrator gives up
/// instead of freezing the program, and the world stops with an explanation.
inline constexpr std::int64_t kMaxAdaptiveSubSteps = 100'000;

/// The shortest sub-step an adaptive integrator may take, as a share of the
/// step. A sub-step that still misses the tolerance at this length is not
/// taken (its result would be as wrong as the error estimate says): the
/// integrator gives up and the world stops with the cause.
inline constexpr double kMinSubStepShare = 1e-12;

struct IntegratorStats {
    std::int64_t accepted = 0; ///< rk45 / ias15 sub-steps accepted
    std::int64_t rejected = 0; ///< rk45 / ias15 sub-steps rejected (error above tolerance)
    bool gaveUp = false;       ///< stopped before the end of the step (why: below)
    /// The error could not be brought within the tolerance even by the
    /// shortest sub-step allowed, kMinSubStepShare of the step: the motion
    /// changes faster than any sub-step can follow (a singular approach).
    /// False when gaveUp means the sub-step budget ran out.
    bool tooShort = false;
    double shortestSubStep = 0.0; ///< s, the sub-step it could not go below (when tooShort)
    /// ias15: the rounding floor it held the error to where the tolerance asked
    /// for less than rounding allows (1, like the tolerance; 0: the tolerance held)
    double toleranceFloor = 0.0;
    std::int64_t roundingChecks = 0; ///< ias15: force evaluations spent measuring the rounding floor
};

class Integrator {
public:
    /// Advances x and v from time t to t + h.
    void advance(IntegratorKind kind, const ForceModel& forces, Matrix2X& x, Matrix2X& v, double t, double h,
                 double tolerance, IntegratorStats& stats);

    /// Forgets the kept acceleration and rk45's step-size guess.
    void invalidate();

private:
    void kickDriftKick(const ForceModel& forces, Matrix2X& x, Matrix2X& v, double t, double h);
    void dormandPrince(const ForceModel& forces, Matrix2X& x, Matrix2X& v, double t, double h, double tolerance,
                       IntegratorStats& stats);
    const Matrix2X& startAcceleration(const ForceModel& forces, const Matrix2X& x, const Matrix2X& v, double t);

    Matrix2X m_a;           // acceleration at the current state (kept between Verlet-type steps)
    bool m_aValid = false;
    double m_rk45h = 0.0;   // rk45's last good sub-step, s (0: choose afresh)
    Ias15 m_ias15;          // the reference integrator and its state between steps
    // Scratch for multi-stage methods, reused between steps to avoid allocation.
    Matrix2X m_kx[7], m_kv[7], m_xs, m_vs, m_xn, m_vn;
};

} // namespace forcelab::sim
