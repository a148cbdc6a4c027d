#include "sim/world/parameters.h"

#include "sim/world/names.h"

#include <array>
#include <cmath>

namespace forcelab::sim {
namespace {

// Accessors: a number field read and written as a double; a switch as 1 or 0;
// a choice as the index of its enumerator.
#define FIELD(f) .get = [](const WorldSettings& s) { return double(s.f); }, \
                 .set = [](WorldSettings& s, double v) { s.f = v; }
#define WHOLE(f) .get = [](const WorldSettings& s) { return double(s.f); }, \
                 .set = [](WorldSettings& s, double v) { s.f = static_cast<int>(v); }
#define SWITCH(f) .get = [](const WorldSettings& s) { return s.f ? 1.0 : 0.0; }, \
                  .set = [](WorldSettings& s, double v) { s.f = v != 0.0; }
#define CHOICE(f, E, names) .get = [](const WorldSettings& s) { return double(static_cast<int>(s.f)); }, \
                            .set = [](WorldSettings& s, double v) { s.f = static_cast<E>(static_cast<int>(v)); }, \
                            .choices = &names

using T = ParameterType;
constexpr auto Log = SliderScale::Log;

constexpr double kBig = 1e7; // px, px/s, px/s²: far beyond any scene, far inside a double

const Parameter kParameters[] = {
    // world
    {.key = "world.width", .label = "Box width", .unit = "px", .lo = 0, .hi = kBig, .loOpen = true,
     .sliderLo = 100, .sliderHi = 2000, .help = "Width of the box the balls live in.", FIELD(box.width),
     .control = "box_width"},
    {.key = "world.height", .label = "Box height", .unit = "px", .lo = 0, .hi = kBig, .loOpen = true,
     .sliderLo = 100, .sliderHi = 2000, .help = "Height of the box; y points down.", FIELD(box.height),
     .control = "box_height"},
    {.key = "world.wall_model", .label = "Wall model", .type = T::Choice,
     .help = "How a ball that crossed a wall is put back: clamp, mirror, exact (time of impact) or reverse.",
     CHOICE(walls.model, WallModel, wallModelNames), .control = "wall_model"},
    {.key = "world.restitution", .label = "Wall restitution", .lo = 0, .hi = 1, .sliderLo = 0, .sliderHi = 1,
     .help = "Share of the speed into a wall that a bounce keeps: 1 loses nothing, 0 stops the ball.",
     FIELD(walls.restitution), .control = "wall_restitution"},
    {.key = "world.middle_wall", .label = "Middle wall", .type = T::Boolean, .hi = 1,
     .help = "A wall down the middle of the box; each ball stays on its side.", SWITCH(walls.middle),
     .control = "middle_wall"},
    {.key = "world.centre_only", .label = "Test the centre only", .type = T::Boolean, .hi = 1,
     .help = "The wall test uses the ball's centre instead of its edge (stage 3's bug).", SWITCH(walls.centreOnly),
     .control = "centre_only"},
    {.key = "world.walls.left", .label = "Left wall", .type = T::Boolean, .hi = 1,
     .help = "A wall at x = 0 (in lesson files: \"left\" in the walls list).", SWITCH(walls.left),
     .control = "wall_left"},
    {.key = "world.walls.right", .label = "Right wall", .type = T::Boolean, .hi = 1,
     .help = "A wall at x = width.", SWITCH(walls.right), .control = "wall_right"},
    {.key = "world.walls.top", .label = "Top wall", .type = T::Boolean, .hi = 1, .help = "A wall at y = 0.",
     SWITCH(walls.top), .control = "wall_top"},
    {.key = "world.walls.bottom", .label = "Floor", .type = T::Boolean, .hi = 1, .help = "A wall at y = height.",
     SWITCH(walls.bottom), .control = "wall_bottom"},
    // time
    {.key = "time.integrator", .label = "Integrator", .type = T::Choice,
     .help = "The method that moves the balls through one step.",
     CHOICE(time.integrator, IntegratorKind, integratorNames), .control = "integrator",
     .alias = [](std::string_view n) { return n == "reference" ? static_cast<int>(IntegratorKind::Ias15) : -1; }},
    {.key = "time.dt", .label = "Step dt", .unit = "s", .lo = 0, .hi = 1, .loOpen = true, .sliderLo = 1e-4,
     .sliderHi = 0.1, .scale = Log, .help = "Simulated time of one step.", FIELD(time.dt), .control = "dt"},
    {.key = "time.substeps", .label = "Sub-steps", .type = T::Integer, .lo = 1, .hi = 1000, .sliderLo = 1,
     .sliderHi = 1000, .scale = Log, .help = "Each step is split into this many equal sub-steps.",
     WHOLE(time.substeps), .control = "substeps"},
    {.key = "time.tolerance", .label = "Tolerance", .lo = 1e-15, .hi = 1, .sliderLo = 1e-12, .sliderHi = 1e-2,
     .scale = Log,
     .help = "Error allowed per sub-step by the adaptive integrators (rk45, ias15); ias15 works to the rounding "
             "floor where this asks for less.",
     FIELD(time.tolerance), .control = "tolerance"},
    {.key = "time.per_frame", .label = "Move per frame", .type = T::Boolean, .hi = 1,
     .help = "Ignore dt: every step moves the balls as if 1/60 s had passed (stage 5's bug).", SWITCH(time.perFrame),
     .control = "per_frame"},
    {.key = "time.step_past_close_passes", .label = "Step past close passes", .type = T::Boolean, .hi = 1,
     .help = "Let a fixed step jump past a close pass it cannot follow instead of stopping there (stage 17's "
             "slingshot bug).",
     SWITCH(time.stepPastClosePasses), .control = "close_passes"},
    // models
    {.key = "models.gravity.enabled", .label = "Gravity", .type = T::Boolean, .hi = 1,
     .help = "The same downward pull on every ball.", SWITCH(gravity.enabled), .control = "gravity", .whenListed = 1},
    {.key = "models.gravity.x", .label = "g x (right)", .unit = "px/s²", .lo = -kBig, .hi = kBig, .sliderLo = -2000,
     .sliderHi = 2000, .help = "Sideways part of gravity.", FIELD(gravity.g.x()), .control = "gravity_x"},
    {.key = "models.gravity.y", .label = "g y (down)", .unit = "px/s²", .lo = -kBig, .hi = kBig, .sliderLo = -2000,
     .sliderHi = 2000, .help = "Downward part of gravity; 980 px/s² is Earth's if 1 px is 1 cm.",
     FIELD(gravity.g.y()), .control = "gravity_y"},
    {.key = "models.drag.enabled", .label = "Drag", .type = T::Boolean, .hi = 1,
     .help = "A force against the velocity.", SWITCH(drag.enabled), .control = "drag", .whenListed = 1},
    {.key = "models.drag.law", .label = "Drag law", .type = T::Choice,
     .help = "linear: F ∝ −v; quadratic: F ∝ −|v| v.", CHOICE(drag.law, DragLaw, dragLawNames),
     .control = "drag_law"},
    {.key = "models.drag.k", .label = "Drag k", .unit = "1/s (linear) or 1/px (quadratic)", .lo = 0, .hi = 1e6,
     .sliderLo = 1e-4, .sliderHi = 10, .scale = Log,
     .help = "How strong the drag is: how fast a 10 px ball slows down.", FIELD(drag.k), .control = "drag_k"},
    {.key = "models.drag.scale", .label = "Drag scaling", .type = T::Choice,
     .help = "mass: drag is a force, F = −k m(10 px) v, so a heavy ball slows down less and falls faster; "
             "none: the tutorial's model, every ball loses the same share of its speed; radius: air drag on "
             "spheres, × 10 px / r.",
     CHOICE(drag.scale, ForceScale, forceScaleNames), .control = "drag_scale"},
    {.key = "models.wind.mode", .label = "Wind", .type = T::Choice,
     .help = "off, random (a new gust every step), smoothed (a bounded random walk), noise (smooth noise) or "
             "pointer (blown by the mouse).",
     CHOICE(wind.mode, WindMode, windModeNames), .control = "wind_mode",
     .whenListed = static_cast<int>(WindMode::Random)},
    {.key = "models.wind.strength", .label = "Wind strength", .unit = "px/s²", .lo = 0, .hi = kBig, .sliderLo = 1,
     .sliderHi = 1e4, .scale = Log, .help = "Largest sideways push on a 10 px ball.", FIELD(wind.strength),
     .control = "wind_strength"},
    {.key = "models.wind.scale", .label = "Wind scaling", .type = T::Choice,
     .help = "none: every ball is pushed alike; radius: by 10 px / r; mass: as a force, by m(10 px) / m.",
     CHOICE(wind.scale, ForceScale, forceScaleNames), .control = "wind_scale"},
    {.key = "models.wind.smoothed_step", .label = "Smoothed step", .lo = 0, .hi = 1, .loOpen = true,
     .sliderLo = 1e-3, .sliderHi = 1, .scale = Log,
     .help = "Largest change of the smoothed wind per step, as a share of its strength.", FIELD(wind.smoothedStep),
     .control = "wind_smoothed_step"},
    {.key = "models.wind.frequency", .label = "Noise frequency", .unit = "Hz", .lo = 0, .hi = 1e3, .loOpen = true,
     .sliderLo = 0.01, .sliderHi = 100, .scale = Log, .help = "How fast the noise wind changes.",
     FIELD(wind.noiseFrequency), .control = "wind_frequency"},
    {.key = "models.wind.compare", .label = "Compare with", .type = T::Choice,
     .help = "A second wind computed beside the first for a second vane; it pushes nothing.",
     CHOICE(wind.compare, WindMode, windModeNames), .control = "wind_compare"},
    {.key = "models.random_accel.enabled", .label = "Random acceleration", .type = T::Boolean, .hi = 1,
     .help = "A random push on every ball, centred on zero (stage 10).", SWITCH(randomAccel.enabled),
     .control = "random_accel", .whenListed = 1},
    {.key = "models.random_accel.fixed", .label = "One value per ball", .type = T::Boolean, .hi = 1,
     .help = "Off: a new random value every step. On: each ball keeps the value it drew first.",
     SWITCH(randomAccel.fixed), .control = "random_fixed"},
    {.key = "models.random_accel.strength", .label = "Random strength", .unit = "px/s²", .lo = 0, .hi = kBig,
     .sliderLo = 1, .sliderHi = 1e4, .scale = Log, .help = "Largest value of each component.",
     FIELD(randomAccel.strength), .control = "random_strength"},
    {.key = "models.random_accel.uncentred", .label = "Un-centred (0 to strength)", .type = T::Boolean, .hi = 1,
     .help = "The course's Math.random() bug: each component is drawn in [0, strength) instead of [−strength, "
             "strength), so every ball drifts right and down at strength/2 on average.",
     SWITCH(randomAccel.uncentred), .control = "random_uncentred"},
    {.key = "models.point.enabled", .label = "Point force", .type = T::Boolean, .hi = 1,
     .help = "An inverse-square pull or push from a fixed point.", SWITCH(point.enabled), .control = "point", .whenListed = 1},
    {.key = "models.point.kind", .label = "Point kind", .type = T::Choice, .help = "attract or repel.",
     CHOICE(point.kind, PointKind, pointKindNames), .control = "point_kind"},
    {.key = "models.point.x", .label = "Point x", .unit = "px", .lo = -kBig, .hi = kBig, .sliderLo = 0,
     .sliderHi = 1000, .help = "Where the point is, across.", FIELD(point.position.x()), .control = "point_x"},
    {.key = "models.point.y", .label = "Point y", .unit = "px", .lo = -kBig, .hi = kBig, .sliderLo = 0,
     .sliderHi = 1000, .help = "Where the point is, down.", FIELD(point.position.y()), .control = "point_y"},
    {.key = "models.point.strength", .label = "Point strength", .unit = "px³/s²", .lo = 0, .hi = 1e15,
     .sliderLo = 1e3, .sliderHi = 1e9, .scale = Log, .help = "S in a = S / d² for a 10 px ball.",
     FIELD(point.strength), .control = "point_strength"},
    {.key = "models.point.max_accel", .label = "Point clamp (0 = off)", .unit = "px/s²", .lo = 0, .hi = 1e9,
     .sliderLo = 10, .sliderHi = 1e6, .scale = Log, .help = "The point's pull is never more than this near it.",
     FIELD(point.maxAccel), .control = "point_clamp"},
    {.key = "models.point.scale", .label = "Point scaling", .type = T::Choice,
     .help = "none, radius or mass, as for the wind.", CHOICE(point.scale, ForceScale, forceScaleNames),
     .control = "point_scale"},
    {.key = "models.point.unnormalised", .label = "Un-normalised (S d / d²)", .type = T::Boolean, .hi = 1,
     .help = "The course's repulsion bug: the difference vector d times S / d² instead of its unit vector, so "
             "|a| = S / d, a 1/d law, not S / d².",
     SWITCH(point.unnormalised), .control = "point_unnormalised"},
    {.key = "models.spring.enabled", .label = "Spring", .type = T::Boolean, .hi = 1,
     .help = "Every ball tied to one anchor by a spring (Hooke's law).", SWITCH(spring.enabled),
     .control = "spring", .whenListed = 1},
    {.key = "models.spring.x", .label = "Anchor x", .unit = "px", .lo = -kBig, .hi = kBig, .sliderLo = 0,
     .sliderHi = 1000, .help = "Where the springs are tied, across.", FIELD(spring.anchor.x()),
     .control = "spring_x"},
    {.key = "models.spring.y", .label = "Anchor y", .unit = "px", .lo = -kBig, .hi = kBig, .sliderLo = 0,
     .sliderHi = 1000, .help = "Where the springs are tied, down.", FIELD(spring.anchor.y()), .control = "spring_y"},
    {.key = "models.spring.k", .label = "Spring k", .unit = "1/s²", .lo = 0, .hi = 1e6, .sliderLo = 0.01,
     .sliderHi = 1e3, .scale = Log, .help = "Stiffness per unit mass: a = −k (x − anchor), so ω = √k.",
     FIELD(spring.k), .control = "spring_k"},
    {.key = "models.mutual_gravity.enabled", .label = "Gravity between balls", .type = T::Boolean, .hi = 1,
     .help = "Every pair of balls pulls together (or pushes apart for G < 0).", SWITCH(mutualGravity.enabled),
     .control = "mutual_gravity", .whenListed = 1},
    {.key = "models.mutual_gravity.G", .label = "G", .unit = "px³/(mass·s²)", .lo = -1e12, .hi = 1e12,
     .sliderLo = 1, .sliderHi = 1e8, .scale = Log, .help = "The constant in F = G m₁ m₂ / r².",
     FIELD(mutualGravity.G), .control = "mutual_g"},
    {.key = "models.mutual_gravity.softening", .label = "Softening ε", .unit = "px", .lo = 0, .hi = 1e6,
     .sliderLo = 0.1, .sliderHi = 100, .scale = Log,
     .help = "ε in F = G m₁ m₂ r / (r² + ε²)^(3/2): the pull fades smoothly to zero inside ε.",
     FIELD(mutualGravity.softening), .control = "mutual_softening"},
    {.key = "models.homing.enabled", .label = "Homing", .type = T::Boolean, .hi = 1,
     .help = "Each ball tied by a spring to the home of its colour.", SWITCH(homing.enabled), .control = "homing", .whenListed = 1},
    {.key = "models.homing.strength", .label = "Homing strength", .unit = "1/s²", .lo = 0, .hi = 1e6,
     .sliderLo = 0.01, .sliderHi = 1e3, .scale = Log, .help = "Stiffness of the spring to home, per unit mass.",
     FIELD(homing.strength), .control = "homing_strength"},
    {.key = "models.pointer.enabled", .label = "Pointer force", .type = T::Boolean, .hi = 1,
     .help = "The mouse pointer pulls (hover) or pushes (pressed).", SWITCH(pointer.enabled), .control = "pointer", .whenListed = 1},
    {.key = "models.pointer.strength", .label = "Pointer strength", .unit = "px³/s²", .lo = 0, .hi = 1e15,
     .sliderLo = 1e3, .sliderHi = 1e9, .scale = Log, .help = "S in a = S / d².", FIELD(pointer.strength),
     .control = "pointer_strength"},
    {.key = "models.pointer.max_accel", .label = "Pointer clamp (0 = off)", .unit = "px/s²", .lo = 0, .hi = 1e9,
     .sliderLo = 10, .sliderHi = 1e6, .scale = Log, .help = "The pointer's pull is never more than this.",
     FIELD(pointer.maxAccel), .control = "pointer_clamp"},
    {.key = "models.magnetic.enabled", .label = "Magnetic field", .type = T::Boolean, .hi = 1,
     .help = "A field out of the screen that turns every moving charge, F = q v × B, without changing its speed.",
     SWITCH(magnetic.enabled), .control = "magnetic", .whenListed = 1},
    {.key = "models.magnetic.B", .label = "Field B", .unit = "rad/s", .lo = -1e6, .hi = 1e6, .sliderLo = -20,
     .sliderHi = 20,
     .help = "How fast a 10 px ball of charge 1 turns: ω = q B m(10 px) / m; negative turns the other way.",
     FIELD(magnetic.B), .control = "magnetic_b"},
    {.key = "models.custom.enabled", .label = "Custom force", .type = T::Boolean, .hi = 1,
     .help = "A force law written as formulas of x, y, vx, vy, m, r, q, t, W, H and named constants (the Force editor).",
     SWITCH(custom.enabled), .control = "custom", .whenListed = 1},
    {.key = "models.custom.acceleration", .label = "Formulas give a, not F", .type = T::Boolean, .hi = 1,
     .help = "On: the formulas are the acceleration (px/s²), the same for every mass; off: the force, divided by m.",
     SWITCH(custom.acceleration), .control = "custom_acceleration"},
    {.key = "models.speed_limit.enabled", .label = "Speed limit", .type = T::Boolean, .hi = 1,
     .help = "No ball moves faster than the limit (a stand-in for terminal velocity).", SWITCH(speedLimit.enabled),
     .control = "speed_limit_on", .whenListed = 1},
    {.key = "models.speed_limit.max", .label = "Largest speed", .unit = "px/s", .lo = 0, .hi = 1e9, .loOpen = true,
     .sliderLo = 10, .sliderHi = 1e5, .scale = Log, .help = "The limit.", FIELD(speedLimit.max),
     .control = "speed_limit"},
    {.key = "models.collisions.detection", .label = "Detection", .type = T::Choice,
     .help = "How touching pairs are found: brute, halved, sweep or grid.",
     CHOICE(collisions.detection, Detection, detectionNames), .control = "detection"},
    {.key = "models.collisions.response", .label = "Response", .type = T::Choice,
     .help = "What a touching pair does: none, flag, 1d-reverse, 1d-elastic, 2d-axis or 2d-impulse.",
     CHOICE(collisions.response, Response, responseNames), .control = "response",
     .whenListed = static_cast<int>(Response::Impulse2D)},
    {.key = "models.collisions.restitution", .label = "Ball restitution", .lo = 0, .hi = 1, .sliderLo = 0,
     .sliderHi = 1, .help = "Share of the approach speed a collision gives back.", FIELD(collisions.restitution),
     .control = "ball_restitution"},
    {.key = "models.collisions.continuous", .label = "Continuous", .type = T::Boolean, .hi = 1,
     .help = "Find the moment of impact inside the step.", SWITCH(collisions.continuous),
     .control = "continuous"},
    {.key = "models.collisions.resting", .label = "Resting contacts", .type = T::Boolean, .hi = 1,
     .help = "Under gravity, solve a pile's contacts several times per step so it stands.",
     SWITCH(collisions.resting), .control = "resting"},
};

#undef FIELD
#undef WHOLE
#undef SWITCH
#undef CHOICE

bool inside(const Parameter& p, double v)
{
    return (p.loOpen ? v > p.lo : v >= p.lo) && (p.hiOpen ? v < p.hi : v <= p.hi);
}

} // namespace

std::span<const Parameter> parameters() { return kParameters; }

const Parameter* findParameter(std::string_view key)
{
    for (const Parameter& p : kParameters)
        if (p.key == key)
            return &p;
    return nullptr;
}

const Parameter* findControl(std::string_view control)
{
    for (const Parameter& p : kParameters)
        if (p.control == control)
            return &p;
    return nullptr;
}

std::vector<const Parameter*> sectionRows(std::string_view section)
{
    std::vector<const Parameter*> out;
    for (const Parameter& p : kParameters)
        if (p.key.size() > section.size() && p.key.substr(0, section.size()) == section &&
            p.key[section.size()] == '.' && p.key.find('.', section.size() + 1) == std::string_view::npos)
            out.push_back(&p);
    return out;
}

std::string_view rowName(const Parameter& p)
{
    return p.key.substr(p.key.rfind('.') + 1);
}

int choiceIndex(const Parameter& p, std::string_view name)
{
    const auto names = p.choices();
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == name)
            return static_cast<int>(i);
    return p.alias ? p.alias(name) : -1;
}

