#include "sim/integrators/ias15.h"

#include "sim/integrators/integrators.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace forcelab::sim {
namespace {

// Gauss–Radau spacings on [0, 1]: h₀ = 0 and the seven other nodes of the
// 8-point Radau rule (exact for polynomials up to degree 14).
constexpr double kH[Ias15::kNodes + 1] = {
    0.0,
    0.0562625605369221464656521910318,
    0.180240691736892364987579942780,
    0.352624717113169637373907769648,
    0.547153626330555383001448554766,
    0.734210177215410531523210605558,
    0.885320946839095768090359771030,
    0.977520613561287501891174488626,
};

// A larger change of sub-step than this means the polynomial moved forward is
// no guess at all: start from zero.
constexpr double kMaxPredictRatio = 20.0;
// A new sub-step below this share of the one tried rejects the try; above its
// inverse the growth is capped.
constexpr double kSafety = 0.25;
// The predictor–corrector stops when b₆ changes by less than this share of |a|.
constexpr double kConverged = 1e-16;
constexpr int kMaxIterations = 12;

// How much rounding in the force values grows on its way into b₆. b₆ is the
// divided difference of the force over the eight nodes,
// g₇ = Σ_i f(h_i) / Π_{j≠i} (h_i − h_j), so independent rounding δ in each
// f(h_i) gives b₆ a rounding of δ √(Σ_i 1 / Π_{j≠i} (h_i − h_j)²) ≈ 4550 δ.
// Computed from the spacings in tables().
// The probe in roundingFloor() moves every coordinate by a whole unit in the
// last place, in the same direction, which is already more than the node
// positions' rounding (half a unit, random); the floor keeps a margin of 2
// above that. Measured on the e = 0.5 Kepler orbit at periapsis: |b₆| / |a|
// of sub-steps far too short to have any truncation error scatters up to
// 7e-12, against a floor of 2.4e-11 there.
constexpr double kFloorMargin = 2.0;
// The floor changes slowly along a path: an error this many times above the
// last floor measured is truncation, without measuring again.
constexpr double kRecheckFloor = 100.0;
// The largest rounding floor that may stand in for the tolerance. The floor
// is 9100 times the relative shake of the force when the state is nudged by an
// ulp or two; above 1e-4 the force values are known to fewer than 8 figures, which
// happens only within a few million ulps of a singular point (a ball falling
// into an attracting point: the floor grows like 1 / distance). There the
// floor is no floor: the sub-step must shrink, and where it cannot, ias15
// gives up. Measured: Kepler orbits centred 1e7 px from the origin with
// periapsis 10 px reach floors of 4.7e-6 (a ball round the point) and 9.4e-6
// (a pair in mutual gravity); a ball falling into the point reaches 1e-4
// about 1e-5 px from it.
constexpr double kMaxFloor = 1e-4;

// The Newton basis N_n(s) = s (s − h₁)…(s − h_{n−1}) in powers of s:
// N_n(s) = Σ_k c[k][n] s^(k+1). So a(s) = a₀ + Σ_n g_n N_n(s) gives
// b_k = Σ_{n ≥ k+1} c[k][n] g_n, with c[n−1][n] = 1.
struct Tables {
    double c[Ias15::kNodes][Ias15::kNodes + 1] = {};
    double noiseGain = 0.0; // rounding of b₆ per unit rounding of one force value (see kFloorMargin)
    Tables()
    {
        for (int i = 0; i <= Ias15::kNodes; ++i) {
            double product = 1.0;
            for (int j = 0; j <= Ias15::kNodes; ++j)
                if (j != i)
                    product *= kH[i] - kH[j];
            noiseGain += 1.0 / (product * product);
        }
        noiseGain = std::sqrt(noiseGain);
        // Expand the products one factor at a time.
        for (int n = 1; n <= Ias15::kNodes; ++n) {
            std::array<double, Ias15::kNodes + 1> poly{}; // poly[p] = coefficient of s^p
            poly[1] = 1.0;                                  // N_1 = s
            for (int j = 1; j < n; ++j) {
                std::array<double, Ias15::kNodes + 1> next{};
                for (int p = 1; p <= j; ++p) {
                    next[p + 1] += poly[p];
                    next[p] -= kH[j] * poly[p];
                }
                poly = next;
            }
            for (int k = 0; k < n; ++k)
                c[k][n] = poly[k + 1];
        }
    }
};

const Tables& tables()
{
    static const Tables t;
    return t;
}

// max |m_ij|, or +∞ when any entry is not finite (Eigen's maxCoeff skips NaN).
double largest(const Matrix2X& m)
{
    if (m.size() == 0)
        return 0.0;
    if (!m.allFinite())
        return std::numeric_limits<double>::infinity();
    return m.cwiseAbs().maxCoeff();
}

double binomial(int n, int k)
{
    double r = 1.0;
    for (int i = 1; i <= k; ++i)
        r = r * (n - k + i) / i;
    return r;
}

// sum += add with Kahan's compensation: comp keeps what the rounding of the
// sum lost, and is taken back from the next addition.
void compensatedAdd(Matrix2X& sum, Matrix2X& comp, const Matrix2X& add, Matrix2X& y, Matrix2X& t)
{
    y = add - comp;
    t = sum + y;
    comp = (t - sum) - y;
    sum = t;
}

} // namespace

