#pragma once
// The limits of a lesson file: sizes that keep a hostile file from exhausting
// memory or time, and the allowed range of every number. docs/lessons.md lists
// the same numbers; the settings ranges match sim::validateSettings.

#include <QString>

#include <cstdint>

namespace forcelab::lessons {

inline constexpr qint64 kMaxFileBytes = 16 * 1024 * 1024; ///< bytes
inline constexpr int kMaxDepth = 32;            ///< nesting of objects and arrays
inline constexpr int kMaxBalls = 200000;        ///< listed balls + spawned balls
inline constexpr int kMaxListEntries = 1000;    ///< challenges, controls, overlays
inline constexpr int kMaxPaletteColours = 256;
inline constexpr int kMaxErrors = 100;          ///< further problems are counted, not listed
inline constexpr int kFormat = 1;
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
inline constexpr Range kBoxSize{0.0, 1e7, true, false, "px"};
inline constexpr Range kUnit{0.0, 1.0, false, false, ""};
inline constexpr Range kDt{0.0, 1.0, true, false, "s"};
inline constexpr Range kTolerance{1e-15, 1.0, false, false, ""};
inline constexpr Range kGravity{-1e7, 1e7, false, false, "px/s²"};
inline constexpr Range kDragK{0.0, 1e6, false, false, "1/s (linear) or 1/px (quadratic)"};
inline constexpr Range kWindStrength{0.0, 1e7, false, false, "px/s²"};
inline constexpr Range kRandomAccel{0.0, 1e7, false, false, "px/s²"};
inline constexpr Range kSmoothedStep{0.0, 1.0, true, false, ""};
inline constexpr Range kFrequency{0.0, 1e3, true, false, "Hz"};
inline constexpr Range kPosition{-1e7, 1e7, false, false, "px"};
inline constexpr Range kInverseSquare{0.0, 1e15, false, false, "px³/s²"};
inline constexpr Range kMaxAccel{0.0, 1e9, false, false, "px/s²"};
inline constexpr Range kSpringK{0.0, 1e6, false, false, "1/s²"};
inline constexpr Range kG{-1e12, 1e12, false, false, "px³/(mass·s²)"};
inline constexpr Range kSoftening{0.0, 1e6, false, false, "px"};
inline constexpr Range kHoming{0.0, 1e6, false, false, "1/s²"};
inline constexpr Range kSpeedLimit{0.0, 1e9, true, false, "px/s"};
inline constexpr Range kBallPosition{-1e7, 1e7, false, false, "px"};
inline constexpr Range kBallVelocity{-1e7, 1e7, false, false, "px/s"};
inline constexpr Range kRadius{0.0, 1e4, true, false, "px"};
inline constexpr Range kMass{0.0, 1e15, true, false, "mass units"};
inline constexpr Range kSpawnSpeed{0.0, 1e7, false, false, "px/s"};
} // namespace range

namespace intrange {
inline constexpr int kSubstepsLo = 1, kSubstepsHi = 1000;
inline constexpr int kStageLo = 0, kStageHi = 99;
} // namespace intrange

} // namespace forcelab::lessons
