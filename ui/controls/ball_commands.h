#pragma once
// The undo steps of ball edits made by hand (SettingsEditor's editBall,
// addBall and removeBall): change some fields of one ball, add a ball, remove
// one. Like the settings commands, each applies itself in redo(), so pushing
// it is the edit. A change writes only the fields it edits, so undoing a new
// mass while the ball flies on puts back the mass and leaves its path alone;
// undone at once, every field is back bit for bit. One drag of a ball, of its
// arrow or of a slider merges into one step. Made in the past (after a
// rewind), an edit starts a new future; its undo brings back the old one.

#include "sim/world/ball_state.h"

#include <QUndoCommand>

#include <functional>

namespace forcelab {

class SimulationController;

/// The fields of a ball an edit changes (a bit set).
enum BallField : unsigned {
    kBallPosition = 1u << 0,
    kBallVelocity = 1u << 1,
    kBallRadius = 1u << 2,
    kBallMass = 1u << 3,
    kBallCharge = 1u << 4,
    kBallColour = 1u << 5,
    kBallRestitution = 1u << 6, ///< its own restitution (or kWorldRestitution)
    kBallPinned = 1u << 7,      ///< written after the others: pinning zeroes the velocity
    kBallAllFields = (1u << 8) - 1,
};

/// Writes the `fields` of `ball` into ball `index` of `balls`.
void writeBallFields(sim::BallState& balls, int index, const sim::Ball& ball, unsigned fields);
/// Copies the `fields` of `from` into `to`.
void copyBallFields(sim::Ball& to, const sim::Ball& from, unsigned fields);

class BallCommand : public QUndoCommand {
public:
    enum class Kind {
        Change, ///< ball `index`'s `fields` go from `before` to `after`
        Add,    ///< `after` is inserted at `index`
        Remove, ///< ball `index` (which is `before`) is removed
    };
    /// `mergeId` ≥ 0 merges a Change with the previous one of the same id,
    /// ball, fields and `session` (one drag); −1 never merges.
    BallCommand(SimulationController* controller, Kind kind, const QString& text, int index,
                const sim::Ball& before, const sim::Ball& after, unsigned fields, int mergeId = -1, int session = 0);

    void undo() override;
    void redo() override;
    int id() const override { return m_kind == Kind::Change ? m_mergeId : -1; }
    bool mergeWith(const QUndoCommand* other) override;

    /// Called after every insertion or removal (redo, undo): the indices
    /// after it moved, so views kept by index start over.
    void onCountChanged(std::function<void()> callback) { m_countChanged = std::move(callback); }

    Kind kind() const { return m_kind; }
    int index() const { return m_index; }

private:
    void undoEdit();
    void redoEdit();
    void change(const sim::Ball& to);
    void insert(const sim::Ball& ball);
    void remove();

    SimulationController* m_controller; // not owned
    Kind m_kind;
    int m_index;
    sim::Ball m_before;
    sim::Ball m_after;
    unsigned m_fields;
    int m_mergeId;
    int m_session;
    std::function<void()> m_countChanged;
    int m_undoCut = -1; // the timeline's cut holding the future this edit replaced (undo brings it back)
    int m_redoCut = -1; // the cut holding the edited future, after an undo
};

} // namespace forcelab
