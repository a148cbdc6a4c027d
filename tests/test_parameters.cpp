// The parameter table (sim/world/parameters.h) against the settings it describes:
// each row reads and writes its own field and no other, its default is
// allowed, its key and control are unique, and the world's validation refuses
// exactly what the row's range refuses.

#include "sim_test_util.h"

#include "sim/world/names.h"
#include "sim/world/number_text.h"
#include "sim/world/parameter_reference.h"
#include "sim/world/parameters.h"
#include "sim/world/world.h"

#include "sim_check.h"

#include <cmath>
#include <limits>
#include <set>
#include <string>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

using forcelab::test::Text;

using namespace forcelab::sim;
using forcelab::test::anotherValue;

namespace {

// Every row's value in a settings struct.
std::vector<double> allValues(const WorldSettings& s)
{
    std::vector<double> out;
    for (const Parameter& p : parameters())
        out.push_back(p.get(s));
    return out;
}

} // namespace


TEST_CASE("TestParameters::keysAndControlsAreUnique")
{
    std::set<std::string_view> keys, controls;
    for (const Parameter& p : parameters()) {
        VERIFY2(keys.insert(p.key).second, p.key.data());
        VERIFY2(p.control.empty() || controls.insert(p.control).second, p.control.data());
        VERIFY(findParameter(p.key) == &p);
        VERIFY(!p.label.empty() && !p.help.empty());
        VERIFY(p.get && p.set);
        REQUIRE_SAME(p.type == ParameterType::Choice, p.choices != nullptr);
        if (p.type == ParameterType::Number || p.type == ParameterType::Integer) {
            VERIFY2(p.lo < p.hi && p.sliderLo < p.sliderHi, p.key.data());
            VERIFY2(p.sliderLo >= p.lo && p.sliderHi <= p.hi, p.key.data());
            VERIFY2(p.scale == SliderScale::Linear || p.sliderLo > 0.0, p.key.data());
        }
    }
    forcelab::test::report("%zu parameters", parameters().size());
}

// Writing one row changes that row and no other: no two rows share a field,
// and no accessor writes somewhere else than it reads.
TEST_CASE("TestParameters::eachRowOwnsOneField")
{
    const WorldSettings defaults;
    const std::vector<double> before = allValues(defaults);
    for (std::size_t i = 0; i < parameters().size(); ++i) {
        const Parameter& p = parameters()[i];
        WorldSettings s = defaults;
        const double v = anotherValue(p, before[i]);
        VERIFY2(!checkValue(p, v), p.key.data());
        p.set(s, v);
        const std::vector<double> after = allValues(s);
        for (std::size_t j = 0; j < after.size(); ++j) {
            const double expected = j == i ? v : before[j];
            VERIFY2(after[j] == expected, Text(Text("writing %1 changed %2")
                                                          .arg(p.key.data())
                                                          .arg(parameters()[j].key.data())).c_str());
        }
    }
}

TEST_CASE("TestParameters::defaultsAreAllowed")
{
    for (const Parameter& p : parameters()) {
        const auto problem = checkValue(p, defaultValue(p));
        VERIFY2(!problem, Text(Text("%1: %2").arg(p.key.data(), problem ? problem->c_str() : "")).c_str());
    }
    VERIFY(!validateSettings(WorldSettings{}));
}

// Just outside each end of a number's range the world refuses the settings
// and names the row's key; at the end itself (when closed) it takes them.
TEST_CASE("TestParameters::validationFollowsTheRanges")
{
    for (const Parameter& p : parameters()) {
        if (p.type != ParameterType::Number && p.type != ParameterType::Integer)
            continue;
        for (const auto& [end, open, outward] : {std::tuple{p.lo, p.loOpen, -1.0}, std::tuple{p.hi, p.hiOpen, 1.0}}) {
            const double step = p.type == ParameterType::Integer ? 1.0 : std::max(std::abs(end), 1.0) * 1e-9;
            WorldSettings s;
            p.set(s, end + outward * step);
            const auto refused = validateSettings(s);
            VERIFY2(refused && refused->keyPath == p.key,
                     Text(Text("%1 = %2: %3")
                                    .arg(p.key.data())
                                    .arg(end + outward * step)
                                    .arg(refused ? toString(*refused).c_str() : "accepted")).c_str());
            WorldSettings t;
            p.set(t, end);
            REQUIRE_SAME(bool(validateSettings(t)), open);
        }
    }
}

