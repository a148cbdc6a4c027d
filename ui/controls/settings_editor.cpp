#include "ui/controls/settings_editor.h"

#include "ui/canvas/simulation_controller.h"
#include "ui/controls/ball_commands.h"
#include "ui/controls/parameter_commands.h"

#include "sim/world/ball_placement.h"
#include "sim/world/number_text.h"

#include <QLocale>
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

bool SettingsEditor::editSpawnSpeed(bool slowest, double speed)
{
    sim::SpawnSettings spawn = m_controller->spawn();
    (slowest ? spawn.minSpeed : spawn.maxSpeed) = speed;
    const sim::SpawnSettings& before = m_controller->spawn();
    if (spawn.minSpeed == before.minSpeed && spawn.maxSpeed == before.maxSpeed)
        return false;
    return editSpawn(tr("Random balls from %1 to %2 px/s").arg(spawn.minSpeed).arg(spawn.maxSpeed), spawn);
}

bool SettingsEditor::editTimeScale(double scale, int session)
{
    const double before = m_controller->timeScale();
    if (scale == before)
        return false;
    m_undoStack->push(new TimeScaleCommand(m_controller, before, scale, session));
    return m_controller->timeScale() != before;
}

std::optional<sim::Ball> SettingsEditor::checkedBall(const sim::Ball& ball, int ignore, bool place)
{
    const sim::Ball one[] = {ball};
    if (auto error = sim::validateBalls(one)) {
        // "balls.0.r: …" names the field; the ball is the one being edited.
        QString key = QString::fromStdString(error->keyPath).section(QLatin1Char('.'), 2);
        emit ballEditNote(tr("%1: %2").arg(key, QString::fromStdString(error->message)), true);
        return std::nullopt;
    }
    if (!(ball.mass >= sim::kMinMass && ball.mass <= sim::kMaxMass)) { // a typed mass is never "0: by its size"
        emit ballEditNote(tr("mass: %1 is outside %2")
                              .arg(QString::fromStdString(sim::numberText(ball.mass)),
                                   QString::fromStdString(sim::rangeText(sim::kMinMass, sim::kMaxMass))),
                          true);
        return std::nullopt;
    }
    sim::Ball checked = ball;
    if (!place)
        return checked;
    const sim::World& world = m_controller->world();
    const sim::Placement placement = sim::placeBall(world.balls(), world.settings(), ball.position, ball.radius, ignore);
    if (!placement.ok) {
        emit ballEditNote(tr("Not placed: %1").arg(QString::fromStdString(placement.why)), true);
        return std::nullopt;
    }
    if (placement.moved)
        emit ballEditNote(tr("Moved to (%1, %2) px, touching, so it does not overlap")
                              .arg(QString::fromStdString(sim::roundedText(placement.position.x(), 6)),
                                   QString::fromStdString(sim::roundedText(placement.position.y(), 6))),
                          false);
    checked.position = placement.position;
    return checked;
}

bool SettingsEditor::editBall(const QString& text, int index, const sim::Ball& after, unsigned fields, EditMerge merge)
{
    const sim::BallState& balls = m_controller->world().balls();
    if (index < 0 || index >= balls.size())
        return false;
    const sim::Ball before = balls.ball(index);
    sim::Ball wanted = before;
    copyBallFields(wanted, after, fields);
    if ((fields & kBallPinned) && wanted.pinned) { // a pinned ball is at rest: undo gives its velocity back
        wanted.velocity.setZero();
        fields |= kBallVelocity;
    }
    const bool place = (fields & (kBallPosition | kBallRadius)) != 0;
    const std::optional<sim::Ball> checked = checkedBall(wanted, index, place);
    if (!checked)
        return false;
    if (checked->position != wanted.position)
        fields |= kBallPosition;
    m_undoStack->push(
        new BallCommand(m_controller, BallCommand::Kind::Change, text, index, before, *checked, fields, merge.id,
                        merge.session));
    return true;
}

int SettingsEditor::addBall(const QString& text, const sim::Ball& ball)
{
    const int count = m_controller->world().balls().size();
    if (count >= sim::kMaxBalls) {
        emit ballEditNote(tr("Not added: the world holds at most %1 balls").arg(QLocale().toString(sim::kMaxBalls)),
                          true);
        return -1;
    }
    sim::Ball wanted = ball;
    if (wanted.mass <= 0.0)
        wanted.mass = sim::sphereMass(wanted.radius);
    const std::optional<sim::Ball> checked = checkedBall(wanted, -1, true);
    if (!checked)
        return -1;
    auto* command =
        new BallCommand(m_controller, BallCommand::Kind::Add, text, count, *checked, *checked, kBallAllFields);
    command->onCountChanged([this] { emit ballCountChanged(); });
    m_undoStack->push(command);
    return count;
}

bool SettingsEditor::removeBall(int index)
{
    const sim::BallState& balls = m_controller->world().balls();
    if (index < 0 || index >= balls.size())
        return false;
    const sim::Ball ball = balls.ball(index);
    auto* command = new BallCommand(m_controller, BallCommand::Kind::Remove, tr("Delete ball %1").arg(index), index,
                                    ball, ball, kBallAllFields);
    command->onCountChanged([this] { emit ballCountChanged(); });
    m_undoStack->push(command);
    return true;
}

int SettingsEditor::duplicateBall(int index)
{
    const sim::BallState& balls = m_controller->world().balls();
    if (index < 0 || index >= balls.size())
        return -1;
    sim::Ball copy = balls.ball(index);
    copy.position.x() += 2.0 * copy.radius * (1.0 + sim::kTouchingGap); // beside it, touching
    return addBall(tr("Duplicate ball %1").arg(index), copy);
}

} // namespace forcelab
