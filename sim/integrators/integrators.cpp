#include "sim/integrators/integrators.h"

#include <algorithm>
#include <cmath>

namespace forcelab::sim {

void Integrator::invalidate()
{
    m_aValid = false;
    m_rk45h = 0.0;
    m_ias15.reset();
}

const Matrix2X& Integrator::startAcceleration(const ForceModel& forces, const Matrix2X& x, const Matrix2X& v,
                                              double t)
{
    if (!m_aValid || m_a.cols() != x.cols()) {
        forces.acceleration(x, v, t, m_a);
        m_aValid = true;
    }
    return m_a;
}

// One velocity-Verlet step: half a kick with the old acceleration, a drift
// with the half-step velocity, a new acceleration, the second half kick.
// Time-reversible and symplectic for position-only forces.
//
// A velocity-dependent force (drag) needs the acceleration at the end
// velocity, which the second kick is computing. Using the half-step velocity
// instead makes the method first order; predicting the end velocity with that
// acceleration and evaluating once more restores second order, at the price
// of one extra evaluation per step while drag is on.
void Integrator::kickDriftKick(const ForceModel& forces, Matrix2X& x, Matrix2X& v, double t, double h)
{
    const Matrix2X& a = startAcceleration(forces, x, v, t);
    v.noalias() += (0.5 * h) * a;
    x.noalias() += h * v;
    forces.acceleration(x, v, t + h, m_a);
    if (!forces.velocityIndependent()) {
        m_vs = v + (0.5 * h) * m_a; // predicted end velocity
        forces.acceleration(x, m_vs, t + h, m_a);
    }
    v.noalias() += (0.5 * h) * m_a;
}

void Integrator::advance(IntegratorKind kind, const ForceModel& forces, Matrix2X& x, Matrix2X& v, double t,
                         double h, double tolerance, IntegratorStats& stats)
{
    switch (kind) {
    case IntegratorKind::Euler: {
        // [code step.euler if time.integrator=euler: One step of explicit Euler]
        // Both updates use the old state: x_{n+1} = x_n + v_n h, v_{n+1} = v_n + a_n h.
        forces.acceleration(x, v, t, m_a);
        x.noalias() += h * v;
        v.noalias() += h * m_a;
        // [/code]
        m_aValid = false;
        break;
    }
    case IntegratorKind::SemiImplicitEuler: {
        // [code step.semi-implicit-euler if time.integrator=semi-implicit-euler: One step of semi-implicit Euler]
        // The velocity is updated first and the position uses the new velocity.
        forces.acceleration(x, v, t, m_a);
        v.noalias() += h * m_a;
        x.noalias() += h * v;
        // [/code]
        m_aValid = false;
        break;
    }
    case IntegratorKind::Exact: {
        // [code step.exact if time.integrator=exact: One step of the exact parabola]
        // With a constant acceleration the motion is a parabola: exact in closed form.
        forces.acceleration(x, v, t, m_a);
        x.noalias() += h * v + (0.5 * h * h) * m_a;
        v.noalias() += h * m_a;
        // [/code]
        m_aValid = false;
        break;
    }
    case IntegratorKind::Verlet:
        kickDriftKick(forces, x, v, t, h);
        break;
    case IntegratorKind::Yoshida4: {
        // Yoshida's composition: Verlet steps of w1 h, w0 h, w1 h with
        // w1 = 1 / (2 − 2^(1/3)) and w0 = 1 − 2 w1 cancel the third-order error.
        const double cbrt2 = std::cbrt(2.0);
        const double w1 = 1.0 / (2.0 - cbrt2);
        const double w0 = 1.0 - 2.0 * w1;
        kickDriftKick(forces, x, v, t, w1 * h);
        kickDriftKick(forces, x, v, t + w1 * h, w0 * h);
        kickDriftKick(forces, x, v, t + (w1 + w0) * h, w1 * h);
        break;
    }
    case IntegratorKind::Rk4: {
        // y = (x, v), y' = (v, a(x, v, t)): four slopes, weights 1, 2, 2, 1.
        Matrix2X* kx = m_kx;
        Matrix2X* kv = m_kv;
        kx[0] = v;
        forces.acceleration(x, v, t, kv[0]);
        m_xs = x + (0.5 * h) * kx[0];
        kx[1] = v + (0.5 * h) * kv[0];
        forces.acceleration(m_xs, kx[1], t + 0.5 * h, kv[1]);
        m_xs = x + (0.5 * h) * kx[1];
        kx[2] = v + (0.5 * h) * kv[1];
        forces.acceleration(m_xs, kx[2], t + 0.5 * h, kv[2]);
        m_xs = x + h * kx[2];
        kx[3] = v + h * kv[2];
        forces.acceleration(m_xs, kx[3], t + h, kv[3]);
        x += (h / 6.0) * (kx[0] + 2.0 * kx[1] + 2.0 * kx[2] + kx[3]);
        v += (h / 6.0) * (kv[0] + 2.0 * kv[1] + 2.0 * kv[2] + kv[3]);
        m_aValid = false;
        break;
    }
    case IntegratorKind::Rk45:
        dormandPrince(forces, x, v, t, h, tolerance, stats);
        m_aValid = false;
        break;
    case IntegratorKind::Ias15:
        m_ias15.advance(forces, x, v, t, h, tolerance, stats);
        m_aValid = false;
        break;
    }
}

namespace {
// Dormand–Prince 5(4) tableau. Row i of A gives stage i from stages 0..i-1;
// B is the 5th-order solution (equal to A's last row, so the last stage is the
// first stage of the next sub-step), E = B − B* is the error estimate's weights.
constexpr double C[7] = {0.0, 1.0 / 5, 3.0 / 10, 4.0 / 5, 8.0 / 9, 1.0, 1.0};
constexpr double A[7][6] = {
    {},
    {1.0 / 5},
    {3.0 / 40, 9.0 / 40},
    {44.0 / 45, -56.0 / 15, 32.0 / 9},
    {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729},
    {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656},
    {35.0 / 384, 0.0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84},
};
constexpr double E[7] = {71.0 / 57600,    0.0,          -71.0 / 16695, 71.0 / 1920,
                         -17253.0 / 339200, 22.0 / 525, -1.0 / 40};
} // namespace

// Adaptive sub-steps until the whole step h is covered. The error of a
// sub-step is the largest component of the 5th−4th order difference over
// tol × (1 + |y|) (absolute error for small values, relative for large ones);
// a sub-step with error ≤ 1 is kept, and the next size is h × 0.9 err^(−1/5),
// limited to between 0.2× and 5×.
void Integrator::dormandPrince(const ForceModel& forces, Matrix2X& x, Matrix2X& v, double t, double h,
                               double tolerance, IntegratorStats& stats)
{
    const double end = t + h;
    double hs = m_rk45h > 0.0 ? std::min(m_rk45h, h) : h;
    bool firstStageValid = false;
    double now = t;
    for (std::int64_t tries = 0; now < end; ++tries) {
        if (tries == kMaxAdaptiveSubSteps) {
            stats.gaveUp = true;
            m_rk45h = 0.0;
            return;
        }
        const bool last = now + hs >= end - 1e-12 * std::abs(h);
        const double step = last ? end - now : hs;
        if (!firstStageValid) {
            m_kx[0] = v;
            forces.acceleration(x, v, now, m_kv[0]);
            firstStageValid = true;
        }
        for (int s = 1; s < 7; ++s) {
            m_xs = x;
            m_vs = v;
            for (int j = 0; j < s; ++j) {
                if (A[s][j] == 0.0)
                    continue;
                m_xs.noalias() += (step * A[s][j]) * m_kx[j];
                m_vs.noalias() += (step * A[s][j]) * m_kv[j];
            }
            m_kx[s] = m_vs;
            forces.acceleration(m_xs, m_vs, now + C[s] * step, m_kv[s]);
        }
        // m_xs, m_vs now hold the 5th-order solution (stage 6 uses row B).
        m_xn.setZero(2, x.cols());
        m_vn.setZero(2, x.cols());
        for (int j = 0; j < 7; ++j) {
            if (E[j] == 0.0)
                continue;
            m_xn.noalias() += (step * E[j]) * m_kx[j];
            m_vn.noalias() += (step * E[j]) * m_kv[j];
        }
        const auto scaleX = (x.cwiseAbs().cwiseMax(m_xs.cwiseAbs()).array() + 1.0) * tolerance;
        const auto scaleV = (v.cwiseAbs().cwiseMax(m_vs.cwiseAbs()).array() + 1.0) * tolerance;
        double err = 0.0;
        if (x.cols() > 0)
            err = std::max((m_xn.array().abs() / scaleX).maxCoeff(), (m_vn.array().abs() / scaleV).maxCoeff());
        if (!std::isfinite(err))
            err = 1e10;
        const double factor = std::clamp(0.9 * std::pow(std::max(err, 1e-10), -0.2), 0.2, 5.0);
        const double minStep = kMinSubStepShare * std::abs(h);
        if (err > 1.0 && step <= minStep) {
            // Even the shortest sub-step misses the tolerance (err is as large
            // as 1e10 for a state that is not finite): taking it would hand
            // back a state as wrong as err says. Stop instead.
            stats.gaveUp = true;
            stats.tooShort = true;
            stats.shortestSubStep = step;
            m_rk45h = 0.0;
            return;
        }
        if (err <= 1.0) {
            ++stats.accepted;
            x = m_xs;
            v = m_vs;
            now = last ? end : now + step;
            // First same as last: the final stage is the next sub-step's first.
            std::swap(m_kx[0], m_kx[6]);
            std::swap(m_kv[0], m_kv[6]);
            if (!last || step >= hs)
                hs = step * factor;
        } else {
            ++stats.rejected;
            hs = std::max(step * std::min(factor, 1.0), minStep);
        }
    }
    m_rk45h = hs;
}

} // namespace forcelab::sim
