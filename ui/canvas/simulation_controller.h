#pragma once
// Runs a world in real time. A QTimer fires at the display rate; each frame
// adds the elapsed real time (× the time scale) to an accumulator and takes as
// many whole steps of settings.time.dt as fit, so the simulation's speed does
// not depend on the refresh rate and every step has the same dt. A cap on
// steps per frame stops a slow frame from spiralling; time dropped by the cap
// is reported. The timer runs only while playing and not suspended (window
// hidden or minimised).

#include "sim/world/scene.h"
#include "sim/world/timeline.h"
#include "sim/world/world.h"
#include "lessons/lesson.h"
#include "ui/script/student_run.h"

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTimer>

#include <memory>
#include <optional>
#include <set>

namespace forcelab {

class SimulationController : public QObject {
    Q_OBJECT
public:
    explicit SimulationController(QObject* parent = nullptr);

    const sim::World& world() const { return m_world; }
    /// For tools that move balls directly (tests, drag-and-throw). Emit
    /// nothing; call notifyBallsChanged() after editing.
    sim::World& mutableWorld() { return m_world; }
    /// After balls were moved by hand: the timeline takes a checkpoint (and
    /// cuts the future when the world was behind its latest step), and the
    /// ghost and the compare panes start again from the edited balls.
    void notifyBallsChanged();
    /// A ball held by the hand was put back between the steps of a playing
    /// world (Canvas keeps a dragged ball under the pointer): no undo step
    /// and no signal, but the next step records the balls as an edit, so
    /// going back re-runs what was shown.
    void noteHandMoved() { m_handMoved = true; }

    /// The live world's past (sim/world/timeline.h): every step the
    /// controller takes is recorded; setSettings, notifyBallsChanged and
    /// respawn are edits; a new scene or a reset starts it afresh. While the
    /// world is behind the latest recorded step, playing and stepOnce re-run
    /// the recorded steps (their logged pointer, not the live one: pointer
    /// moves wait until the world is back at the latest step).
    const sim::Timeline& timeline() const { return m_timeline; }
    std::int64_t earliestStep() const { return m_timeline.earliestStep(); }
    std::int64_t latestStep() const { return m_timeline.latestStep(); }
    /// The cut the last edit made (an undo command keeps it), or -1.
    int lastCut() const { return m_timeline.lastCut(); }
    /// Brings back the future that edit `cutId` cut, after its own change was
    /// undone: the world goes to the step of the edit, as it was before it.
    /// The ghost and compare panes restart there. False when it is gone.
    bool restoreFuture(int cutId);

    /// In slow motion (time scale below 1, while playing), where the canvas
    /// draws the balls: the last step's start and end positions mixed by the
    /// share of a step the clock has run past it, x₀ + α (x₁ − x₀) with
    /// α = accumulator / dt, so a ball glides between steps instead of
    /// jumping every few frames. nullptr otherwise (draw the positions).
    const sim::Matrix2X* interpolatedPositions();

    /// Starts `scene` (kept for reset) at time 0. On an invalid scene the
    /// running one is kept and the error is returned (and signalled).
    std::optional<QString> setScene(const sim::Scene& scene);
    const sim::Scene& scene() const { return m_scene; }
    /// Counts setScene calls: a new scene, not a reset (what is kept per run, like the arrows' scale, starts over).
    int sceneSerial() const { return m_sceneSerial; }

    /// The spawn settings the world was last started with (the scene's, or a respawn's).
    const sim::SpawnSettings& spawn() const { return m_spawn; }
    /// Starts again from the scene's listed balls plus `spawn`'s random ones,
    /// keeping the live settings (the ball-count control). Returns false (and
    /// signals the error) when the spawn settings are refused.
    bool respawn(const sim::SpawnSettings& spawn);

    /// Pushes a whole settings struct. Returns false (and emits
    /// errorOccurred) when the world refuses it; the world then keeps its settings.
    bool setSettings(const sim::WorldSettings& settings);