void Ias15::reset()
{
    m_prevStep = 0.0;
    m_ePrevValid = false;
    m_bScaled = false;
    m_nextStep = 0.0;
    m_cols = -1;
}

// The previous sub-step's acceleration polynomial, written in the variable of
// the next sub-step: with s_old = 1 + q s_new (q = new length / old length),
// a = a₀ + Σ_k b_k (1 + q s)^(k+1) gives b'_m = q^(m+1) Σ_{k ≥ m} C(k+1, m+1) b_k.
// The previous sub-step's own prediction error is added as a correction.
void Ias15::predict(double ratio)
{
    const Eigen::Index n = m_bPrev[0].cols();
    if (ratio > kMaxPredictRatio) {
        for (int k = 0; k < kNodes; ++k) {
            m_b[k].setZero(2, n);
            m_e[k].setZero(2, n);
        }
        return;
    }
    double qPower = 1.0;
    for (int m = 0; m < kNodes; ++m) {
        qPower *= ratio;
        m_e[m].setZero(2, n);
        for (int k = m; k < kNodes; ++k)
            m_e[m].noalias() += (qPower * binomial(k + 1, m + 1)) * m_bPrev[k];
        if (m_ePrevValid)
            m_b[m] = m_e[m] + (m_bPrev[m] - m_ePrev[m]);
        else
            m_b[m] = m_e[m];
    }
}

double Ias15::trySubStep(const ForceModel& forces, const Matrix2X& x, const Matrix2X& v, double t, double dt)
{
    const Tables& tab = tables();
    const Eigen::Index n = x.cols();
    // g from b: back-substitution through the triangular c.
    for (int k = kNodes - 1; k >= 0; --k) {
        m_g[k] = m_b[k];
        for (int j = k + 1; j < kNodes; ++j)
            m_g[k].noalias() -= tab.c[k][j + 1] * m_g[j];
    }

    double previousError = 2.0;
    double lastChange = 0.0; // the last pass's change of b₆, relative to |a|
    for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
        double change = 0.0, scale = 0.0;
        for (int node = 1; node <= kNodes; ++node) {
            const double s = kH[node];
            // Position and velocity at s from the current polynomial:
            // x = x₀ + s Δt v₀ + (s Δt)² (a₀/2 + Σ b_k s^(k+1) / ((k+2)(k+3))),
            // v = v₀ + s Δt (a₀ + Σ b_k s^(k+1) / (k+2)).
            m_acc = 0.5 * m_a0;
            m_sum = m_a0;
            double sPower = 1.0;
            for (int k = 0; k < kNodes; ++k) {
                sPower *= s;
                m_acc.noalias() += (sPower / ((k + 2) * (k + 3))) * m_b[k];
                m_sum.noalias() += (sPower / (k + 2)) * m_b[k];
            }
            const double sdt = s * dt;
            m_xs = x + sdt * v + (sdt * sdt) * m_acc;
            m_vs = v + sdt * m_sum;
            forces.acceleration(m_xs, m_vs, t + sdt, m_f);

            // New divided difference g_node from the force at this node and
            // the g's below it (already updated in this pass).
            m_y = (m_f - m_a0) / s;
            for (int j = 1; j < node; ++j)
                m_y = (m_y - m_g[j - 1]) / (s - kH[j]);
            m_dx = m_y - m_g[node - 1]; // the change of g_node
            m_g[node - 1] = m_y;
            for (int k = 0; k < node; ++k)
                m_b[k].noalias() += tab.c[k][node] * m_dx;
            if (node == kNodes && n > 0) {
                change = largest(m_dx); // c[6][7] = 1: the change of b₆
                scale = largest(m_f);
            }
        }
        const double error = scale > 0.0 ? change / scale : (change > 0.0 ? 1.0 : 0.0);
        if (!std::isfinite(error))
            return std::numeric_limits<double>::infinity();
        lastChange = error;
        if (error < kConverged)
            break;
        // Rounding has the last word: stop when a pass no longer helps. When
        // the passes grow instead, the sub-step is too long for the iteration
        // to converge at all (a stiff force); lastChange then says so.
        if (iteration > 1 && error >= previousError)
            break;
        previousError = error;
    }
    if (n == 0)
        return 0.0;
    const double b6 = largest(m_b[kNodes - 1]);
    const double a = largest(m_f);
    const double estimate = a > 0.0 ? b6 / a : (b6 > 0.0 ? 1.0 : 0.0);
    if (!std::isfinite(estimate))
        return std::numeric_limits<double>::infinity();
    // An estimate the predictor–corrector had not settled is no better than
    // its last correction.
    return std::max(estimate, lastChange);
}

