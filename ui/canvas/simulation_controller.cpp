#include "ui/canvas/simulation_controller.h"

#include "sim/world/parameters.h"

#include "lessons/lesson_loader.h"
#include "sim/studies/work_precision.h"

#include <algorithm>
#include <cmath>

namespace forcelab {

SimulationController::SimulationController(QObject* parent)
    : QObject(parent)
{
    m_timer.setTimerType(Qt::PreciseTimer);
    m_timer.setInterval(kFrameIntervalMs);
    connect(&m_timer, &QTimer::timeout, this, &SimulationController::tick);
    m_clock.start();
    m_timeline.start(m_world);
}

std::optional<QString> SimulationController::setScene(const sim::Scene& scene)
{
    if (auto error = m_world.reset(scene)) {
        const QString message = errorLine(*error);
        emit errorOccurred(message);
        return message;
    }
    m_scene = scene;
    ++m_sceneSerial;
    startedScene();
    return std::nullopt;
}

bool SimulationController::setSettings(const sim::WorldSettings& settings)
{
    if (auto error = m_world.setSettings(settings)) {
        emit errorOccurred(errorLine(*error));
        return false;
    }
    if (m_ghost && m_ghost->setSettings(ghostSettings(settings))) {
        // The ghost cannot take them (e.g. exact with a changing force): it goes.
        m_ghost.reset();
        m_ghostMode = GhostMode::Off;
        emit ghostChanged();
    }
    // The panes follow every live change but their own settings.
    for (Pane& pane : m_panes) {
        if (pane.world)
            if (auto error = pane.world->setSettings(paneSettings(settings, pane))) {
                emit errorOccurred(tr("%1 pane: %2").arg(pane.label, errorLine(*error)));
                pane.world.reset();
            }
        if (pane.student) // the script reads the settings when it is loaded
            restartStudent(pane);
    }
    m_timeline.settingsEdited(m_world);
    emit settingsChanged();
    emit stepped(); // a paused canvas shows the change (walls, markers)
    emit timelineChanged();
    checkHalted();
    return true;
}

void SimulationController::notifyBallsChanged()
{
    m_previous.resize(2, 0); // moved by hand: nothing to blend with
    m_timeline.edited(m_world);
    m_handMoved = false;
    // The ghost and the panes compare ways of running this world: they start
    // again from the edited balls (an added ball has no ghost to be compared with).
    restartGhost();
    restartPanes();
    emit stepped();
    emit timelineChanged();
}

// Takes the next step: the recorded one while the world is behind the
// latest, else a new one, recorded.
void SimulationController::stepWorld()
{
    // A ball held by the hand between steps is an edit all the same (and
    // one made in the past starts a new future), or the record would not
    // re-run to what was shown.
    if (m_handMoved) {
        m_timeline.edited(m_world);
        m_handMoved = false;
    }
    if (m_world.stepCount() < m_timeline.latestStep()) {
        m_timeline.replayStep(m_world);
        if (m_ghost)
            m_ghost->setPointer(m_world.pointer());
        followStudent();
        return;
    }
    if (m_pendingPointer) {
        m_world.setPointer(*m_pendingPointer);
        if (m_ghost)
            m_ghost->setPointer(*m_pendingPointer);
        m_pendingPointer.reset();
    }
    m_world.step();
    m_timeline.afterStep(m_world);
    followStudent();
}

// After each live step (not each frame): the student's code takes its step
// and is compared with this one, so the first departure is found at its step.
void SimulationController::followStudent()
{
    for (Pane& pane : m_panes) {
        if (!pane.student || !pane.world)
            continue;
        const bool failed = pane.student->error().has_value();
        const bool departed = pane.student->departure().has_value();
        pane.student->setPointer(m_world.pointer()); // the pointer the engine's step saw (a replayed one too)
        pane.student->follow(m_world);
        pane.student->copyInto(m_world, *pane.world);
        if (pane.student->error().has_value() != failed || pane.student->departure().has_value() != departed)
            emit studentRunChanged();
    }
}

void SimulationController::setStudentCode(const ScriptEdits& edits)
{
    if (!studentRun()) {
        m_lessonPanes.clear();
        for (const Pane& pane : m_panes)
            m_lessonPanes.push_back({pane.label, pane.set});
    }
    m_panes.clear();
    Pane pane;
    pane.label = tr("your code");
    pane.student = std::make_unique<StudentRun>(edits);
    m_panes.push_back(std::move(pane));
    restartPanes();
    emit ghostChanged();
    emit studentRunChanged();
    emit stepped();
}

void SimulationController::stopStudentCode()
{
    if (!studentRun())
        return;
    const std::vector<ComparePane> lessonPanes = std::move(m_lessonPanes); // setComparePanes clears the kept list
    setComparePanes(lessonPanes);
    emit studentRunChanged();
    emit stepped();
}

const StudentRun* SimulationController::studentRun() const
{
    for (const Pane& pane : m_panes)
        if (pane.student)
            return pane.student.get();
    return nullptr;
}

void SimulationController::restartStudent(Pane& pane)
{
    pane.student->restart(m_world);
    if (pane.world)
        pane.student->copyInto(m_world, *pane.world);
    emit studentRunChanged();
}

bool SimulationController::stepBack()
{
    pause();
    return seekStep(m_world.stepCount() - 1);
}

bool SimulationController::seekStep(std::int64_t step)
{
    pause();
    if (step == m_world.stepCount() && step <= m_timeline.latestStep())
        return true;
    const bool accounting = m_world.accounting();
    if (!m_timeline.seek(step, m_world))
        return false;
    afterSeek(accounting);
    return true;
}

bool SimulationController::restoreFuture(int cutId)
{
    const bool accounting = m_world.accounting();
    if (!m_timeline.restoreCut(cutId, m_world))
        return false;
    afterSeek(accounting);
    return true;
}

// The world jumped: the ghost and the panes start over from it (simplest
// consistent choice: their own past is not recorded), the views redraw. The
// energy books follow the Accuracy dock's switch, not the checkpoint's.
void SimulationController::afterSeek(bool accounting)
{
    if (m_world.accounting() != accounting)
        m_world.setAccounting(accounting);
    m_accumulator = 0.0;
    m_previous.resize(2, 0);
    m_handMoved = false; // the world is a recorded one again
    restartGhost();
    restartPanes();
    emit seeked();
    emit settingsChanged(); // the settings in force at that step
    emit stepped();
    emit timelineChanged();
    checkHalted();
}

// The world refuses to step while its motion would blow up. The controller
// pauses, so the play button tells the truth, and reports the reason once.
void SimulationController::checkHalted()
{
    const QString reason = m_world.halted() ? QString::fromStdString(*m_world.halted()) : QString();
    if (reason == m_haltReason)
        return;
    m_haltReason = reason;
    if (!reason.isEmpty())
        pause();
    emit haltedChanged(reason);
}

void SimulationController::setPointer(const sim::PointerInput& pointer)
{
    if (m_world.stepCount() < m_timeline.latestStep()) {
        m_pendingPointer = pointer; // the record's pointer acts until the latest step
        return;
    }
    m_pendingPointer.reset();
    m_world.setPointer(pointer);
    if (m_ghost)
        m_ghost->setPointer(pointer);
}

void SimulationController::setMaxStepsPerFrame(int steps)
{
    m_maxStepsPerFrame = std::max(1, steps);
}

int SimulationController::advance(double elapsedSeconds)
{
    const double dt = m_world.settings().time.dt;
    if (!(elapsedSeconds > 0.0) || !(dt > 0.0))
        return 0;
    m_accumulator += elapsedSeconds * m_timeScale;
    // Whole steps that fit; what is left (< dt) waits for the next frame.
    const double wanted = std::floor(m_accumulator / dt);
    int steps = static_cast<int>(std::min(wanted, static_cast<double>(m_maxStepsPerFrame)));
    m_accumulator -= steps * dt;
    if (wanted > steps) {
        // More than the cap: drop the whole steps that did not fit, keep the fraction.
        const double dropped = (wanted - steps) * dt;
        m_accumulator = std::max(0.0, m_accumulator - dropped);
        m_droppedTime += dropped;
        emit timeDropped(dropped);
    }
    // Slow motion draws between the last two steps: keep where the last one started.
    const bool slow = m_timeScale < 1.0;
    for (int k = 0; k < steps && !m_world.halted(); ++k) {
        if (slow && k == steps - 1)
            m_previous = m_world.balls().position;
        stepWorld();
    }
    stepGhost();
    if (steps > 0) {
        emit stepped();
        emit timelineChanged();
    }
    else if (m_playing && m_timeScale < 1.0)
        emit framePassed();
    checkHalted();
    return steps;
}

void SimulationController::tick()
{
    // Real time since the last frame, measured, not assumed from the interval.
    const double elapsed = static_cast<double>(m_clock.nsecsElapsed()) * 1e-9;
    m_clock.restart();
    advance(elapsed);
}

void SimulationController::play()
{
    setPlaying(true);
}

void SimulationController::pause()
{
    setPlaying(false);
}

void SimulationController::togglePlay()
{
    setPlaying(!m_playing);
}

void SimulationController::setPlaying(bool playing)
{
    if (playing == m_playing)
        return;
    m_playing = playing;
    updateTimer();
    emit playingChanged(m_playing);
}

const sim::Matrix2X* SimulationController::interpolatedPositions()
{
    const sim::Matrix2X& now = m_world.balls().position;
    const double dt = m_world.settings().time.dt;
    if (!m_playing || !(m_timeScale < 1.0) || m_previous.cols() != now.cols() || !(dt > 0.0))
        return nullptr;
    const double alpha = std::clamp(m_accumulator / dt, 0.0, 1.0);
    m_interpolated = m_previous + alpha * (now - m_previous);
    return &m_interpolated;
}

void SimulationController::stepOnce()
{
    pause();
    m_accumulator = 0.0;
    m_previous.resize(2, 0);
    stepWorld();
    stepGhost();
    emit stepped();
    emit timelineChanged();
    checkHalted();
}

bool SimulationController::runToStep(std::int64_t step)
{
    pause();
    if (step <= m_world.stepCount())
        return step == m_world.stepCount();
    m_accumulator = 0.0;
    m_previous.resize(2, 0);
    while (m_world.stepCount() < step && !m_world.halted())
        stepWorld();
    stepGhost(); // it catches up with the world, as after a frame
    emit stepped();
    emit timelineChanged();
    checkHalted();
    return m_world.stepCount() == step;
}

bool SimulationController::respawn(const sim::SpawnSettings& spawn)
{
    sim::Scene scene = m_scene;
    scene.settings = m_world.settings();
    scene.spawn = spawn;
    if (static_cast<double>(scene.balls.size()) + spawn.count > sim::kMaxBalls) {
        emit errorOccurred(tr("spawn.count: %1 listed + %2 random balls is more than the limit of %3")
                               .arg(scene.balls.size()).arg(spawn.count).arg(sim::kMaxBalls));
        return false;
    }
    if (auto error = m_world.reset(scene)) {
        emit errorOccurred(errorLine(*error));
        return false;
    }
    m_spawn = spawn;
    m_accumulator = 0.0;
    m_clock.restart();
    m_timeline.edited(m_world); // back at step 0: the run so far is a cut an undo can bring back
    m_handMoved = false;
    restartGhost();
    restartPanes();
    emit sceneChanged();
    emit stepped();
    emit timelineChanged();
    return true;
}

void SimulationController::reset()
{
    if (auto error = m_world.reset(m_scene)) {
        emit errorOccurred(errorLine(*error));
        return;
    }
    startedScene();
}

// The world has just been started on m_scene (a new scene or a reset): the
// frame clock, the ghost and the views start over, and a scene that is
// unstable from its first step is reported at once.
void SimulationController::startedScene()
{
    m_spawn = m_scene.spawn;
    m_accumulator = 0.0;
    m_previous.resize(2, 0);
    m_droppedTime = 0.0;
    m_clock.restart();
    m_timeline.start(m_world);
    m_handMoved = false;
    m_pendingPointer.reset();
    restartGhost();
    restartPanes();
    emit sceneChanged();
    emit settingsChanged();
    emit stepped();
    emit timelineChanged();
    checkHalted();
}

void SimulationController::setTimeScale(double scale)
{
    if (!(scale >= kMinTimeScale && scale <= kMaxTimeScale)) {
        emit errorOccurred(tr("time scale: %1 is outside %2 to %3").arg(scale).arg(kMinTimeScale).arg(kMaxTimeScale));
        emit timeScaleChanged(m_timeScale);
        return;
    }
    if (scale == m_timeScale)
        return;
    m_timeScale = scale;
    m_previous.resize(2, 0); // kept only in slow motion: what is there may be from an earlier slow run
    emit timeScaleChanged(m_timeScale);
}

void SimulationController::holdAccounting(const void* holder, bool hold)
{
    if (hold)
        m_accountingHolders.insert(holder);
    else
        m_accountingHolders.erase(holder);
    const bool on = !m_accountingHolders.empty();
    if (m_world.accounting() != on)
        m_world.setAccounting(on);
}

void SimulationController::setSuspended(bool suspended)
{
    if (suspended == m_suspended)
        return;
    m_suspended = suspended;
    updateTimer();
}

void SimulationController::updateTimer()
{
    const bool run = m_playing && !m_suspended;
    if (run && !m_timer.isActive()) {
        // Time spent paused or hidden is not simulated.
        m_clock.restart();
        m_accumulator = 0.0;
        m_timer.start();
    } else if (!run && m_timer.isActive()) {
        m_timer.stop();
    }
}

void SimulationController::setComparePanes(const std::vector<ComparePane>& panes)
{
    const bool student = studentRun() != nullptr;
    m_panes.clear();
    m_lessonPanes.clear();
    if (student)
        emit studentRunChanged();
    for (const ComparePane& p : panes)
        m_panes.push_back({p.label, p.set, nullptr, nullptr});
    restartPanes();
    emit ghostChanged();
}

sim::WorldSettings SimulationController::paneSettings(const sim::WorldSettings& live, const Pane& pane)
{
    sim::WorldSettings s = live;
    for (const auto& [key, value] : pane.set)
        if (const sim::Parameter* row = sim::findParameter(key))
            row->set(s, value);
    return s;
}

// The panes start from the live world's state now (its balls and time 0 of
// their own), like the twin ghost.
void SimulationController::restartPanes()
{
    for (Pane& pane : m_panes) {
        pane.world.reset();
        sim::Scene scene = m_scene;
        scene.settings = paneSettings(m_world.settings(), pane);
        auto world = std::make_unique<sim::World>();
        if (auto error = world->reset(scene)) {
            emit errorOccurred(tr("%1 pane: %2").arg(pane.label, errorLine(*error)));
            continue;
        }
        world->mutableBalls() = m_world.balls();
        pane.world = std::move(world);
        if (pane.student)
            restartStudent(pane);
    }
    m_paneOffset = m_world.time();
}

void SimulationController::setGhost(GhostMode mode, sim::IntegratorKind integrator, int divider)
{
    m_ghostMode = mode;
    m_ghostIntegrator = integrator;
    m_ghostDivider = std::max(1, divider);
    restartGhost();
}

sim::WorldSettings SimulationController::ghostSettings(const sim::WorldSettings& live) const
{
    sim::WorldSettings s = live;
    if (m_ghostMode == GhostMode::Compare) {
        s.time.integrator = m_ghostIntegrator;
        s.time.dt = live.time.dt / m_ghostDivider;
    }
    return s;
}

// The ghost starts from the live world's state now: the same balls (the twin's
// nudged), the same settings but its own integrator, its own clock at 0.
void SimulationController::restartGhost()
{
    m_ghost.reset();
    if (m_ghostMode != GhostMode::Off) {
        sim::Scene scene;
        scene.settings = ghostSettings(m_world.settings());
        auto ghost = std::make_unique<sim::World>();
        if (auto error = ghost->reset(scene)) {
            emit errorOccurred(tr("ghost: %1").arg(errorLine(*error)));
            m_ghostMode = GhostMode::Off;
        } else {
            sim::BallState& balls = ghost->mutableBalls();
            balls = m_world.balls();
            if (m_ghostMode == GhostMode::Twin)
                balls.position.row(0).array() += kTwinOffset;
            ghost->setPointer(m_world.pointer());
            m_ghost = std::move(ghost);
            m_ghostOffset = m_world.time();
        }
    }
    emit ghostChanged();
}

// Steps the ghost until it has reached the live world's time (within half of
// its step: with a step of dt / divider it lands on it exactly).
void SimulationController::stepGhost()
{
    for (Pane& pane : m_panes) {
        if (!pane.world || pane.student) // a student's run follows each step (followStudent)
            continue;
        const double target = m_world.time() - m_paneOffset;
        const double h = pane.world->settings().time.dt;
        while (!pane.world->halted() && pane.world->time() < target - 0.5 * h)
            pane.world->step();
    }
    if (!m_ghost)
        return;
    const double target = m_world.time() - m_ghostOffset;
    const double h = m_ghost->settings().time.dt;
    while (!m_ghost->halted() && m_ghost->time() < target - 0.5 * h)
        m_ghost->step();
}

double SimulationController::ghostSeparation() const
{
    return m_ghost ? sim::largestSeparation(m_world, *m_ghost) : 0.0;
}

} // namespace forcelab
