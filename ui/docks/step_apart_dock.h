#pragma once
// "One Step Apart" (issue #37 part 4): one step of the selected ball taken
// apart, in the order the course's JavaScript runs it — forces, acceleration,
// velocity, position, walls, detection, response, push-apart — each with the
// lines of lessons/code/*.js that did it and the ball's values after it at full
// precision. The step is run by a ScriptWorld loaded from the live world and
// instrumented by wrapping the script's own functions, so what is shown is
// what ran; a last row checks it against the engine's own next step.

#include <QDockWidget>
#include <QList>
#include <QPair>
#include <QString>
#include <QStringList>

class QLabel;
class QPushButton;
class QSpinBox;
class QTextBrowser;

namespace forcelab {

class SimulationController;

struct StepApartRow {
    enum class Kind { SubStep, Force, Acceleration, Velocity, Position, Rule, Detection, Response, PushApart, Check };
    Kind kind = Kind::Rule;
    int subStep = 0;          ///< 0-based
    QString stage;            ///< in plain words
    QStringList code;         ///< "walls.js:12  b[axis.v] = u;", the lines that did it
    double x = 0.0, y = 0.0, vx = 0.0, vy = 0.0; ///< the ball after this stage: px, px/s
    bool hasAcceleration = false;
    double ax = 0.0, ay = 0.0;   ///< px/s²: the sum so far (Force), the total (Acceleration)
    double ownAx = 0.0, ownAy = 0.0; ///< px/s²: this force's own part (Force)
    QList<QPair<int, int>> pairs;    ///< Detection: the touching pairs with this ball
    int other = -1;                  ///< Response, PushApart: the other ball
    QString note;             ///< "no wall touched", "matches the engine bit for bit", …
    bool ok = true;           ///< Check: the script's step equals the engine's
};

class StepApartDock : public QDockWidget {
    Q_OBJECT
public:
    /// `controller` is not owned and must outlive the dock.
    explicit StepApartDock(SimulationController* controller, QWidget* parent = nullptr);

    const QList<StepApartRow>& rows() const { return m_rows; }
    /// A message shown instead of the rows (no JavaScript yet, pause first, a script error).
    QString message() const { return m_message; }
    int ball() const { return m_ball; }
    /// The rows as plain text, for a test or a copy.
    QString shownText() const;
    /// The sub-step shown (1-based), or 0 for all of them.
    int shownSubStep() const;
    void showSubStep(int subStep);

public slots:
    /// The canvas's selection; -1 takes ball 0.
    void setSelectedBall(int ball);
    /// Takes the current step apart again (only while visible; otherwise when shown).
    void refresh();

protected:
    void showEvent(QShowEvent* event) override;

private:
    QString pauseNote() const;
    void takeApart();
    void render();

    SimulationController* m_controller; // not owned
    int m_ball = 0;
    bool m_stale = true; // something changed while hidden
    QList<StepApartRow> m_rows;
    QString m_message;
    QLabel* m_title = nullptr;
    QTextBrowser* m_view = nullptr;
    QSpinBox* m_subStep = nullptr; // with many sub-steps, one at a time
    int m_subSteps = 1;
    QPushButton* m_stepButton = nullptr;
    QPushButton* m_backButton = nullptr;
};

} // namespace forcelab