double Ias15::roundingFloor(const ForceModel& forces, const Matrix2X& x, const Matrix2X& v, double t)
{
    // Move every coordinate and velocity by a unit or two in its last place
    // and see how far the force moves: that is how much the rounding of the
    // node positions (x₀ plus a small offset, rounded) shakes the force values.
    // A force model's own rounding adds a few ε |a|. Neighbouring balls move
    // by different amounts (+1, −1, +2, −2 units, repeating): a force between
    // balls sees only their difference, which moving all of them alike would
    // leave unchanged. (It did: lesson 20's three bodies got a floor below
    // 1e-11 while their estimate scattered above it, so at tolerance 1e-11
    // the sub-steps shrank until the step ran out of them, at t = 0.93 s.
    // Now the floor there is 6.6e-10 and the run keeps its energy to 1e-15.)
    const auto nudged = [](const Matrix2X& from, Matrix2X& to) {
        to.resize(from.rows(), from.cols());
        for (Eigen::Index i = 0; i < from.cols(); ++i) {
            const int units = 1 + static_cast<int>((i / 2) % 2);
            const double towards = i % 2 == 0 ? std::numeric_limits<double>::infinity()
                                               : -std::numeric_limits<double>::infinity();
            for (Eigen::Index d = 0; d < from.rows(); ++d) {
                double c = from(d, i);
                for (int k = 0; k < units; ++k)
                    c = std::nextafter(c, towards);
                to(d, i) = c;
            }
        }
    };
    nudged(x, m_xs);
    nudged(v, m_vs);
    forces.acceleration(m_xs, m_vs, t, m_f);
    const double scale = largest(m_a0);
    if (!(scale > 0.0))
        return 0.0;
    const double shake = std::max(largest(m_f - m_a0), 2.0 * std::numeric_limits<double>::epsilon() * scale);
    return kFloorMargin * tables().noiseGain * shake / scale;
}

// The end of the sub-step, s = 1:
// Δx = Δt v₀ + Δt² (a₀/2 + Σ b_k / ((k+2)(k+3))), Δv = Δt (a₀ + Σ b_k / (k+2)).
void Ias15::acceptSubStep(Matrix2X& x, Matrix2X& v, double dt)
{
    m_acc = 0.5 * m_a0;
    m_sum = m_a0;
    for (int k = 0; k < kNodes; ++k) {
        m_acc.noalias() += (1.0 / ((k + 2) * (k + 3))) * m_b[k];
        m_sum.noalias() += (1.0 / (k + 2)) * m_b[k];
    }
    m_dx = dt * v + (dt * dt) * m_acc;
    m_dv = dt * m_sum;
    compensatedAdd(x, m_compX, m_dx, m_y, m_xs);
    compensatedAdd(v, m_compV, m_dv, m_y, m_vs);
}

