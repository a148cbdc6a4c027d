#include "force_model.h"

#include <cmath>
#include <numbers>

namespace forcelab::sim {
namespace {

// Each model adds its acceleration to `a`. x, v are 2×N, like a.

// Uniform gravity: the same acceleration g for every ball.
void addUniformGravity(const GravitySettings& s, Matrix2X& a)
{
    a.colwise() += s.g;
}

// Drag opposes the velocity. Linear: a = −c v with c = k × the ball's scale
// factor (m_ref / m for a force), so dv/dt = −c v decays as e^(−ct).
// Quadratic: a = −c |v| v, which matters more at high speed. `scale` is empty
// for the tutorial's model, where every ball has c = k.
void addDrag(const DragSettings& s, const VectorX& scale, const Matrix2X& v, Matrix2X& a)
{
    if (scale.size() == 0) {
        if (s.law == DragLaw::Linear)
            a.noalias() -= s.k * v;
        else
            a -= s.k * (v.array().rowwise() * v.colwise().norm().array()).matrix();
        return;
    }
    const Eigen::ArrayXd c = s.k * scale.array();
    if (s.law == DragLaw::Linear)
        a -= (v.array().rowwise() * c.transpose()).matrix();
    else
        a -= (v.array().rowwise() * (c * v.colwise().norm().transpose().array()).transpose()).matrix();
}

// Wind blows along x: the reference ball gets w, the others w × its factor.
void addWind(double w, const VectorX& scale, Matrix2X& a)
{
    a.row(0) += w * scale.transpose();
}

// Inverse-square attraction or repulsion from point p: |a| = S / d² along the
// line from p to the ball, optionally clamped to maxAccel. At d = 0 the
// direction is undefined and the model adds nothing.
void addInverseSquare(const Vec2& p, double strength, bool attract, double maxAccel, const VectorX* scale,
                      const Matrix2X& x, Matrix2X& a)
{
    const double sign = attract ? -1.0 : 1.0;
    for (Eigen::Index i = 0; i < x.cols(); ++i) {
        const Vec2 d = x.col(i) - p;
        const double d2 = d.squaredNorm();
        if (d2 == 0.0)
            continue;
        const double dist = std::sqrt(d2);
        double mag = strength / d2;
        if (scale)
            mag *= (*scale)[i];
        if (maxAccel > 0.0 && mag > maxAccel)
            mag = maxAccel;
        a.col(i) += (sign * mag / dist) * d;
    }
}

// Hooke's law per unit mass: a = −k (x − anchor), an oscillation with ω = √k.
void addSpring(const SpringSettings& s, const Matrix2X& x, Matrix2X& a)
{
    a -= s.k * (x.colwise() - s.anchor);
}

// Homing: a spring of stiffness `strength` to each ball's own home.
void addHoming(const HomingSettings& s, const Matrix2X& home, const Matrix2X& x, Matrix2X& a)
{
    a.noalias() += s.strength * (home - x);
}

// Mutual gravity: F = G m_i m_j r⃗ / (r² + ε²)^(3/2) along the line between
// centres (Plummer softening). For r ≫ ε it is G m_i m_j / r²; near r = 0 it
// falls smoothly to zero instead of flipping direction at full strength, so a
// head-on pass through a softened pair has no kink for the step to miss.
// Each pair is computed once and applied to both balls with opposite signs,
// so total momentum is conserved to rounding. Coincident centres add nothing.
void addMutualGravity(const MutualGravitySettings& s, const VectorX& mass, const Matrix2X& x, Matrix2X& a)
{
    const Eigen::Index n = x.cols();
    const double eps2 = s.softening * s.softening;
    for (Eigen::Index i = 0; i < n; ++i) {
        const Vec2 xi = x.col(i);
        Vec2 ai = Vec2::Zero();
        for (Eigen::Index j = i + 1; j < n; ++j) {
            const Vec2 d = x.col(j) - xi;
            const double r2 = d.squaredNorm();
            if (r2 == 0.0)
                continue;
            // G / (r² + ε²)^(3/2): the force per unit mass of each partner per px of d.
            const double s2 = r2 + eps2;
            const double f = s.G / (s2 * std::sqrt(s2));
            ai += (f * mass[j]) * d;
            a.col(j) -= (f * mass[i]) * d;
        }
        a.col(i) += ai;
    }
}

// Potential of one mutual-gravity pair: U(r) = −G m₁ m₂ / √(r² + ε²), whose
// derivative is the Plummer force above, with U(∞) = 0.
double mutualPairPotential(double G, double eps, double m1m2, double r)
{
    const double s2 = r * r + eps * eps;
    return s2 == 0.0 ? 0.0 : -G * m1m2 / std::sqrt(s2);
}

} // namespace

VectorX scaleFactors(ForceScale scale, const BallState& balls)
{
    switch (scale) {
    case ForceScale::None:
        return VectorX::Ones(balls.size());
    case ForceScale::Radius:
        return kReferenceRadius * balls.radius.cwiseInverse();
    case ForceScale::Mass:
        return sphereMass(kReferenceRadius) * balls.inverseMass;
    }
    return VectorX::Ones(balls.size());
}

ForceModel::ForceModel(const WorldSettings& settings, const BallState& balls, const StepInputs& inputs)
    : m_settings(settings)
    , m_balls(balls)
    , m_inputs(inputs)
{
    if (settings.wind.mode != WindMode::Off)
        m_windScale = scaleFactors(settings.wind.scale, balls);
    if (settings.point.enabled && settings.point.scale != ForceScale::None)
        m_pointScale = scaleFactors(settings.point.scale, balls);
    if (settings.drag.enabled && settings.drag.scale != ForceScale::None)
        m_dragScale = scaleFactors(settings.drag.scale, balls);
}

double ForceModel::windAt(double t) const
{
    return m_inputs.wind.at(m_settings.wind.mode, m_settings.wind, t);
}

void ForceModel::acceleration(const Matrix2X& x, const Matrix2X& v, double t, Matrix2X& a) const
{
    ++m_evaluations;
    const WorldSettings& s = m_settings;
    a.setZero(2, x.cols());
    if (s.gravity.enabled)
        addUniformGravity(s.gravity, a);
    if (s.drag.enabled)
        addDrag(s.drag, m_dragScale, v, a);
    if (s.wind.mode != WindMode::Off)
        addWind(windAt(t), m_windScale, a);
    if (s.randomAccel.enabled && m_inputs.randomAccel.cols() == a.cols())
        a += m_inputs.randomAccel;
    if (s.point.enabled)
        addInverseSquare(s.point.position, s.point.strength, s.point.kind == PointKind::Attract, s.point.maxAccel,
                         s.point.scale == ForceScale::None ? nullptr : &m_pointScale, x, a);
    if (s.pointer.enabled && m_inputs.pointer.inside)
        addInverseSquare(m_inputs.pointer.position, s.pointer.strength, !m_inputs.pointer.pressed,
                         s.pointer.maxAccel, nullptr, x, a);
    if (s.spring.enabled)
        addSpring(s.spring, x, a);
    if (s.homing.enabled)
        addHoming(s.homing, m_balls.home, x, a);
    if (s.mutualGravity.enabled)
        addMutualGravity(s.mutualGravity, m_balls.mass, x, a);
}

double ForceModel::potential(const Matrix2X& x) const
{
    const WorldSettings& s = m_settings;
    const VectorX& m = m_balls.mass;
    double u = 0.0;
    if (s.gravity.enabled) // U = −m g·x: falling along g lowers the energy
        u -= (m.transpose() * (s.gravity.g.transpose() * x).transpose())(0);
    if (s.spring.enabled) // U = ½ m k |x − anchor|²
        u += 0.5 * s.spring.k * m.dot((x.colwise() - s.spring.anchor).colwise().squaredNorm().transpose());
    if (s.homing.enabled)
        u += 0.5 * s.homing.strength * m.dot((x - m_balls.home).colwise().squaredNorm().transpose());
    if (s.point.enabled) { // U = ∓ m c S / d, the unclamped inverse-square potential
        const double sign = s.point.kind == PointKind::Attract ? -1.0 : 1.0;
        for (Eigen::Index i = 0; i < x.cols(); ++i) {
            const double d = (x.col(i) - s.point.position).norm();
            const double c = s.point.scale == ForceScale::None ? 1.0 : m_pointScale[i];
            if (d > 0.0)
                u += sign * m[i] * c * s.point.strength / d;
        }
    }
    if (s.mutualGravity.enabled) {
        const Eigen::Index n = x.cols();
        for (Eigen::Index i = 0; i < n; ++i)
            for (Eigen::Index j = i + 1; j < n; ++j)
                u += mutualPairPotential(s.mutualGravity.G, s.mutualGravity.softening, m[i] * m[j],
                                         (x.col(j) - x.col(i)).norm());
    }
    return u;
}

const char* nonConstantAccelerationReason(const WorldSettings& s)
{
    // Random and smoothed wind and the random acceleration are drawn once per
    // step, so within a step they are constant.
    if (s.drag.enabled)
        return "drag depends on velocity";
    if (s.wind.mode == WindMode::Noise)
        return "noise wind changes during the step";
    if (s.point.enabled)
        return "the point force depends on position";
    if (s.pointer.enabled)
        return "the pointer force depends on position";
    if (s.spring.enabled)
        return "the spring force depends on position";
    if (s.homing.enabled)
        return "homing depends on position";
    if (s.mutualGravity.enabled)
        return "mutual gravity depends on position";
    return nullptr;
}

} // namespace forcelab::sim
