#pragma once
// A student's own JavaScript run beside the engine. The course's pieces
// (lessons/code/*.js) are loaded as usual, except the files the student has
// rewritten, whose text is theirs; the run starts from the live world as it
// is (ScriptWorld::loadFrom: balls, clock and random generators) and takes
// one step after each of the live world's steps, so the two can be compared
// step by step. The first step at which a ball's x, y, vx or vy departs
// from the engine's beyond the tolerance is kept: where it happened and by
// how much. A script error or an endless loop stops the run with a message.
#include "sim/world/world.h"
#include "ui/script/script_world.h"

#include <QMap>
#include <QString>

#include <cstdint>
#include <optional>

namespace forcelab {

/// The student's files: piece name ("walls.js") → their text.
using ScriptEdits = QMap<QString, QString>;

/// The first difference between the student's run and the engine's.
struct ScriptDeparture {
    std::int64_t step = 0;   ///< the live world's step count when it showed
    double time = 0.0;       ///< s
    int ball = -1;           ///< -1: the two hold different numbers of balls
    QString field;           ///< "x", "y", "vx" or "vy"
    double reference = 0.0;  ///< the engine's value (px or px/s)
    double student = 0.0;    ///< the student's
    sim::Vec2 referencePosition{0, 0}; ///< px, the ball where the engine has it
    sim::Vec2 studentPosition{0, 0};   ///< px, and where the student's code has it
    double size() const { return std::abs(student - reference); }
};

class StudentRun {
public:
    /// |student − engine| ≤ tolerance · max(1, |engine|) counts as agreeing
    /// (the course's code agrees to 0; a rounding in another order to ~1e-13).
    static constexpr double kTolerance = 1e-9;

    explicit StudentRun(ScriptEdits edits);

    const ScriptEdits& edits() const { return m_edits; }
    /// Starts again from `world` as it is now; forgets the departure. A load
    /// error (a syntax error in the student's file) stops the run.
    void restart(const sim::World& world);
    /// The live world just took a step: the student's code takes one too, and
    /// the two are compared. Nothing after an error.
    void follow(const sim::World& reference);
    void setPointer(const sim::PointerInput& pointer);

    /// Why the run stopped (its file, line and message), if it did.
    const std::optional<ScriptError>& error() const { return m_error; }
    const std::optional<ScriptDeparture>& departure() const { return m_departure; }
    /// Steps taken since the last restart.
    std::int64_t steps() const { return m_steps; }
    /// px, the largest distance between a ball and its reference now.
    double separation() const { return m_separation; }

    /// Writes the student's balls into `mirror` (positions, velocities, radii
    /// and masses), so a world painter and World::energy() can use it; when
    /// a ball appeared in both runs, the mirror first takes `reference`'s
    /// balls (colours). False when the student's count matches neither (then
    /// `mirror` is left as it was).
    bool copyInto(const sim::World& reference, sim::World& mirror) const;

private:
    ScriptEdits m_edits;
    ScriptWorld m_script;
    std::optional<ScriptError> m_error;
    std::optional<ScriptDeparture> m_departure;
    std::int64_t m_steps = 0;
    double m_separation = 0.0;
};

} // namespace forcelab