void Ias15::advance(const ForceModel& forces, Matrix2X& x, Matrix2X& v, double t, double h, double epsilon,
                    IntegratorStats& stats)
{
    if (m_cols != x.cols()) {
        reset();
        m_cols = x.cols();
    }
    if (m_prevStep == 0.0) {
        m_compX.setZero(2, x.cols());
        m_compV.setZero(2, x.cols());
    }
    double floor = -1.0; // the rounding floor of the error estimate, once measured in this step
    const double end = t + h;
    const double minStep = kMinSubStepShare * std::abs(h);
    double dt = m_nextStep > 0.0 ? std::min(m_nextStep, h) : h;
    double now = t;
    for (std::int64_t tries = 0; now < end; ++tries) {
        if (tries == kMaxAdaptiveSubSteps) {
            stats.gaveUp = true;
            reset();
            return;
        }
        const bool last = now + dt >= end - 1e-12 * std::abs(h);
        const double step = last ? end - now : dt;
        // The first guess of the polynomial.
        if (m_prevStep > 0.0) {
            predict(step / m_prevStep);
        } else if (!m_bScaled) {
            for (int k = 0; k < kNodes; ++k) {
                m_b[k].setZero(2, x.cols());
                m_e[k].setZero(2, x.cols());
            }
        }
        m_bScaled = false;
        forces.acceleration(x, v, now, m_a0);
        const double error = trySubStep(forces, x, v, now, step);
        const auto nextFor = [&](double tolerance) {
            if (!std::isfinite(error))
                return 0.1 * step;
            return error > 0.0 ? step * std::pow(tolerance / error, 1.0 / 7.0) : step / kSafety;
        };
        // Above ε: is it truncation, which a shorter sub-step lowers, or
        // rounding, which it does not? The floor measured last in this step is
        // reused while the error is far above it.
        if (error > epsilon && std::isfinite(error) && !(floor >= 0.0 && error > kRecheckFloor * floor)) {
            ++stats.roundingChecks;
            floor = roundingFloor(forces, x, v, now);
        }
        // A floor above kMaxFloor is not rounding to work to but a sign that
        // the force is nearly singular here: it does not stand in.
        const bool floorUsable = floor >= 0.0 && floor <= kMaxFloor;
        const double tolerance =
            std::isfinite(error) && error > epsilon && floorUsable ? std::max(epsilon, floor) : epsilon;
        double next = nextFor(tolerance);
        if (next < kSafety * step && step <= minStep) {
            // Even the shortest sub-step misses the tolerance: its result
            // would be as wrong as the estimate says. Give up; the world
            // stops and names the cause.
            stats.gaveUp = true;
            stats.tooShort = true;
            stats.shortestSubStep = step;
            reset();
            return;
        }
        if (next < kSafety * step) {
            // Too large a sub-step: try again with the suggested length.
            ++stats.rejected;
            dt = std::max(next, minStep);
            if (m_prevStep == 0.0 && std::isfinite(error)) {
                // No previous sub-step to predict from: keep this try's
                // polynomial, rescaled to the shorter length (s → q s).
                const double q = dt / step;
                double qPower = 1.0;
                for (int k = 0; k < kNodes; ++k) {
                    qPower *= q;
                    m_b[k] *= qPower;
                }
                m_bScaled = true;
            }
            continue;
        }
        ++stats.accepted;
        if (tolerance > epsilon) // accepted only thanks to the floor
            stats.toleranceFloor = std::max(stats.toleranceFloor, tolerance);
        acceptSubStep(x, v, step);
        now = last ? end : now + step;
        for (int k = 0; k < kNodes; ++k) {
            std::swap(m_bPrev[k], m_b[k]);
            std::swap(m_ePrev[k], m_e[k]);
        }
        m_ePrevValid = m_prevStep > 0.0;
        m_prevStep = step;
        next = std::min(next, step / kSafety);
        // A sub-step shortened to end the world step says little about the
        // next one: keep the guess unless it asks for less.
        if (!last || step >= dt || next < dt)
            dt = next;
    }
    m_nextStep = dt;
}

} // namespace forcelab::sim
