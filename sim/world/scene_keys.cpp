#include "sim/world/scene_keys.h"

#include "sim/world/number_text.h"

#include <charconv>
#include <cmath>

namespace forcelab::sim {

namespace {

struct Target {
    double* number = nullptr; ///< a ball's field
    int* integer = nullptr;   ///< spawn.count
    std::uint64_t* seed = nullptr;
    double lo = 0.0, hi = 0.0;
    bool* flag = nullptr;     ///< a switch: 0 or 1
};

std::optional<std::string> find(Scene& scene, std::string_view key, Target& t)
{
    if (key.starts_with("spawn.")) {
        const std::string_view field = key.substr(6);
        if (field == "count") {
            t.integer = &scene.spawn.count;
            t.lo = 0.0;
            t.hi = double(kMaxBalls) - double(scene.balls.size());
            return std::nullopt;
        }
        if (field == "seed") {
            t.seed = &scene.spawn.seed;
            t.lo = 0.0;
            t.hi = 9007199254740992.0; // 2^53: exact as a double
            return std::nullopt;
        }
        SpawnSettings& s = scene.spawn;
        constexpr double kFastest = 1e7; // px/s, as the lesson file allows
        if (field == "speed.0")
            t = {&s.minSpeed, nullptr, nullptr, 0.0, kFastest};
        else if (field == "speed.1")
            t = {&s.maxSpeed, nullptr, nullptr, 0.0, kFastest};
        else if (field == "radius.0")
            t = {&s.minRadius, nullptr, nullptr, kMinRadius, kMaxRadius};
        else if (field == "radius.1")
            t = {&s.maxRadius, nullptr, nullptr, kMinRadius, kMaxRadius};
        else if (field == "fully_inside")
            t = {nullptr, nullptr, nullptr, 0.0, 1.0, &s.fullyInside};
        else if (field == "horizontal")
            t = {nullptr, nullptr, nullptr, 0.0, 1.0, &s.horizontal};
        else
            return "the random balls' keys are spawn.count, spawn.seed, spawn.speed.0 and .1 (slowest and fastest), "
                   "spawn.radius.0 and .1, spawn.fully_inside and spawn.horizontal";
        return std::nullopt;
    }
    if (!key.starts_with("balls."))
        return "not a scene key (balls.N.field or spawn.count)";
    key.remove_prefix(6);
    const std::size_t dot = key.find('.');
    int index = -1;
    const auto [end, ec] = std::from_chars(key.data(), key.data() + (dot == std::string_view::npos ? key.size() : dot), index);
    if (dot == std::string_view::npos || ec != std::errc() || end != key.data() + dot || index < 0)
        return "a ball's key is balls.N.field, N its index in the lesson's list";
    if (index >= int(scene.balls.size()))
        return "the lesson lists " + std::to_string(scene.balls.size()) + " balls, so there is no listed ball " +
               std::to_string(index);
    Ball& b = scene.balls[std::size_t(index)];
    const std::string_view field = key.substr(dot + 1);
    constexpr double kFar = 1e7;
    if (field == "x")
        t = {&b.position.x(), nullptr, nullptr, -kFar, kFar};
    else if (field == "y")
        t = {&b.position.y(), nullptr, nullptr, -kFar, kFar};
    else if (field == "vx")
        t = {&b.velocity.x(), nullptr, nullptr, -kFar, kFar};
    else if (field == "vy")
        t = {&b.velocity.y(), nullptr, nullptr, -kFar, kFar};
    else if (field == "r")
        t = {&b.radius, nullptr, nullptr, kMinRadius, kMaxRadius};
    else if (field == "mass")
        t = {&b.mass, nullptr, nullptr, kMinMass, kMaxMass};
    else if (field == "charge")
        t = {&b.charge, nullptr, nullptr, -kMaxCharge, kMaxCharge};
    else
        return "a ball's fields are x, y, vx, vy, r, mass and charge";
    return std::nullopt;
}

} // namespace

std::optional<std::string> setSceneKey(Scene& scene, std::string_view key, double value)
{
    Target t;
    if (auto problem = find(scene, key, t))
        return problem;
    if (!std::isfinite(value) || value < t.lo || value > t.hi)
        return numberText(value) + " is outside " + rangeText(t.lo, t.hi);
    if ((t.integer || t.seed) && value != std::floor(value))
        return numberText(value) + " is not a whole number";
    if (t.flag && value != 0.0 && value != 1.0)
        return numberText(value) + " is not a switch (true or false)";
    if (t.number)
        *t.number = value;
    else if (t.integer)
        *t.integer = int(value);
    else if (t.flag)
        *t.flag = value != 0.0;
    else
        *t.seed = std::uint64_t(value);
    return std::nullopt;
}

std::optional<std::string> checkSpawnRanges(const SpawnSettings& spawn)
{
    if (spawn.minSpeed > spawn.maxSpeed)
        return "the slowest speed, spawn.speed.0 = " + numberText(spawn.minSpeed) + " px/s, is above the fastest, " +
               numberText(spawn.maxSpeed) + " px/s";
    if (spawn.minRadius > spawn.maxRadius)
        return "the smallest radius, spawn.radius.0 = " + numberText(spawn.minRadius) + " px, is above the largest, " +
               numberText(spawn.maxRadius) + " px";
    return std::nullopt;
}

bool isSceneKey(std::string_view key) { return key.starts_with("balls.") || key.starts_with("spawn."); }

} // namespace forcelab::sim
