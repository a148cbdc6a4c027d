#pragma once
// The timeline bar: a step back, a scrubber over the recorded steps
// (sim/world/timeline.h, owned by the controller), a step forward, and where
// the world is in the record: "t = 12.35 s of 60.00 s". Dragging the scrubber
// shows the recorded world at that step (the controller re-runs it from a
// checkpoint); the step forward re-runs the next recorded step while the
// world is behind the latest, else takes a new one.

#include <QWidget>

class QLabel;
class QSlider;
class QToolButton;

namespace forcelab {

class SimulationController;

class TimelineBar : public QWidget {
    Q_OBJECT
public:
    explicit TimelineBar(SimulationController* controller, QWidget* parent = nullptr);

    QSlider* slider() const { return m_slider; }
    QToolButton* stepBackButton() const { return m_back; }
    QToolButton* stepForwardButton() const { return m_forward; }
    QLabel* timeLabel() const { return m_label; }

    /// The label's text for a world at `now` s of a record ending at `latest` s.
    static QString timeText(double now, double latest);

private:
    void refresh();
    void seekTo(int value);

    SimulationController* m_controller;
    QToolButton* m_back;
    QSlider* m_slider;
    QToolButton* m_forward;
    QLabel* m_label;
    // The slider counts steps from the earliest recorded one (an int holds
    // 2^31 steps: 1 year at dt = 1/60 s).
    qint64 m_base = 0;
};

} // namespace forcelab
