#pragma once
// A stopwatch on simulated time, for the challenges that ask to time
// something: started and stopped by hand, or armed on an event of one ball
// (a bounce, the top of a flight, crossing a line, a full turn round the
// spring's anchor or the attracting point), and stopped after the n-th next
// event ("time ten swings"). Event times come from sim::EventWatch, which
// finds them inside a step, so the watch is not limited to whole frames.

#include "ui/drawing/display_units.h"

#include "sim/world/events.h"

#include <QDockWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace forcelab {

class SimulationController;

class StopwatchDock : public QDockWidget {
    Q_OBJECT
public:
    enum class State {
        Idle,    ///< reset, not started
        Armed,   ///< waiting for the start event
        Running, ///< timing
        Stopped, ///< shows the time measured
    };

    /// `controller` is not owned and must outlive the dock.
    explicit StopwatchDock(SimulationController* controller, QWidget* parent = nullptr);

    State state() const { return m_state; }
    /// s of simulated time: measured (Stopped) or so far (Running); 0 otherwise.
    double elapsed() const;

    /// What the watch is set to do (the dock's controls).
    enum class StartOn { Hand, Event };
    enum class StopOn { Hand, Events };
    void setStartOn(StartOn on);
    void setStopOn(StopOn on, int events = 1);
    /// `line` in px, whatever the units shown.
    void setEvent(sim::EventKind kind, int ball, double line = 0.0);

public slots:
    /// Start (or arm), or stop when running by hand.
    void startOrStop();
    void reset();
    /// The ball the events are about (the canvas's selection).
    void setBall(int ball);
    /// The view's units changed: the line's position is shown in m or px.
    void unitsChanged();

private:
    void onStepped();
    void showTime();
    void updateControls();
    sim::EventSpec spec() const;

    SimulationController* m_controller; // not owned
    sim::EventWatch m_watch;
    State m_state = State::Idle;
    double m_start = 0.0, m_stop = 0.0; // s of world time
    int m_eventsLeft = 0;

    QLabel* m_time = nullptr;
    QComboBox* m_startOn = nullptr;
    QComboBox* m_stopOn = nullptr;
    QSpinBox* m_count = nullptr;
    QComboBox* m_event = nullptr;
    QSpinBox* m_ball = nullptr;
    QDoubleSpinBox* m_line = nullptr;
    ShownUnit m_lineUnit{QStringLiteral("px")}; // what m_line shows: px, or m in SI
    QPushButton* m_startStop = nullptr;
    QPushButton* m_reset = nullptr;
    QLabel* m_laps = nullptr;
    QStringList m_lapTexts;
};

} // namespace forcelab