// docs/parameters.md is what the table says today (regenerate it with
// `forcelab-cli params > docs/parameters.md`).
TEST_CASE("TestParameters::referenceIsUpToDate")
{
    std::ifstream file(FORCELAB_SOURCE_DIR "/docs/parameters.md", std::ios::binary);
    VERIFY2(file.good(), "docs/parameters.md is missing");
    const std::string onDisk((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    const std::string generated = parameterReference();
    VERIFY2(onDisk == generated, "docs/parameters.md is out of date: run forcelab-cli params > docs/parameters.md");
    for (const Parameter& p : parameters()) {
        const std::string_view name = p.key.substr(p.key.rfind('.') + 1);
        VERIFY(onDisk.find(std::string("`").append(name).append("`")) != std::string::npos);
    }
}


// The one formatter of numbers and ranges (sim/world/number_text.h), which
// sim's messages, the lesson reader's messages, the docs and saved lessons share.
TEST_CASE("TestParameters::numberAndRangeText")
{
    // Whole numbers up to 1e9 in full, others in the shortest round-trip form.
    CHECK(numberText(0.0) == "0");
    CHECK(numberText(-0.0) == "0");
    CHECK(numberText(3.0) == "3");
    CHECK(numberText(-42.0) == "-42");
    CHECK(numberText(100000.0) == "100000");
    CHECK(numberText(1e9) == "1000000000");
    CHECK(numberText(1e10) == "1e+10");
    CHECK(numberText(0.1) == "0.1");
    CHECK(numberText(0.1 + 0.2) == "0.30000000000000004");
    CHECK(numberText(1e-9) == "1e-09");
    CHECK(numberText(2.5) == "2.5");
    CHECK(numberText(1e15) == "1e+15");
    CHECK(numberText(std::numeric_limits<double>::infinity()) == "inf");
    // The saved form has no whole-number rule: 1e5 is shorter than 100000.
    CHECK(shortestText(100000.0) == "1e+05");
    CHECK(shortestText(600.0) == "600");
    CHECK(shortestText(1.0 / 3.0) == "0.3333333333333333");
    // Rounded to significant digits, as printf's %g.
    CHECK(roundedText(1.0 / 60.0, 2) == "0.017");
    CHECK(roundedText(123456.7, 4) == "1.235e+05");
    CHECK(roundedText(600.0, 6) == "600");
    CHECK(roundedText(18.1, 6) == "18.1");
    // Ranges: brackets for closed ends, parentheses for open ones, the unit after a space.
    CHECK(rangeText(0, 1) == "[0, 1]");
    CHECK(rangeText(0, 1, "s", true) == "(0, 1] s");
    CHECK(rangeText(0, 1, {}, false, true) == "[0, 1)");
    CHECK(rangeText(1e-15, 1) == "[1e-15, 1]");
    CHECK(rangeText(-1e12, 1e12, "px³/(mass·s²)") == "[-1e+12, 1e+12] px³/(mass·s²)");
    CHECK(rangeText(-1e7, 1e7, "px") == "[-10000000, 10000000] px");
    // A row's range is the same text, or its words for switches and choices.
    CHECK(rangeText(*findParameter("time.dt")) == "(0, 1] s");
    CHECK(rangeText(*findParameter("world.restitution")) == "[0, 1]");
    CHECK(rangeText(*findParameter("models.point.strength")) == "[0, 1e+15] px³/s²");
    CHECK(rangeText(*findParameter("world.middle_wall")) == "true or false");
}
