#pragma once
// The limits of a lesson file: sizes that keep a hostile file from exhausting
// memory or time, and the allowed range of the numbers that are not world
// settings (balls, spawning). The settings' ranges are the rows of
// sim/world/parameters.cpp, which the reader walks.

#include "sim/world/ball_state.h"

#include <QString>

#include <cstdint>

namespace forcelab::lessons {

inline constexpr qint64 kMaxFileBytes = 16 * 1024 * 1024; ///< bytes
inline constexpr int kMaxDepth = 32;            ///< nesting of objects and arrays
using sim::kMaxBalls;                           ///< listed balls + spawned balls
inline constexpr int kMaxListEntries = 1000;    ///< challenges, controls, overlays
inline constexpr int kMaxPaletteColours = 256;
inline constexpr int kMaxErrors = 100;          ///< further problems are counted, not listed
inline constexpr int kFormat = 1;
/// "student_code": at most this many files of at most this many characters each.
inline constexpr int kMaxStudentFiles = 64;
inline constexpr int kMaxStudentFileChars = 64 * 1024;
/// Sub-steps one claim may run (the longest shipped claim takes 18,000), so
/// that `check` and the Predict panel finish in seconds.
inline constexpr double kMaxClaimSteps = 1e6;
/// Seeds written as JSON numbers must be exact doubles; larger seeds are written as strings.
inline constexpr std::uint64_t kMaxNumberSeed = std::uint64_t{1} << 53;

/// A closed or half-open interval of allowed values, with the unit for messages.
struct Range {
    double lo;
    double hi;
    bool loOpen = false;
    bool hiOpen = false;
    const char* unit = "";

    bool contains(double v) const
    {
        return (loOpen ? v > lo : v >= lo) && (hiOpen ? v < hi : v <= hi);
    }
    QString text() const;
};

namespace range {
inline constexpr Range kUnit{0.0, 1.0, false, false, ""};
inline constexpr Range kBallPosition{-1e7, 1e7, false, false, "px"};
inline constexpr Range kBallVelocity{-1e7, 1e7, false, false, "px/s"};
inline constexpr Range kRadius{sim::kMinRadius, sim::kMaxRadius, false, false, "px"};
inline constexpr Range kMass{sim::kMinMass, sim::kMaxMass, false, false, "mass units"};
/// Density of a listed ball: its mass is density × (4/3) π r³ (1: the default).
inline constexpr Range kDensity{1e-12, 1e12, false, false, ""};
inline constexpr Range kCharge{-sim::kMaxCharge, sim::kMaxCharge, false, false, "charge units"};
inline constexpr Range kSpawnSpeed{0.0, 1e7, false, false, "px/s"};
inline constexpr Range kClaimTime{0.0, 3600.0, false, false, "s"};       ///< a claim's `at`
inline constexpr Range kClaimNumber{-1e15, 1e15, false, false, ""};     ///< a claim's stated value
inline constexpr Range kClaimTolerance{0.0, 1e15, false, false, ""};    ///< a claim's `within`
inline constexpr Range kPercent{0.0, 100.0, false, false, "%"};
/// "units": the SI scale; beyond these a shown number is nothing a class reads.
inline constexpr Range kPxPerMetre{1e-9, 1e9, false, false, "px per m"};
inline constexpr Range kKgPerMass{1e-9, 1e9, false, false, "kg per mass unit"};
} // namespace range

namespace intrange {
inline constexpr int kStageLo = 0, kStageHi = 99;
} // namespace intrange

} // namespace forcelab::lessons
