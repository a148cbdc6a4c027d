#pragma once
// The undo steps of SettingsEditor (settings_editor.h). Each holds the whole
// state before and after one edit (the settings struct, the spawn settings or
// the time scale) and applies it through the controller in redo(), so the
// first redo (QUndoStack::push) is the edit itself and undo and redo go
// through the same checks. A command whose first redo the controller refuses
// marks itself obsolete and the stack drops it. Consecutive moves of one
// slider during one drag merge into a single step.

#include "sim/world/scene.h"
#include "sim/world/world_settings.h"

#include <QUndoCommand>

namespace forcelab {

class SimulationController;

/// After an undo's own change (which may have cut the edited future),
/// brings back the future the edit cut (`undoCut`, −1 for none). Returns the
/// cut holding the edited future, for redo: the one the restore made, else
/// the undo's own.
int restoreCutFuture(SimulationController* controller, int undoCut);
/// After a redo's own change (which cut the future the undo brought back):
/// brings back the edited future (`redoCut`). Returns the cut holding the
/// other, for undo.
int restoreEditedFuture(SimulationController* controller, int redoCut);

/// A change of the world's settings.
class SettingsCommand : public QUndoCommand {
public:
    /// `mergeId` ≥ 0 merges with the previous command of the same id and
    /// `session` (one slider drag); -1 never merges.
    SettingsCommand(SimulationController* controller, const QString& text, const sim::WorldSettings& before,
                    const sim::WorldSettings& after, int mergeId = -1, int session = 0);

    /// Where the first redo writes whether the controller took the edit
    /// (the command may be merged or dropped by then); cleared after it.
    void reportTo(bool* accepted) { m_report = accepted; }

    void undo() override;
    void redo() override;
    int id() const override { return m_mergeId; }
    bool mergeWith(const QUndoCommand* other) override;

    const sim::WorldSettings& before() const { return m_before; }
    const sim::WorldSettings& after() const { return m_after; }

private:
    SimulationController* m_controller; // not owned
    sim::WorldSettings m_before;
    sim::WorldSettings m_after;
    int m_mergeId;
    int m_session;
    bool* m_report = nullptr;
    // An edit made behind the latest recorded step cuts the steps after it
    // (sim/world/timeline.h): undo brings them back, redo the edited ones.
    int m_undoCut = -1; // the future the edit cut, for undo (-1: none)
    int m_redoCut = -1; // the edited future an undo cut, for redo (-1: none)
};

/// A new number of random balls (or other spawn settings): the world restarts.
class SpawnCommand : public QUndoCommand {
public:
    SpawnCommand(SimulationController* controller, const QString& text, const sim::SpawnSettings& before,
                 const sim::SpawnSettings& after);
    void undo() override;
    void redo() override;
    void reportTo(bool* accepted) { m_report = accepted; }

private:
    SimulationController* m_controller; // not owned
    sim::SpawnSettings m_before;
    sim::SpawnSettings m_after;
    bool* m_report = nullptr;
    // The run a respawn ended is a cut (sim/world/timeline.h): undo brings it
    // back, at its start, with its recorded past; redo the respawned run.
    int m_undoCut = -1;
    int m_redoCut = -1;
};

/// A new time scale (slow motion, fast forward).
class TimeScaleCommand : public QUndoCommand {
public:
    TimeScaleCommand(SimulationController* controller, double before, double after, int session = -1);
    void undo() override;
    void redo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

    /// The merge id of time-scale changes (distinct from every settings control).
    static constexpr int kId = 1'000'000;

private:
    SimulationController* m_controller; // not owned
    double m_before;
    double m_after;
    int m_session;
};

} // namespace forcelab
