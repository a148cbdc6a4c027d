#include "sim/world/step_plan.h"

#include "sim/world/parameters.h"

#include <cmath>

namespace forcelab::sim {

std::optional<StepPlan> planSteps(double duration, double dt, std::int64_t maxSteps, std::string* why)
{
    auto refuse = [&](std::string text) {
        if (why)
            *why = std::move(text);
        return std::nullopt;
    };
    if (!std::isfinite(duration) || duration < 0.0)
        return refuse(numberText(duration) + " s is not a length of time a run can have");
    if (!(dt > 0.0) || !std::isfinite(dt))
        return refuse("dt = " + numberText(dt) + " s is not a step");
    const double n = duration / dt; // may be huge or inf: checked as a double first
    if (!(n <= static_cast<double>(maxSteps) + 1.0))
        return refuse(numberText(duration) + " s is " + numberText(std::ceil(n)) + " steps of dt = " +
                      numberText(dt) + " s, more than " + std::to_string(maxSteps));
    StepPlan plan;
    const double nearest = std::round(n);
    if (std::abs(n - nearest) <= 1e-9 * std::max(1.0, nearest)) {
        plan.whole = static_cast<std::int64_t>(nearest);
    } else {
        plan.whole = static_cast<std::int64_t>(std::floor(n));
        plan.last = duration - static_cast<double>(plan.whole) * dt;
    }
    if (plan.steps() > maxSteps)
        return refuse(numberText(duration) + " s is " + std::to_string(plan.steps()) + " steps of dt = " +
                      numberText(dt) + " s, more than " + std::to_string(maxSteps));
    return plan;
}

void runPlan(World& world, const StepPlan& plan)
{
    for (std::int64_t k = 0; k < plan.whole && !world.halted(); ++k)
        world.step();
    if (plan.last <= 0.0 || world.halted())
        return;
    const WorldSettings own = world.settings();
    WorldSettings shorter = own;
    shorter.time.dt = plan.last;
    if (world.setSettings(shorter)) // cannot happen: a shorter step is in range; then the run ends a step early
        return;
    world.step();
    if (!world.halted()) // setSettings would clear a halt; a halted run keeps its state as it stopped
        world.setSettings(own);
}

} // namespace forcelab::sim
