#include "sim/studies/kepler.h"

#include <cmath>
#include <numbers>

namespace forcelab::sim {

double KeplerOrbit::meanMotion() const
{
    return 2.0 * std::numbers::pi / period;
}

double KeplerOrbit::mu() const
{
    const double n = meanMotion();
    return n * n * a * a * a;
}

Scene KeplerOrbit::scene(IntegratorKind integrator, double dt, double tolerance) const
{
    // At periapsis r = a(1 − e) and, from the energy −μ/2a, v² = μ (1 + e) / r.
    const double rp = a * (1.0 - e);
    Ball b;
    b.position = focus + Vec2(rp, 0.0);
    b.velocity = Vec2(0.0, std::sqrt(mu() * (1.0 + e) / rp));
    b.radius = 10.0;
    b.mass = 1.0;
    Scene s;
    s.settings.walls = WallSettings{false, false, false, false, WallModel::Clamp, 1.0};
    s.settings.point = PointForceSettings{true, PointKind::Attract, focus, mu(), 0.0, ForceScale::None};
    s.settings.time.integrator = integrator;
    s.settings.time.dt = dt;
    s.settings.time.tolerance = tolerance;
    s.balls = {b};
    return s;
}

Vec2 KeplerOrbit::position(double t) const
{
    const double M = std::remainder(meanMotion() * t, 2.0 * std::numbers::pi); // mean anomaly in (−π, π]
    double E = M + e * std::sin(M);
    for (int i = 0; i < 50; ++i) {
        const double dE = (E - e * std::sin(E) - M) / (1.0 - e * std::cos(E));
        E -= dE;
        if (std::abs(dE) < 1e-16)
            break;
    }
    return focus + Vec2(a * (std::cos(E) - e), a * std::sqrt(1.0 - e * e) * std::sin(E));
}

} // namespace forcelab::sim
