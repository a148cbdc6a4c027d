#include "ui/canvas/history_recorder.h"

#include "ui/canvas/simulation_controller.h"

#include <algorithm>

namespace forcelab {

HistoryRecorder::HistoryRecorder(SimulationController* controller, QObject* parent)
    : QObject(parent)
    , m_controller(controller)
{
    setObjectName(QStringLiteral("historyRecorder"));
    connect(m_controller, &SimulationController::stepped, this, &HistoryRecorder::record);
    connect(m_controller, &SimulationController::sceneChanged, this, &HistoryRecorder::clear);
    connect(m_controller, &SimulationController::seeked, this, &HistoryRecorder::clear); // paths restart where it jumped
}

void HistoryRecorder::setRecorded(const Overlays& overlays)
{
    if (overlays.trails != m_recorded.trails)
        m_trails.clear(); // a trail starts when it is switched on
    if (overlays.impact != m_recorded.impact)
        resetCollision();
    if (overlays.centreOfMass != m_recorded.centreOfMass)
        m_centreOfMassPath.clear(); // its path starts when it is switched on
    m_recorded = overlays;
    if (m_recorded.trails)
        m_trails.record(m_controller->world().balls(), m_controller->world().time());
    if (m_recorded.centreOfMass)
        recordCentreOfMass();
    emit changed();
}

void HistoryRecorder::setSelectedBall(int index)
{
    if (index == m_selected)
        return;
    m_selected = index;
    m_trails.setSelected(index);
    showSelectedCollision(); // its latest, also from before it was selected
    emit changed();
}

void HistoryRecorder::setTrailScope(TrailRecorder::Scope scope)
{
    m_trails.setScope(scope);
    if (m_recorded.trails)
        m_trails.record(m_controller->world().balls(), m_controller->world().time());
    emit changed();
}

void HistoryRecorder::record()
{
    const sim::World& world = m_controller->world();
    if (m_recorded.trails)
        m_trails.record(world.balls(), world.time());
    if (m_recorded.centreOfMass)
        recordCentreOfMass();
    if (m_recorded.apexes)
        recordApexes();
    if (m_recorded.trails) {
        const auto& panes = m_controller->comparePanes();
        m_paneTrails.resize(panes.size());
        for (std::size_t k = 0; k < panes.size(); ++k)
            if (panes[k].world)
                m_paneTrails[k].record(panes[k].world->balls(), panes[k].world->time());
    }
    if (m_recorded.impact)
        trackCollision();
    m_previousTime = world.time();
    emit changed();
}

void HistoryRecorder::clear()
{
    m_trails.clear();
    m_paneTrails.clear();
    m_centreOfMassPath.clear();
    m_apexes.clear();
    m_apexVy.resize(0);
    resetCollision();
    emit changed();
}

void HistoryRecorder::recordCentreOfMass()
{
    const sim::BallState& balls = m_controller->world().balls();
    const double total = balls.mass.sum();
    if (balls.empty() || !(total > 0.0))
        return;
    const sim::Vec2 centre = (balls.position * balls.mass.matrix()) / total;
    if (!m_centreOfMassPath.empty() && m_centreOfMassPath.back() == centre)
        return;
    // A bounded path: past kMaxCentrePoints the older half goes.
    if (m_centreOfMassPath.size() >= kMaxCentrePoints)
        m_centreOfMassPath.erase(m_centreOfMassPath.begin(),
                                 m_centreOfMassPath.begin() + static_cast<std::ptrdiff_t>(kMaxCentrePoints / 2));
    m_centreOfMassPath.push_back(centre);
}

void HistoryRecorder::recordApexes()
{
    // The top of a flight: vy turns from up (−) to down (+) between frames.
    const sim::BallState& balls = m_controller->world().balls();
    const int n = std::min(balls.size(), kMaxApexBalls);
    if (m_apexVy.size() == n) {
        for (int i = 0; i < n; ++i)
            if (m_apexVy[i] < 0.0 && balls.velocity(1, i) >= 0.0)
                m_apexes.push_back({balls.position.col(i), balls.radius[i]});
    }
    m_apexVy = balls.velocity.row(1).head(n).transpose();
    // Bounded: past 2,000 marks the older half goes.
    if (m_apexes.size() > 2000)
        m_apexes.erase(m_apexes.begin(), m_apexes.begin() + 1000);
}

void HistoryRecorder::resetCollision()
{
    m_collision = CollisionView();
    m_latest.clear();
    m_previousContacts.clear();
    m_previousVelocity.resize(0, 0);
    m_previousTime = -1.0;
}

// Every ball's latest collision is kept, so a ball selected after its hit
// shows it; the shown one is the selected ball's (ball 0 when none is
// selected, as the readout does: a lesson on one collision shows it
// without a click).
void HistoryRecorder::trackCollision()
{
    const sim::World& world = m_controller->world();
    const sim::BallState& balls = world.balls();
    const int n = balls.size();
    if (world.time() == m_previousTime) { // no step (an edit while paused): only the state moved
        m_previousVelocity = balls.velocity;
        return;
    }
    if (m_latest.size() != static_cast<std::size_t>(n)) { // balls added or deleted: their numbers changed
        m_latest.assign(static_cast<std::size_t>(n), CollisionView());
        m_previousContacts.clear();
    }
    std::vector<std::pair<int, int>> now;
    now.reserve(world.contacts().size());
    for (const sim::Contact& c : world.contacts())
        now.emplace_back(std::min(c.a, c.b), std::max(c.a, c.b));
    std::sort(now.begin(), now.end());
    // A new contact, not one that lasts from the frame before (resting balls).
    if (m_previousVelocity.cols() == n)
        for (const auto& [a, b] : now) {
            if (std::binary_search(m_previousContacts.begin(), m_previousContacts.end(), std::pair{a, b}))
                continue;
            for (const auto& [i, partner] : {std::pair{a, b}, std::pair{b, a}}) {
                CollisionView v;
                v.a = i;
                v.b = partner;
                v.positionA = balls.position.col(i);
                v.positionB = balls.position.col(partner);
                v.radiusA = balls.radius[i];
                v.radiusB = balls.radius[partner];
                v.beforeA = m_previousVelocity.col(i);
                v.beforeB = m_previousVelocity.col(partner);
                v.afterA = balls.velocity.col(i);
                v.afterB = balls.velocity.col(partner);
                v.time = world.time();
                m_latest[static_cast<std::size_t>(i)] = v;
            }
        }
    m_previousContacts = std::move(now);
    m_previousVelocity = balls.velocity;
    showSelectedCollision();
}

void HistoryRecorder::showSelectedCollision()
{
    const int i = m_selected >= 0 ? m_selected : 0;
    m_collision = i < static_cast<int>(m_latest.size()) ? m_latest[static_cast<std::size_t>(i)] : CollisionView();
}

} // namespace forcelab
