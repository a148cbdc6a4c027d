#include "ui/controls/ball_commands.h"

#include "ui/canvas/simulation_controller.h"
#include "ui/controls/parameter_commands.h"

namespace forcelab {

void writeBallFields(sim::BallState& balls, int index, const sim::Ball& ball, unsigned fields)
{
    if (fields & kBallPosition)
        balls.position.col(index) = ball.position;
    if (fields & kBallVelocity)
        balls.velocity.col(index) = ball.velocity;
    if (fields & kBallRadius)
        balls.radius[index] = ball.radius;
    if (fields & kBallMass)
        balls.setMass(index, ball.mass);
    if (fields & kBallCharge)
        balls.charge[index] = ball.charge;
    if (fields & kBallColour)
        balls.color[static_cast<std::size_t>(index)] = ball.color;
    if (fields & kBallRestitution)
        balls.restitution[index] = ball.restitution;
    if (fields & kBallPinned) // last: it sets the inverse mass from the mass written above
        balls.setPinned(index, ball.pinned);
}

void copyBallFields(sim::Ball& to, const sim::Ball& from, unsigned fields)
{
    if (fields & kBallPosition)
        to.position = from.position;
    if (fields & kBallVelocity)
        to.velocity = from.velocity;
    if (fields & kBallRadius)
        to.radius = from.radius;
    if (fields & kBallMass)
        to.mass = from.mass;
    if (fields & kBallCharge)
        to.charge = from.charge;
    if (fields & kBallColour)
        to.color = from.color;
    if (fields & kBallRestitution)
        to.restitution = from.restitution;
    if (fields & kBallPinned)
        to.pinned = from.pinned;
}

BallCommand::BallCommand(SimulationController* controller, Kind kind, const QString& text, int index,
                         const sim::Ball& before, const sim::Ball& after, unsigned fields, int mergeId, int session)
    : QUndoCommand(text)
    , m_controller(controller)
    , m_kind(kind)
    , m_index(index)
    , m_before(before)
    , m_after(after)
    , m_fields(fields)
    , m_mergeId(mergeId)
    , m_session(session)
{
}

// Every ball edit is checked by SettingsEditor before the command is made;
// these only guard against a world that no longer has the ball (a reset or a
// new random set of balls between the edit and its undo).
void BallCommand::change(const sim::Ball& to)
{
    sim::BallState& balls = m_controller->mutableWorld().mutableBalls();
    if (m_index < balls.size())
        writeBallFields(balls, m_index, to, m_fields);
    m_controller->notifyBallsChanged();
}

void BallCommand::insert(const sim::Ball& ball)
{
    sim::BallState& balls = m_controller->mutableWorld().mutableBalls();
    if (m_index <= balls.size())
        balls.insert(m_index, ball);
    m_controller->notifyBallsChanged();
    if (m_countChanged)
        m_countChanged();
}

void BallCommand::remove()
{
    sim::BallState& balls = m_controller->mutableWorld().mutableBalls();
    if (m_index < balls.size())
        balls.remove(m_index);
    m_controller->notifyBallsChanged();
    if (m_countChanged)
        m_countChanged();
}

void BallCommand::undo()
{
    undoEdit();
    // An edit made in the past started a new future; undone, the old one comes back.
    m_redoCut = restoreCutFuture(m_controller, m_undoCut);
    m_undoCut = -1;
}

void BallCommand::redo()
{
    redoEdit();
    m_undoCut = restoreEditedFuture(m_controller, m_redoCut);
    m_redoCut = -1;
}

void BallCommand::undoEdit()
{
    switch (m_kind) {
    case Kind::Change:
        change(m_before);
        break;
    case Kind::Add:
        remove();
        break;
    case Kind::Remove:
        insert(m_before);
        break;
    }
}

void BallCommand::redoEdit()
{
    switch (m_kind) {
    case Kind::Change:
        change(m_after);
        break;
    case Kind::Add:
        insert(m_after);
        break;
    case Kind::Remove:
        remove();
        break;
    }
}

bool BallCommand::mergeWith(const QUndoCommand* other)
{
    const auto* o = static_cast<const BallCommand*>(other);
    if (o->m_kind != Kind::Change || m_kind != Kind::Change || o->m_mergeId != m_mergeId ||
        o->m_session != m_session || o->m_index != m_index || o->m_fields != m_fields)
        return false;
    m_after = o->m_after;
    if (m_undoCut < 0)
        m_undoCut = o->m_undoCut;
    return true;
}

} // namespace forcelab
