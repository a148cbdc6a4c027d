#pragma once
// Predict, then run: a lesson's questions ("How high will the red ball rise
// after its first bounce?") asked while the lesson waits at t = 0. The
// student types a number (or picks an answer), presses Run, and when the
// live run reaches the moment the question is about, the dock shows the
// prediction against the measurement. The measurement is the answering
// claim's own (sim::checkClaim on the scene with the settings the student
// ran), so the question, the lesson's text and the check can never disagree.
// The measurement runs on a worker thread with a progress bar and a Cancel
// button, so a lesson whose claim takes long never freezes the window.

#include "lessons/lesson.h"
#include "ui/drawing/display_units.h"

#include "sim/studies/claims.h"

#include <QDockWidget>
#include <QFutureWatcher>

#include <atomic>
#include <optional>

class QButtonGroup;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QVBoxLayout;

namespace forcelab {

class SimulationController;

class PredictDock : public QDockWidget {
    Q_OBJECT
public:
    /// `controller` is not owned and must outlive the dock.
    explicit PredictDock(SimulationController* controller, QWidget* parent = nullptr);
    ~PredictDock() override;

    /// The lesson's questions (none: the dock says so).
    void setLesson(const Lesson& lesson);
    bool hasQuestions() const { return !m_lesson.predict.empty(); }
    /// The question shown, an index into the lesson's predict list.
    int question() const { return m_question; }

    /// The measurement of the question asked last, once locked in.
    std::optional<double> measured() const { return m_measured; }
    /// The student's answer, once locked in (a choice's value for a choice).
    std::optional<double> predicted() const { return m_predicted; }
    /// Whether the result is shown (the run has reached the question's time).
    bool revealed() const { return m_revealed; }
    /// Whether the answer is being measured (the worker runs).
    bool measuring() const { return m_watcher.isRunning(); }

public slots:
    /// Takes the answer and starts measuring it; the lesson runs when the
    /// measurement is done.
    void lockIn();
    /// Stops the measurement; the question is asked again.
    void cancelMeasurement();
    /// Shows the result now, without waiting for the run.
    void reveal();
    void nextQuestion();
    /// The units changed (View → Units, or a lesson's own): the answer's
    /// unit is shown again, and a typed answer is read in the new one.
    void unitsChanged();

private:
    void showQuestion();
    void onStepped();
    void measurementFinished();
    void setAnswerEnabled(bool enabled);
    ShownUnit unitOf(const sim::Claim& claim) const;

    SimulationController* m_controller; // not owned
    Lesson m_lesson;
    int m_question = 0;
    std::optional<double> m_predicted;
    std::optional<double> m_measured;
    double m_revealAt = 0.0; // s of live time
    bool m_revealed = false;

    QLabel* m_ask = nullptr;
    QLineEdit* m_number = nullptr;
    QLabel* m_unit = nullptr;
    QWidget* m_choiceBox = nullptr;
    QVBoxLayout* m_choiceLayout = nullptr;
    QButtonGroup* m_choices = nullptr;
    QPushButton* m_run = nullptr;
    QPushButton* m_show = nullptr;
    QPushButton* m_next = nullptr;
    QLabel* m_result = nullptr;
    QPushButton* m_cancel = nullptr;
    QProgressBar* m_progress = nullptr;
    QFutureWatcher<sim::ClaimResult> m_watcher;
    std::atomic<bool> m_cancelFlag{false};
    bool m_discard = false; // the question changed while measuring: drop the result
};

} // namespace forcelab
