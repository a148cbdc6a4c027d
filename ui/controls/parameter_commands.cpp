#include "ui/controls/parameter_commands.h"

#include "ui/canvas/simulation_controller.h"

#include <utility>

namespace forcelab {

SettingsCommand::SettingsCommand(SimulationController* controller, const QString& text,
                                 const sim::WorldSettings& before, const sim::WorldSettings& after, int mergeId,
                                 int session)
    : QUndoCommand(text)
    , m_controller(controller)
    , m_before(before)
    , m_after(after)
    , m_mergeId(mergeId)
    , m_session(session)
{
}

int restoreCutFuture(SimulationController* controller, int undoCut)
{
    int redoCut = controller->lastCut();
    if (undoCut >= 0 && controller->restoreFuture(undoCut) && controller->lastCut() >= 0)
        redoCut = controller->lastCut();
    return redoCut;
}

int restoreEditedFuture(SimulationController* controller, int redoCut)
{
    int undoCut = controller->lastCut();
    if (redoCut >= 0 && controller->restoreFuture(redoCut) && undoCut < 0)
        undoCut = controller->lastCut();
    return undoCut;
}

void SettingsCommand::undo()
{
    m_controller->setSettings(m_before);
    m_redoCut = restoreCutFuture(m_controller, m_undoCut);
    m_undoCut = -1;
}

void SettingsCommand::redo()
{
    // Refused (only the first time can it be: later redos put back settings
    // the world once took): the stack drops the command.
    const bool accepted = m_controller->setSettings(m_after);
    if (accepted) {
        // The future this edit cuts (or, on a redo made at the latest step,
        // the one restoring the edited future cuts) is what undo brings back.
        m_undoCut = restoreEditedFuture(m_controller, m_redoCut);
        m_redoCut = -1;
    }
    setObsolete(!accepted);
    if (m_report)
        *std::exchange(m_report, nullptr) = accepted;
}

bool SettingsCommand::mergeWith(const QUndoCommand* other)
{
    const auto* o = static_cast<const SettingsCommand*>(other);
    if (o->isObsolete() || o->m_mergeId != m_mergeId || o->m_session != m_session)
        return false;
    m_after = o->m_after;
    if (m_undoCut < 0)
        m_undoCut = o->m_undoCut;
    return true;
}

SpawnCommand::SpawnCommand(SimulationController* controller, const QString& text, const sim::SpawnSettings& before,
                           const sim::SpawnSettings& after)
    : QUndoCommand(text)
    , m_controller(controller)
    , m_before(before)
    , m_after(after)
{
}

void SpawnCommand::undo()
{
    m_controller->respawn(m_before);
    m_redoCut = restoreCutFuture(m_controller, m_undoCut);
    m_undoCut = -1;
}

void SpawnCommand::redo()
{
    const bool accepted = m_controller->respawn(m_after);
    if (accepted) {
        m_undoCut = restoreEditedFuture(m_controller, m_redoCut);
        m_redoCut = -1;
    }
    setObsolete(!accepted);
    if (m_report)
        *std::exchange(m_report, nullptr) = accepted;
}

TimeScaleCommand::TimeScaleCommand(SimulationController* controller, double before, double after, int session)
    : QUndoCommand(QObject::tr("Change speed to %1×").arg(after))
    , m_controller(controller)
    , m_before(before)
    , m_after(after)
    , m_session(session)
{
}

void TimeScaleCommand::undo()
{
    m_controller->setTimeScale(m_before);
}

void TimeScaleCommand::redo()
{
    m_controller->setTimeScale(m_after);
    if (m_controller->timeScale() != m_after)
        setObsolete(true);
}

int TimeScaleCommand::id() const
{
    return m_session >= 0 ? kId : -1;
}

bool TimeScaleCommand::mergeWith(const QUndoCommand* other)
{
    const auto* o = static_cast<const TimeScaleCommand*>(other);
    if (o->isObsolete() || o->m_session != m_session)
        return false;
    m_after = o->m_after;
    setText(o->text());
    return true;
}

} // namespace forcelab
