#pragma once
// The soft contact of the staged solve (staged_solve.h), after Box2D v3's
// b2MakeSoft: a stiff spring with a damper, solved implicitly over one step.
// With ω the spring's angular frequency, ζ the damping ratio and h the step,
//   a1 = 2ζ + h·ω,  a2 = h·ω·a1,  a3 = 1 / (1 + a2),
// an overlap s < 0 asks for the separating speed −s·ω/a1 (biasRate), and the
// impulse that meets it is scaled by a2·a3 (massScale) less a3 times the
// impulse already applied (impulseScale). However long the step, the spring
// cannot overshoot, so the push never feeds energy into a pile the way a
// rigid correction of the whole overlap does.

namespace forcelab::sim {

struct Softness {
    double biasRate = 0.0;     ///< 1/s, separating speed per px of overlap: ω/a1
    double massScale = 1.0;    ///< 1, share of the row's mass a push uses: a2·a3
    double impulseScale = 0.0; ///< 1, share of the impulse so far it takes back: a3
};

/// The coefficients of a soft contact of angular frequency `omega` (1/s) and
/// damping ratio `zeta` (1: critical) over a step of length `h` (s).
inline Softness makeSoft(double omega, double zeta, double h)
{
    const double a1 = 2.0 * zeta + h * omega;
    const double a2 = h * omega * a1;
    const double a3 = 1.0 / (1.0 + a2);
    return {omega / a1, a2 * a3, a3};
}

} // namespace forcelab::sim
