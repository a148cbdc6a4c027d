#include "sim/forces/force_models.h"

#include "sim/forces/custom_force.h"

#include "sim/forces/force_model.h"

#include <cmath>
#include <numbers>

namespace forcelab::sim {
namespace {

// Each model adds its acceleration to `a`. x, v are 2×N, like a.


// [code gravity if models.gravity.enabled=true: Gravity]
// Uniform gravity: the same acceleration g for every ball.
void addUniformGravity(const GravitySettings& s, Matrix2X& a)
{
    a.colwise() += s.g;
}
// [/code]

// [code drag if models.drag.enabled=true: Drag]
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
// [/code]

// Wind blows along x: the reference ball gets w, the others w × its factor.
void addWind(double w, const VectorX& scale, Matrix2X& a)
{
    a.row(0) += w * scale.transpose();
}

// Inverse-square attraction or repulsion from point p: |a| = S / d² along the
// line from p to the ball, optionally clamped to maxAccel. At d = 0 the
// direction is undefined and the model adds nothing. `unnormalised` is the
// course's bug: the difference vector d itself times S / d², not its unit
// vector, so |a| = S / d (point.unnormalised in world_settings.h).
void addInverseSquare(const Vec2& p, double strength, bool attract, double maxAccel, const VectorX* scale,
                      const Matrix2X& x, Matrix2X& a, bool unnormalised = false)
{
    const double sign = attract ? -1.0 : 1.0;
    for (Eigen::Index i = 0; i < x.cols(); ++i) {
        const Vec2 d = x.col(i) - p;
        const double d2 = d.squaredNorm();
        if (d2 == 0.0)
            continue;
        const double dist = std::sqrt(d2);
        double mag = unnormalised ? strength / dist : strength / d2;
        if (scale)
            mag *= (*scale)[i];
        if (maxAccel > 0.0 && mag > maxAccel)
            mag = maxAccel;
        a.col(i) += (sign * mag / dist) * d;
    }
}

// [code spring if models.spring.enabled=true: A spring to the anchor]
// Hooke's law per unit mass: a = −k (x − anchor), an oscillation with ω = √k.
void addSpring(const SpringSettings& s, const Matrix2X& x, Matrix2X& a)
{
    a -= s.k * (x.colwise() - s.anchor);
}
// [/code]

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


// [code magnetic if models.magnetic.enabled=true: A magnetic field]
// Magnetic field B out of the screen: a = (q/m) m₁₀ B (v_y, −v_x). It is
// always at right angles to v, so it turns the ball and does no work.
void addMagnetic(const MagneticSettings& s, const BallState& b, const Matrix2X& v, Matrix2X& a)
{
    const double m10 = sphereMass(kReferenceRadius);
    const Eigen::ArrayXd w = (s.B * m10) * (b.charge.array() * b.inverseMass.array()); // ω per ball, rad/s
    a.row(0).array() += w.transpose() * v.row(1).array();
    a.row(1).array() -= w.transpose() * v.row(0).array();
}
// [/code]

// Potential energies: U with −∇U/m = the model's acceleration.

// U = −m g·x: falling along g lowers the energy.
double gravityPotential(const ForceContext& c, const Matrix2X& x)
{
    return -(c.balls.mass.transpose() * (c.settings.gravity.g.transpose() * x).transpose())(0);
}

// U = ½ m k |x − anchor|².
double springPotential(const ForceContext& c, const Matrix2X& x)
{
    const SpringSettings& s = c.settings.spring;
    return 0.5 * s.k * c.balls.mass.dot((x.colwise() - s.anchor).colwise().squaredNorm().transpose());
}

double homingPotential(const ForceContext& c, const Matrix2X& x)
{
    return 0.5 * c.settings.homing.strength * c.balls.mass.dot((x - c.balls.home).colwise().squaredNorm().transpose());
}

// U = ∓ m c S / d, the unclamped inverse-square potential; with the
// un-normalised bug (|a| = S / d) U = ± m c S ln(d / 1 px) instead.
double pointPotential(const ForceContext& c, const Matrix2X& x)
{
    const PointForceSettings& s = c.settings.point;
    const double sign = s.kind == PointKind::Attract ? -1.0 : 1.0;
    double u = 0.0;
    for (Eigen::Index i = 0; i < x.cols(); ++i) {
        const double d = (x.col(i) - s.position).norm();
        const double f = s.scale == ForceScale::None ? 1.0 : c.pointScale[i];
        if (d > 0.0)
            u += s.unnormalised ? -sign * c.balls.mass[i] * f * s.strength * std::log(d)
                                : sign * c.balls.mass[i] * f * s.strength / d;
    }
    return u;
}

double mutualPotential(const ForceContext& c, const Matrix2X& x)
{
    const MutualGravitySettings& s = c.settings.mutualGravity;
    const VectorX& m = c.balls.mass;
    double u = 0.0;
    const Eigen::Index n = x.cols();
    for (Eigen::Index i = 0; i < n; ++i)
        for (Eigen::Index j = i + 1; j < n; ++j)
            u += mutualPairPotential(s.G, s.softening, m[i] * m[j], (x.col(j) - x.col(i)).norm());
    return u;
}

const ForceModelInfo kModels[] = {
    {.name = "gravity",
     .on = [](const WorldSettings& s) { return s.gravity.enabled; },
     .add = [](const ForceContext& c, const Matrix2X&, const Matrix2X&, double, Matrix2X& a) {
         addUniformGravity(c.settings.gravity, a);
     },
     .potential = &gravityPotential,
     .switchOff = [](WorldSettings& s) { s.gravity.enabled = false; },
     .steadyAtRest = true,
     .sameForEveryBall = true},
    {.name = "drag",
     .on = [](const WorldSettings& s) { return s.drag.enabled; },
     .add = [](const ForceContext& c, const Matrix2X&, const Matrix2X& v, double, Matrix2X& a) {
         addDrag(c.settings.drag, c.dragScale, v, a);
     },
     .conservativePart = [](WorldSettings& s) { s.drag.enabled = false; },
     .switchOff = [](WorldSettings& s) { s.drag.enabled = false; },
     .notConstant = [](const WorldSettings&) -> const char* { return "drag depends on velocity"; },
     .velocityDependent = true,
     .stiffness = [](const WorldSettings& s, double dragFactor, double dragSpeed, double&, double& damping) {
         // The ball that drag slows fastest. Quadratic drag a = −c |v| v,
         // linearised along v, slows at the rate d|a|/d|v| = 2 c |v|: twice
         // its rate at the speed itself, and the explicit step overshoots (turns
         // the ball round) exactly when 2 c |v| h > 2.
         if (s.drag.law == DragLaw::Linear)
             damping += s.drag.k * dragFactor;
         else
             damping += 2.0 * s.drag.k * dragFactor * dragSpeed;
     },
     .steadyAtRest = true}, // nothing on a ball at rest
    {.name = "wind",
     .on = [](const WorldSettings& s) { return s.wind.mode != WindMode::Off; },
     .add = [](const ForceContext& c, const Matrix2X&, const Matrix2X&, double t, Matrix2X& a) {
         addWind(c.inputs.wind.at(c.settings.wind.mode, c.settings.wind, t), c.windScale, a);
     },
     .conservativePart = [](WorldSettings& s) { s.wind.mode = WindMode::Off; },
     .switchOff = [](WorldSettings& s) { s.wind.mode = WindMode::Off; },
     // Random and smoothed wind are drawn once per step: constant within it.
     .notConstant = [](const WorldSettings& s) -> const char* {
         return s.wind.mode == WindMode::Noise ? "noise wind changes during the step" : nullptr;
     }},
    {.name = "random",
     .on = [](const WorldSettings& s) { return s.randomAccel.enabled; },
     .add = [](const ForceContext& c, const Matrix2X&, const Matrix2X&, double, Matrix2X& a) {
         if (c.inputs.randomAccel.cols() == a.cols())
             a += c.inputs.randomAccel;
     },
     .conservativePart = [](WorldSettings& s) { s.randomAccel.enabled = false; },
     .switchOff = [](WorldSettings& s) { s.randomAccel.enabled = false; }},
    {.name = "point force",
     .on = [](const WorldSettings& s) { return s.point.enabled; },
     .add = [](const ForceContext& c, const Matrix2X& x, const Matrix2X&, double, Matrix2X& a) {
         const PointForceSettings& s = c.settings.point;
         addInverseSquare(s.position, s.strength, s.kind == PointKind::Attract, s.maxAccel,
                          s.scale == ForceScale::None ? nullptr : &c.pointScale, x, a, s.unnormalised);
     },
     .potential = &pointPotential,
     .conservativePart = [](WorldSettings& s) { s.point.maxAccel = 0.0; },
     .switchOff = [](WorldSettings& s) { s.point.enabled = false; },
     .notConstant = [](const WorldSettings&) -> const char* { return "the point force depends on position"; },
     .steadyAtRest = true},
    {.name = "pointer",
     .on = [](const WorldSettings& s) { return s.pointer.enabled; },
     .add = [](const ForceContext& c, const Matrix2X& x, const Matrix2X&, double, Matrix2X& a) {
         const PointerInput& p = c.inputs.pointer;
         if (p.inside)
             addInverseSquare(p.position, c.settings.pointer.strength, !p.pressed, c.settings.pointer.maxAccel,
                              nullptr, x, a);
     },
     .conservativePart = [](WorldSettings& s) { s.pointer.enabled = false; },
     .switchOff = [](WorldSettings& s) { s.pointer.enabled = false; },
     .notConstant = [](const WorldSettings&) -> const char* { return "the pointer force depends on position"; }},
    {.name = "spring",
     .on = [](const WorldSettings& s) { return s.spring.enabled; },
     .add = [](const ForceContext& c, const Matrix2X& x, const Matrix2X&, double, Matrix2X& a) {
         addSpring(c.settings.spring, x, a);
     },
     .potential = &springPotential,
     .switchOff = [](WorldSettings& s) { s.spring.enabled = false; },
     .notConstant = [](const WorldSettings&) -> const char* { return "the spring force depends on position"; },
     .stiffness = [](const WorldSettings& s, double, double, double& omega2, double&) { omega2 += s.spring.k; },
     .steadyAtRest = true},
    {.name = "homing",
     .on = [](const WorldSettings& s) { return s.homing.enabled; },
     .add = [](const ForceContext& c, const Matrix2X& x, const Matrix2X&, double, Matrix2X& a) {
         addHoming(c.settings.homing, c.balls.home, x, a);
     },
     .potential = &homingPotential,
     .switchOff = [](WorldSettings& s) { s.homing.enabled = false; },
     .notConstant = [](const WorldSettings&) -> const char* { return "homing depends on position"; },
     .stiffness = [](const WorldSettings& s, double, double, double& omega2, double&) {
         omega2 += s.homing.strength;
     },
     .steadyAtRest = true},
    {.name = "between balls",
     .on = [](const WorldSettings& s) { return s.mutualGravity.enabled; },
     .add = [](const ForceContext& c, const Matrix2X& x, const Matrix2X&, double, Matrix2X& a) {
         addMutualGravity(c.settings.mutualGravity, c.balls.mass, x, a);
     },
     .potential = &mutualPotential,
     .switchOff = [](WorldSettings& s) { s.mutualGravity.enabled = false; },
     .notConstant = [](const WorldSettings&) -> const char* { return "mutual gravity depends on position"; }},
    // No potential and nothing to book: it does no work, so the energy that
    // energy() sees must stay as it is, and any change is the integrator's.
    {.name = "magnetic",
     .on = [](const WorldSettings& s) { return s.magnetic.enabled; },
     .add = [](const ForceContext& c, const Matrix2X&, const Matrix2X& v, double, Matrix2X& a) {
         addMagnetic(c.settings.magnetic, c.balls, v, a);
     },
     .switchOff = [](WorldSettings& s) { s.magnetic.enabled = false; },
     .notConstant = [](const WorldSettings&) -> const char* { return "the magnetic force depends on velocity"; },
     .velocityDependent = true,
     .steadyAtRest = true}, // nothing on a ball at rest
    // The student's own law. With a potential it is counted as potential
    // energy; without one its work is booked like the drag's.
    {.name = "custom force",
     .on = [](const WorldSettings& s) { return s.custom.enabled; },
     .add = [](const ForceContext& c, const Matrix2X& x, const Matrix2X& v, double t, Matrix2X& a) {
         addCustomAcceleration(c.settings, c.balls, x, v, t, a);
     },
     .potential = [](const ForceContext& c, const Matrix2X& x) { return customPotential(c.settings, c.balls, x); },
     .conservativePart = [](WorldSettings& s) {
         if (s.custom.potential.empty())
             s.custom.enabled = false;
     },
     .switchOff = [](WorldSettings& s) { s.custom.enabled = false; },
     .notConstant = [](const WorldSettings&) -> const char* { return "the custom force may change during a step"; },
     .velocityDependent = true},
};

} // namespace

std::span<const ForceModelInfo> forceModels() { return kModels; }

} // namespace forcelab::sim
