#pragma once
// ias15: a 15th-order implicit Runge–Kutta method on Gauss–Radau spacings with
// adaptive sub-steps, after Everhart (1985) and Rein & Spiegel (2015). It is
// the reference integrator: at its default tolerance its error per sub-step is
// below the rounding of a double, so what remains is rounding alone.
//
// Inside a sub-step of length Δt the acceleration is written as a polynomial
// in s = (t − t₀)/Δt ∈ [0, 1]:
//
//     a(s) = a₀ + b₀ s + b₁ s² + … + b₆ s⁷
//
// Integrating it twice gives the velocity and the position at any s. The b's
// are found by a predictor–corrector loop: evaluate the force at the seven
// Gauss–Radau nodes s = h₁…h₇ (with h₀ = 0 these eight nodes integrate
// polynomials up to degree 14 exactly, hence order 15), turn the values into
// Newton divided differences g₁…g₇, convert to b's, and repeat until the b's
// stop changing. A good first guess (the previous sub-step's polynomial moved
// forward in time) makes two passes enough in smooth motion.
//
// The size of the last term, |b₆| / |a|, estimates the sub-step's error; the
// next sub-step is Δt (ε / error)^(1/7), where ε is time.tolerance. Rounding
// sets a floor under that estimate: b₆ is a seventh divided difference of
// force values, so it magnifies their rounding about 4550 times, and far from
// the origin the force values carry the rounding of large coordinates. A
// tolerance below the floor cannot be met by any sub-step, however short, so
// where the estimate is above ε the floor is measured (one extra force
// evaluation) and, if it is higher, it stands in for ε; the world reports it.
// A floor above 1e-4 is no rounding to work to but the sign of a nearly
// singular force (a ball a few million ulps from an attracting point): it does
// not stand in. A sub-step whose predictor–corrector does not converge (a
// stiff force, a sub-step too long) is refused like one with a large error.
// One that misses the tolerance even at the shortest length allowed
// (kMinSubStepShare of the step) is not taken at all: ias15 gives up
// (IntegratorStats::tooShort) and the world stops, naming the cause. Positions
// and velocities are summed with compensated (Kahan) summation, so rounding
// does not build up over millions of sub-steps.

#include "sim/forces/force_model.h"
#include "sim/world/types.h"

#include <cstdint>

namespace forcelab::sim {

struct IntegratorStats;

class Ias15 {
public:
    /// Advances x and v from t to t + h in adaptive sub-steps; the last one
    /// is shortened to end exactly at t + h.
    void advance(const ForceModel& forces, Matrix2X& x, Matrix2X& v, double t, double h, double epsilon,
                 IntegratorStats& stats);

    /// Forgets the predicted polynomial, the step-size guess and the rounding
    /// carried by the compensated sums (the state was changed from outside).
    void reset();

    static constexpr int kNodes = 7; ///< Gauss–Radau nodes after s = 0

private:
    // One try of a sub-step of length dt from (x, v) at time t. Leaves the
    // converged b's in m_b and returns the error estimate |b₆| / |a|.
    // The returned error is at least the last pass's change of b₆ (a pass that
    // has not settled is no better than that), and +∞ when anything is not
    // finite.
    double trySubStep(const ForceModel& forces, const Matrix2X& x, const Matrix2X& v, double t, double dt);
    // The smallest error estimate that still means something at (x, v): the
    // rounding of the force values at the nodes, carried into |b₆| / |a|. Costs
    // one force evaluation; needs m_a0 = a(x, v, t).
    double roundingFloor(const ForceModel& forces, const Matrix2X& x, const Matrix2X& v, double t);
    void predict(double ratio);
    void acceptSubStep(Matrix2X& x, Matrix2X& v, double dt);

    Matrix2X m_b[kNodes];     // b₀…b₆ of the current try, px/s²
    Matrix2X m_g[kNodes];     // g₁…g₇, divided differences of the force at the nodes
    Matrix2X m_e[kNodes];     // the prediction the current try started from
    Matrix2X m_bPrev[kNodes]; // the last accepted sub-step's b's and prediction
    Matrix2X m_ePrev[kNodes];
    Matrix2X m_a0, m_f, m_xs, m_vs, m_acc, m_dx, m_dv, m_y, m_sum;
    Matrix2X m_compX, m_compV; // low-order bits lost by the sums of x and v
    double m_prevStep = 0.0;   // s, length of the last accepted sub-step (0: none to predict from)
    bool m_ePrevValid = false; // the last accepted sub-step started from a prediction
    bool m_bScaled = false;    // m_b holds a rejected try rescaled to the next try's length
    double m_nextStep = 0.0;   // s, step-size guess (0: try the whole step)
    Eigen::Index m_cols = -1;  // ball count the state belongs to
};

} // namespace forcelab::sim
