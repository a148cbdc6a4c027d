#pragma once
// Checks a trace written anywhere (a student's program) against the
// reference: the first step and ball where the student's numbers depart
// beyond a tolerance, how far, and which known mistake explains them best,
// found by rerunning the reference with that mistake switched on (explicit
// Euler for the update order, the per-frame bug, the other wall rules, …)
// and seeing which run the student's numbers follow. Pure C++.

#include "sim/world/scene.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace forcelab::sim {

/// One row of a student's trace: step and ball name the state; x and y are
/// needed, vx and vy are compared when the file has them.
struct StudentRow {
    std::int64_t step = 0;
    int ball = 0;
    double x = 0.0, y = 0.0;
    std::optional<double> vx, vy;
    long line = 0; ///< where it is in the file (1-based), for messages
};

/// Where a trace first leaves another.
struct Departure {
    std::int64_t step = 0;
    int ball = 0;
    std::string field;     ///< "x", "y", "vx" or "vy"
    double student = 0.0;
    double reference = 0.0;
    double size = 0.0;     ///< |student − reference|, px or px/s
    long line = 0;
};

/// The student's rows against one run of a scene.
struct TraceMatch {
    std::optional<Departure> departure; ///< nullopt: every row within the tolerance
    std::int64_t rowsAgreeing = 0;      ///< rows (in step, ball order) before the departure
    double largestAgreeing = 0.0;       ///< largest difference among them
    std::int64_t lastStep = 0;          ///< the last step the file has
    std::optional<std::string> problem; ///< the run could not be made (a row names a ball that is not there, …)
};

/// A value departs when |student − reference| > tolerance × max(1, |reference|).
TraceMatch matchTrace(const Scene& scene, const std::vector<StudentRow>& rows, double tolerance);

/// A known mistake, as a change to the reference's settings.
struct TraceVariant {
    std::string cause;   ///< the kind of mistake: "update order", "units per frame", "wall rule", …
    std::string setting; ///< what was changed, as --set would write it
    std::string meaning; ///< what the student's program does, in a sentence
};

/// The mistakes that can be tried on this scene (those that change something).
std::vector<std::pair<TraceVariant, Scene>> traceVariants(const Scene& scene);

struct Diagnosis {
    TraceVariant variant;
    TraceMatch match;
};

/// The variant the student's rows follow furthest beyond the reference's
/// departure (ties: the closer one); nullopt when none follows them further
/// than the reference does.
std::optional<Diagnosis> diagnose(const Scene& scene, const std::vector<StudentRow>& rows, double tolerance,
                                  const TraceMatch& reference);

/// The usual causes of a departure, for when no variant explains it.
std::string usualCauses();

} // namespace forcelab::sim
