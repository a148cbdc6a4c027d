#pragma once
// A Kepler orbit with a known answer, for tests and the accuracy sweep. The
// point force attracting with the inverse-square law and no clamp is exactly
// Kepler's problem with μ = strength: one ball orbits the fixed point.

#include "sim/world/scene.h"

namespace forcelab::sim {

struct KeplerOrbit {
    double a = 100.0;           ///< px, semi-major axis
    double e = 0.5;             ///< 1, eccentricity, [0, 1)
    double period = 1.0;        ///< s
    Vec2 focus{300.0, 200.0};   ///< px, the attracting point

    double meanMotion() const;  ///< 1/s, n = 2π / period
    double mu() const;          ///< px³/s², μ = n² a³ (Kepler's third law)
    double energyPerMass() const { return -0.5 * mu() / a; } ///< px²/s², −μ / 2a

    /// One ball of mass 1 at periapsis, moving at the periapsis speed; no
    /// walls, no other model.
    Scene scene(IntegratorKind integrator, double dt, double tolerance = 1e-9) const;

    /// Where the ball is at time t, from Kepler's equation E − e sin E = n t
    /// solved by Newton's method.
    Vec2 position(double t) const;
};

} // namespace forcelab::sim
