#include "sim/world/parameter_reference.h"

#include "sim/world/parameters.h"

#include <string_view>

namespace forcelab::sim {
namespace {

// "models.drag.k" → section "models.drag", name "k".
std::string_view sectionOf(std::string_view key)
{
    return key.substr(0, key.rfind('.'));
}

std::string defaultText(const Parameter& p)
{
    const double v = defaultValue(p);
    switch (p.type) {
    case ParameterType::Boolean:
        return v != 0.0 ? "true" : "false";
    case ParameterType::Choice:
        return std::string("`").append(p.choices()[static_cast<std::size_t>(v)]).append("`");
    case ParameterType::Number:
    case ParameterType::Integer:
        break;
    }
    return numberText(v);
}

} // namespace

std::string parameterReference()
{
    std::string out =
        "# Parameter reference\n\n"
        "Every setting of a world: its key path in a lesson file and in `--set KEY.PATH=VALUE`, its unit, its\n"
        "value when a lesson does not give it, and the values it may take. The Parameters panel shows the same\n"
        "names and ranges. This page is written by `forcelab-cli params` from the table in `sim/world/parameters.cpp`;\n"
        "`test_parameters` fails when it is out of date.\n\n"
        "In a lesson file the walls are a list (`\"walls\": [\"left\", \"bottom\"]`), and a model's object\n"
        "switches the model on unless it says `\"enabled\": false` (see docs/lessons.md). One more setting has\n"
        "no row here because it is not a number: `time.seed`, the random seed (a whole number up to 2^64 − 1,\n"
        "written as a string above 2^53; default 1).\n";
    std::string_view section;
    for (const Parameter& p : parameters()) {
        if (sectionOf(p.key) != section) {
            section = sectionOf(p.key);
            out.append("\n## `").append(section).append("`\n\n");
            out.append("| key | label | unit | default | allowed | what it does |\n|---|---|---|---|---|---|\n");
        }
        std::string allowed = rangeText(p);
        if ((p.type == ParameterType::Number || p.type == ParameterType::Integer) && !p.unit.empty())
            allowed.resize(allowed.size() - p.unit.size() - 1); // the unit has its own column
        out.append("| `").append(p.key.substr(section.size() + 1)).append("` | ").append(p.label).append(" | ");
        out.append(p.unit).append(" | ").append(defaultText(p)).append(" | ").append(allowed).append(" | ");
        out.append(p.help).append(" |\n");
    }
    return out;
}

} // namespace forcelab::sim