    void setPointer(const sim::PointerInput& pointer);
    /// The world's energy books (sim::World::setAccounting) stay on while
    /// any view holds them: each view that shows booked energy (the Accuracy
    /// dock's drift, the energy bars' "lost") holds them while it is shown,
    /// and one view hiding does not switch them off under another.
    void holdAccounting(const void* holder, bool hold);

    bool isPlaying() const { return m_playing; }
    bool isSuspended() const { return m_suspended; }
    bool isTimerActive() const { return m_timer.isActive(); }

    /// Simulated seconds per real second (slow motion < 1 < fast forward).
    double timeScale() const { return m_timeScale; }
    static constexpr double kMinTimeScale = 0.05;
    static constexpr double kMaxTimeScale = 16.0;

    /// Most steps one frame may take; the rest of the frame's time is dropped.
    int maxStepsPerFrame() const { return m_maxStepsPerFrame; }
    void setMaxStepsPerFrame(int steps);

    /// Timer interval, ms (about the display rate).
    static constexpr int kFrameIntervalMs = 16;

    /// What one frame does with `elapsedSeconds` of real time: returns the
    /// number of steps taken. The timer calls it; tests call it directly.
    int advance(double elapsedSeconds);
    /// Simulated time waiting in the accumulator (less than one dt), s.
    double accumulator() const { return m_accumulator; }
    /// Simulated time dropped by the cap since the scene started, s.
    double droppedTime() const { return m_droppedTime; }

    /// A second world run beside the live one, for comparison. Compare: the
    /// same balls and settings with another integrator and a step of
    /// dt / divider (default: the reference integrator at the same dt). Twin:
    /// the same integrator and dt, every ball moved 1e-10 px to the right, to
    /// show how fast a tiny difference grows. The ghost starts from the live
    /// world's state when switched on, restarts with every reset or new
    /// scene, takes the live world's settings edits and pointer, and is
    /// stepped to the same simulated time after every step of the live world.
    /// Runs beside the live one (a lesson's `compare` panes): the live
    /// settings with a few of the pane's own, started from the same balls
    /// and stepped in lock-step. A new scene or a reset starts them over.
    struct Pane {
        QString label;
        std::vector<std::pair<std::string, double>> set; ///< key path and value (sim/world/parameters.h rows)
        std::unique_ptr<sim::World> world;
        /// Set for the pane of a student's own code (setStudentCode): `world`
        /// then only shows the script's balls, which the script moves.
        std::unique_ptr<StudentRun> student;
    };
    void setComparePanes(const std::vector<ComparePane>& panes);
    const std::vector<Pane>& comparePanes() const { return m_panes; }

    /// Runs the course's JavaScript with the student's files in place of the
    /// course's, in one pane beside the live world (the reference), from the
    /// live world's state now and one step after each of its steps; the
    /// lesson's own compare panes wait until stopStudentCode(). A seek, an
    /// edit, new settings or a reset start it again from the live world.
    void setStudentCode(const ScriptEdits& edits);
    void stopStudentCode();
    /// The student's run, or null when none runs.
    const StudentRun* studentRun() const;
    /// The live settings with `pane`'s own applied.
    static sim::WorldSettings paneSettings(const sim::WorldSettings& live, const Pane& pane);

