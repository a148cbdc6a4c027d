#pragma once
// The one way a control changes the world's settings, the random balls or the
// speed of the film. The Parameters panel, the stage's sliders and the force
// editor all edit through it: it owns the undo stack, and each edit is a
// command whose redo applies it (Qt's pattern: pushing the command is what
// applies it). An edit the controller refuses leaves no step on the stack and
// returns false, so the control that made it can go back to the world's value.

#include "sim/world/ball_state.h"
#include "sim/world/scene.h"
#include "sim/world/world_settings.h"

#include <QObject>

#include <functional>
#include <optional>

class QUndoStack;

namespace forcelab {

class SimulationController;

/// Which consecutive edits make one undo step: edits with the same id ≥ 0
/// and the same session (one slider drag) merge; −1 never merges.
struct EditMerge {
    int id = -1;
    int session = 0;
};

class SettingsEditor : public QObject {
    Q_OBJECT
public:
    explicit SettingsEditor(SimulationController* controller, QObject* parent = nullptr);

    /// Every accepted edit, for Undo / Redo (cleared with each new lesson).
    QUndoStack* undoStack() const { return m_undoStack; }

    /// Changes a copy of the world's settings with `change` and applies it as
    /// one undo step named `text`. False when the controller refused it (it
    /// has said why through errorOccurred).
    bool editSettings(const QString& text, const std::function<void(sim::WorldSettings&)>& change, EditMerge merge = {});
    /// New random balls: the world restarts. False when refused.
    bool editSpawn(const QString& text, const sim::SpawnSettings& spawn);
    /// One end of the random balls' speed range, px/s (`slowest`, or the
    /// fastest): places the balls again, one undo step. False when nothing
    /// changed or the world refused it (a slowest speed above the fastest,
    /// with its message; nothing is clamped).
    bool editSpawnSpeed(bool slowest, double speed);
    /// A new time scale; `session` ≥ 0 merges one drag into one step. False
    /// when the speed did not change (already at that speed, or out of range).
    bool editTimeScale(double scale, int session = -1);

    /// Sets the `fields` (ui/controls/ball_commands.h) of ball `index` to
    /// `after`'s as one undo step. Each number is checked against its range;
    /// a new position or radius that would put the ball in a wall or in
    /// another ball moves it to touching (said through ballEditNote). Pinning
    /// a ball stops it (its velocity is part of the step). False, with the
    /// reason said through ballEditNote, when refused.
    bool editBall(const QString& text, int index, const sim::Ball& after, unsigned fields, EditMerge merge = {});
    /// Adds `ball` as the last ball (moved to touching like editBall); its
    /// index, or −1 when refused (the ball limit, a value out of range, no room).
    int addBall(const QString& text, const sim::Ball& ball);
    /// Removes ball `index` as one undo step. False when there is no such ball.
    bool removeBall(int index);
    /// Adds a copy of ball `index` beside it (to the right, touching, or
    /// wherever the nearest free place is): the copy's index, or −1.
    int duplicateBall(int index);

signals:
    /// What a ball edit did that its maker did not ask for, or why it was
    /// refused: one sentence for the pointer or the status bar.
    void ballEditNote(const QString& message, bool refused);
    /// Balls were added or removed, by an edit or its undo or redo (the
    /// indices after them moved).
    void ballCountChanged();

private:
    /// The ball checked and placed: nullopt (and the note said) when refused.
    std::optional<sim::Ball> checkedBall(const sim::Ball& ball, int ignore, bool place);

    SimulationController* m_controller; // not owned
    QUndoStack* m_undoStack;
};

} // namespace forcelab
