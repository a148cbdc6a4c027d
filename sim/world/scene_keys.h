#pragma once
// Key paths into a scene beyond its world settings, for a claim's "set": one
// listed ball's start ("balls.2.vx") and the random balls' count, seed,
// speed and radius ranges and switches ("spawn.count", "spawn.speed.1",
// "spawn.fully_inside"), named as in the lesson file. A claim such as "with the tip ball 200 px higher, …" runs
// the scene it describes. World settings are the rows of sim/world/parameters.h.

#include "sim/world/scene.h"

#include <optional>
#include <string>
#include <string_view>

namespace forcelab::sim {

/// Sets `value` at `key` in `scene`; or, leaving the scene as it was, says
/// why it cannot (the key names nothing, the ball does not exist, the value
/// is outside the field's range).
std::optional<std::string> setSceneKey(Scene& scene, std::string_view key, double value);

/// Why the random balls' ranges cannot be drawn from (a slowest speed above
/// the fastest, a smallest radius above the largest), or nothing: checked
/// once all of a claim's keys are set, since one key alone may pass through
/// such a state.
std::optional<std::string> checkSpawnRanges(const SpawnSettings& spawn);

/// Whether `key` has the form of a scene key (it starts "balls." or "spawn."),
/// whatever its ball or field.
bool isSceneKey(std::string_view key);

} // namespace forcelab::sim