    enum class GhostMode { Off, Compare, Twin };
    void setGhost(GhostMode mode, sim::IntegratorKind integrator = sim::IntegratorKind::Ias15, int divider = 1);
    GhostMode ghostMode() const { return m_ghostMode; }
    sim::IntegratorKind ghostIntegrator() const { return m_ghostIntegrator; }
    int ghostDivider() const { return m_ghostDivider; }
    /// The ghost world, or null when off.
    const sim::World* ghost() const { return m_ghost.get(); }
    /// Largest distance between a live ball and its ghost, px (inf when the
    /// two hold different balls, 0 when off).
    double ghostSeparation() const;
    /// How far the twin's balls are moved at its start, px.
    static constexpr double kTwinOffset = 1e-10;

public slots:
    void play();
    void pause();
    void setPlaying(bool playing);
    void togglePlay();
    /// Pauses and advances exactly one step of dt (re-runs the recorded one
    /// when the world is behind the latest recorded step).
    void stepOnce();
    /// Pauses and steps the world on to step `step` (a step after the
    /// world's), all in one frame; false when the world stops on the way
    /// (it halted) or `step` is not ahead.
    bool runToStep(std::int64_t step);
    /// Pauses and goes one step back (false at the earliest recorded step).
    bool stepBack();
    /// Pauses and shows the recorded world at `step` in [earliestStep(),
    /// latestStep()]; the ghost and the compare panes restart from it (their
    /// own past is not kept), trails are cleared. False when out of range.
    bool seekStep(std::int64_t step);
    /// Restarts the scene with the lesson's own settings, balls and spawn settings.
    void reset();
    void setTimeScale(double scale);
    /// Stops the timer while the window is hidden; playing resumes after.
    void setSuspended(bool suspended);

signals:
    void stepped();          ///< the world advanced (once per frame, not per step)
    void settingsChanged();  ///< the world's settings changed
    void sceneChanged();     ///< a new scene or a reset: balls and settings replaced
    void errorOccurred(const QString& message);
    void playingChanged(bool playing);
    void timeScaleChanged(double scale);
    /// A frame needed more steps than the cap: `seconds` of simulated time were skipped.
    void timeDropped(double seconds);
    /// A frame passed without a step (slow motion): the interpolated picture changed.
    void framePassed();
    /// The world stopped itself because the motion blows up (`reason` says why
    /// and how to fix it), or, with an empty reason, it may run again.
    void haltedChanged(const QString& reason);
    /// The ghost was switched, restarted or refused its settings.
    void ghostChanged();
    /// The recorded span or the world's place in it changed.
    void timelineChanged();
    /// The student's run started, stopped, departed or failed.
    void studentRunChanged();
    /// The world jumped to another recorded step (a seek, a step back, a
    /// restored future): paths drawn so far no longer lead to it.
    void seeked();

private:
    void tick();
    void stepWorld();
    void afterSeek(bool accounting);
    void updateTimer();
    void checkHalted();
    void restartGhost();
    void startedScene();
    void stepGhost();
    sim::WorldSettings ghostSettings(const sim::WorldSettings& live) const;

    sim::World m_world;
    std::set<const void*> m_accountingHolders; // see holdAccounting
    sim::Timeline m_timeline;
    std::optional<sim::PointerInput> m_pendingPointer; // the live pointer, held while re-running the record
    bool m_handMoved = false; // a held ball was moved since the last step (noteHandMoved)
    QString m_haltReason; // the last reason reported by haltedChanged
    sim::Scene m_scene;
    int m_sceneSerial = 0;
    sim::SpawnSettings m_spawn; // of the running world
    QTimer m_timer;
    QElapsedTimer m_clock;
    double m_accumulator = 0.0; // s of simulated time not yet stepped
    double m_droppedTime = 0.0; // s
    double m_timeScale = 1.0;
    sim::Matrix2X m_previous;     // px, positions at the start of the last step (empty: none)
    sim::Matrix2X m_interpolated; // px, scratch for interpolatedPositions()
    int m_maxStepsPerFrame = 8;
    bool m_playing = false;
    bool m_suspended = false;

    GhostMode m_ghostMode = GhostMode::Off;
    sim::IntegratorKind m_ghostIntegrator = sim::IntegratorKind::Ias15;
    int m_ghostDivider = 1;
    std::unique_ptr<sim::World> m_ghost;
    std::vector<Pane> m_panes;
    std::vector<ComparePane> m_lessonPanes; // the lesson's own, kept while a student's code runs
    void followStudent();
    void restartStudent(Pane& pane);
    double m_paneOffset = 0.0; // s, live time when the panes started
    void restartPanes();
    double m_ghostOffset = 0.0; // s, live time when the ghost started (its own time starts at 0)
};

} // namespace forcelab
