#pragma once
// One row per setting of a world, in the spirit of REBOUND's field list:
// where it lives in a lesson file (its key path), what a person calls it, its
// unit, the values it may take, how a slider moves through them, one sentence
// of help, and how to read and write it in WorldSettings. Validation, the
// lesson reader and writer, `--set`, the Parameters panel and the parameter
// reference in docs/ all walk this table, so a new setting is one row plus
// its physics.

#include "sim/world/number_text.h" // numberText, rangeText(lo, hi, …): the formatter
#include "sim/world/world_settings.h"

#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace forcelab::sim {

enum class ParameterType {
    Number,  ///< a double in [lo, hi] (open ends as flagged)
    Integer, ///< a whole number in [lo, hi]
    Boolean, ///< on or off (read and written as 1 or 0)
    Choice,  ///< one of choices() (read and written as its index)
};

enum class SliderScale { Linear, Log };

struct Parameter {
    std::string_view key{};   ///< key path in lesson files and `--set`, e.g. "models.drag.k"
    std::string_view label{}; ///< what a control shows, e.g. "Drag k"
    std::string_view unit{};  ///< e.g. "px/s²"; empty for pure numbers
    ParameterType type = ParameterType::Number;
    double lo = 0.0; ///< smallest allowed value (Number, Integer)
    double hi = 0.0; ///< largest allowed value
    bool loOpen = false; ///< lo itself is not allowed
    bool hiOpen = false; ///< hi itself is not allowed
    double sliderLo = 0.0; ///< where a slider starts; typed values may go to lo
    double sliderHi = 0.0; ///< where a slider ends; typed values may go to hi
    SliderScale scale = SliderScale::Linear;
    std::string_view help{}; ///< one sentence for tooltips and the docs
    double (*get)(const WorldSettings&) = nullptr;
    void (*set)(WorldSettings&, double) = nullptr;
    std::span<const std::string_view> (*choices)() = nullptr; ///< Choice only
    std::string_view control{}; ///< the Parameters panel's row for it (lesson `controls` name it)
    /// Choice only, optional: reads a name that is not in choices() (an alias
    /// such as "reference"); returns the index or −1.
    int (*alias)(std::string_view) = nullptr;
    /// The value a lesson file means when it lists the row's section without
    /// giving the row: a listed model is on ("gravity": {} switches gravity
    /// on), listed wind blows at random, listed collisions use 2d-impulse.
    /// NaN: the default stands.
    double whenListed = std::numeric_limits<double>::quiet_NaN();
};

/// Every row, grouped by section in reading order.
std::span<const Parameter> parameters();

/// The row for a key path, or nullptr.
const Parameter* findParameter(std::string_view key);

/// The row whose panel control is `control`, or nullptr.
const Parameter* findControl(std::string_view control);

/// The rows directly in one section, in table order: "models.drag" gives
/// enabled, law, k; "world" gives width, height, … but not world.walls.left.
std::vector<const Parameter*> sectionRows(std::string_view section);

/// The name of a row inside its section: "k" for "models.drag.k".
std::string_view rowName(const Parameter& p);

/// The index of a choice's name (or alias), or −1.
int choiceIndex(const Parameter& p, std::string_view name);

/// "[0, 1]", "(0, 1] s": the allowed values, for messages and the docs
/// ("true or false", "one of …" for switches and choices).
std::string rangeText(const Parameter& p);

/// nullopt when `value` is allowed; otherwise what is wrong ("1.5 is outside
/// [0, 1]", "2.5 is not a whole number", "7 is not one of …").
std::optional<std::string> checkValue(const Parameter& p, double value);

/// The value of a row in a default WorldSettings.
double defaultValue(const Parameter& p);

} // namespace forcelab::sim