std::string rangeText(const Parameter& p)
{
    switch (p.type) {
    case ParameterType::Boolean:
        return "true or false";
    case ParameterType::Choice:
        return "one of " + joinNames(p.choices());
    case ParameterType::Number:
    case ParameterType::Integer:
        break;
    }
    return rangeText(p.lo, p.hi, p.unit, p.loOpen, p.hiOpen);
}

std::optional<std::string> checkValue(const Parameter& p, double v)
{
    if (!std::isfinite(v))
        return numberText(v) + " is not a finite number";
    switch (p.type) {
    case ParameterType::Boolean:
        if (v != 0.0 && v != 1.0)
            return numberText(v) + " is not true (1) or false (0)";
        return std::nullopt;
    case ParameterType::Choice:
        if (std::floor(v) != v || v < 0 || v >= static_cast<double>(p.choices().size()))
            return numberText(v) + " is not one of " + joinNames(p.choices());
        return std::nullopt;
    case ParameterType::Integer:
        if (std::floor(v) != v)
            return numberText(v) + " is not a whole number";
        break;
    case ParameterType::Number:
        break;
    }
    if (!inside(p, v))
        return numberText(v) + " is outside " + rangeText(p);
    return std::nullopt;
}

double defaultValue(const Parameter& p)
{
    return p.get(WorldSettings{});
}

} // namespace forcelab::sim
