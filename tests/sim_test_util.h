#pragma once
// Small helpers shared by the simulation tests.

#include "sim/parameters.h"
#include "sim/world.h"

#include <cmath>
#include <vector>

namespace forcelab::test {

/// A scene with no walls, no models and the given balls.
inline sim::Scene openScene(std::vector<sim::Ball> balls)
{
    sim::Scene s;
    s.settings.walls = sim::WallSettings{false, false, false, false, sim::WallModel::Clamp, 1.0};
    s.balls = std::move(balls);
    return s;
}

inline sim::Ball ballAt(double x, double y, double vx = 0.0, double vy = 0.0, double r = 10.0, double mass = 0.0)
{
    sim::Ball b;
    b.position = sim::Vec2(x, y);
    b.velocity = sim::Vec2(vx, vy);
    b.radius = r;
    b.mass = mass;
    return b;
}

/// A value the parameter row allows that differs from `from`: the other
/// choice or switch state, or a point inside its slider range.
inline double anotherValue(const sim::Parameter& p, double from)
{
    switch (p.type) {
    case sim::ParameterType::Boolean:
    case sim::ParameterType::Choice:
        return from == 0.0 ? 1.0 : 0.0;
    case sim::ParameterType::Integer:
        return from == p.lo ? p.lo + 1 : p.lo;
    case sim::ParameterType::Number:
        break;
    }
    const double mid = p.scale == sim::SliderScale::Log ? std::sqrt(p.sliderLo * p.sliderHi)
                                                        : 0.5 * (p.sliderLo + p.sliderHi);
    return mid != from ? mid : 0.25 * p.sliderLo + 0.75 * p.sliderHi;
}

/// Least-squares slope of log(err) against log(dt): the observed order.
inline double fittedOrder(const std::vector<double>& dt, const std::vector<double>& err)
{
    const std::size_t n = dt.size();
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double x = std::log(dt[i]), y = std::log(err[i]);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

} // namespace forcelab::test
