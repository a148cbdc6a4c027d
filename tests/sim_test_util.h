#pragma once
// Small helpers shared by the simulation tests.

#include "sim/world/parameters.h"
#include "sim/studies/work_precision.h"
#include "sim/world/world.h"

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace forcelab::test {

// Scenes built in code: sim's own helpers (sim/world/scene.h).
using sim::ballAt;
using sim::openScene;

/// `b` painted `color` (for tests that look at the picture).
inline sim::Ball coloured(sim::Ball b, sim::Rgb color)
{
    b.color = color;
    return b;
}

/// Starts `world` on the scene with this integrator and step and takes
/// `steps` steps (fewer if the world halts). Returns why the scene was
/// refused, or nullopt.
inline std::optional<std::string> runFor(sim::World& world, sim::Scene scene, sim::IntegratorKind integrator, double dt,
                                         int steps)
{
    scene.settings.time.integrator = integrator;
    scene.settings.time.dt = dt;
    if (auto refused = world.reset(scene))
        return toString(*refused);
    for (int k = 0; k < steps && !world.halted(); ++k)
        world.step();
    return std::nullopt;
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

/// Least-squares slope of log(err) against log(dt): the observed order
/// (sim/studies/work_precision.h, which the sweep and the Accuracy dock use too).
using sim::fittedOrder;

} // namespace forcelab::test
