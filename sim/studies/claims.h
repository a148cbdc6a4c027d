#pragma once
// Claims: what a lesson's text says about its scene, as something a machine
// can measure. A claim names a measurement from the table below (one row per
// measurement: name, unit, what it means), the ball and the time it is about,
// and the number the text states with its tolerance, or a bound. check()
// runs the scene in a world of its own and says whether the claim holds.

#include "sim/world/scene.h"

#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace forcelab::sim {

/// How the measured number is compared with the claim's value.
enum class ClaimTest {
    Near,  ///< |measured − value| ≤ tolerance (or ≤ tolerance × |value| when relative)
    Below, ///< measured < value
    Above, ///< measured > value
};

/// When a measurement is taken.
enum class MeasureWhen {
    At,      ///< at the moment `at`
    OverRun, ///< over the whole run from 0 to `at` (a largest or smallest value)
    Event,   ///< at the n-th event (an apex, a turning point) before `at`
};

struct Claim {
    std::string text;       ///< the lesson's sentence this claim checks, in the lesson's words
    std::string measure;    ///< a name of claimMeasures(): "apex", "period", "energy_drift", …
    int ball = 0;           ///< the ball measured, for measurements of one ball
    int other = 1;          ///< the second ball, for "distance" and "acceleration_ratio"
    double at = 1.0;        ///< s: the moment (At), the length of the run (OverRun) or the latest time for the event (Event)
    int occurrence = 1;     ///< Event: which one, 1 for the first
    char axis = 'y';        ///< 'x' or 'y': the coordinate of position, velocity, turning points and period
    double distance = 10.0; ///< px: how close to a wall counts as "at the wall" (near_wall)
    ClaimTest test = ClaimTest::Near;
    double value = 0.0;     ///< the number the text states, in the measurement's unit
    double tolerance = 0.0; ///< Near: the allowed difference (the measurement's unit, or a fraction when relative)
    bool relative = false;  ///< Near: tolerance is a fraction of |value|
    /// Changes to the scene's settings before it runs ("with resting contacts
    /// off, …"): key paths of sim/world/parameters.h and their values (a choice by
    /// its index, a switch as 0 or 1), or of sim/world/scene_keys.h ("balls.0.y",
    /// "spawn.count").
    std::vector<std::pair<std::string, double>> set;

    friend bool operator==(const Claim&, const Claim&) = default;
};

/// One row of the measurement table.
struct ClaimMeasure {
    std::string_view name;
    std::string_view unit; ///< "px", "px/s", "s", "1" (a ratio), "balls", "hits"
    MeasureWhen when;
    bool perBall;          ///< it is about `ball` (and `other`)
    std::string_view doc;  ///< what it measures, for docs/lessons.md and errors
};

/// Every measurement a claim can name.
std::span<const ClaimMeasure> claimMeasures();
const ClaimMeasure* findClaimMeasure(std::string_view name);

struct ClaimResult {
    bool holds = false;
    bool cancelled = false;  ///< the progress callback stopped the run; nothing was measured
    double measured = 0.0;   ///< NaN when it could not be measured (the event never came)
    std::string explanation; ///< "measured 191.8 px, stated 192 px ± 1 px" or why it could not be measured
};

/// Runs `scene` from t = 0 in a world of its own and checks the claim. A
/// claim about a ball that does not exist, or an event that does not happen
/// before `at`, does not hold (and the explanation says so).
/// `progress`, when given, is called after every step with the share of the
/// run done (0 to 1); returning false stops the run, and the result is
/// `cancelled` (the workbench's Predict panel runs claims on a worker
/// thread with a Cancel button).
using ClaimProgress = std::function<bool(double done)>;
ClaimResult checkClaim(const Scene& scene, const Claim& claim, const ClaimProgress& progress = {});

/// The claim as a line of a report: "holds: <text> (measured …)".
std::string describe(const Claim& claim, const ClaimResult& result);

} // namespace forcelab::sim
