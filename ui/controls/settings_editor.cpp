#include "ui/controls/settings_editor.h"

#include "ui/canvas/simulation_controller.h"
#include "ui/controls/parameter_commands.h"

#include <QUndoStack>

namespace forcelab {

SettingsEditor::SettingsEditor(SimulationController* controller, QObject* parent)
    : QObject(parent)
    , m_controller(controller)
    , m_undoStack(new QUndoStack(this))
{
    setObjectName(QStringLiteral("settingsEditor"));
    m_undoStack->setObjectName(QStringLiteral("parameterUndoStack"));
}

bool SettingsEditor::editSettings(const QString& text, const std::function<void(sim::WorldSettings&)>& change,
                                  EditMerge merge)
{
    const sim::WorldSettings before = m_controller->world().settings();
    sim::WorldSettings after = before;
    change(after);
    bool accepted = false;
    auto* command = new SettingsCommand(m_controller, text, before, after, merge.id, merge.session);
    command->reportTo(&accepted);
    m_undoStack->push(command); // applies it: redo
    return accepted;
}

bool SettingsEditor::editSpawn(const QString& text, const sim::SpawnSettings& spawn)
{
    bool accepted = false;
    auto* command = new SpawnCommand(m_controller, text, m_controller->spawn(), spawn);
    command->reportTo(&accepted);
    m_undoStack->push(command);
    return accepted;
}

bool SettingsEditor::editTimeScale(double scale, int session)
{
    const double before = m_controller->timeScale();
    if (scale == before)
        return false;
    m_undoStack->push(new TimeScaleCommand(m_controller, before, scale, session));
    return m_controller->timeScale() != before;
}

} // namespace forcelab
