#pragma once
// The stage: what the class sees. The canvas, with the banner that says why
// the simulation stopped itself above it; in the stage view (projector mode)
// also the bar of large controls, the lesson's sliders and the readout, laid
// out beside the box or under it, whichever leaves the box larger. The main
// window puts it in the middle and hides everything else in the stage view.

#include "lessons/lesson.h"
#include "ui/drawing/world_painter.h"

#include <QList>
#include <QWidget>

class QAction;
class QBoxLayout;
class QLabel;

namespace forcelab {

class BallTable;
class Canvas;
class HistoryRecorder;
class SettingsEditor;
class SimulationController;
class StageBar;
class StageSliders;

class StageView : public QWidget {
    Q_OBJECT
public:
    /// `controller` and `editor` are not owned and must outlive the view.
    StageView(SimulationController* controller, SettingsEditor* editor, QWidget* parent = nullptr);

    Canvas* canvas() const { return m_canvas; }
    /// What the simulation did, for the canvas and every view of the past.
    HistoryRecorder* history() const { return m_history; }

    /// Makes the stage view's bar with these buttons (the window's own
    /// actions: play, step, reset, slower, faster), plus the bar's Sliders
    /// button. Called once, after the window has made its actions.
    void createBar(const QList<QAction*>& actions);

    /// True while the stage view shows its bar.
    bool isStaged() const;
    /// Shows or hides the bar; the readout and the totals move from the
    /// canvas to the bar and back.
    void setStaged(bool on);

    /// A new lesson: its caption and sliders (its overlays come first, through setOverlays).
    void setLesson(const Lesson& lesson);
    /// The canvas's overlays (in the stage view, without the readouts the bar shows).
    void setOverlays(const Overlays& overlays);

    /// Puts the bar beside the box or under it, sized to what it holds.
    void layoutStage();

    /// Shows the stage's ball table under the box with ball `index` selected
    /// (the canvas's "Edit its numbers" in the stage view).
    void showBallTable(int index);
    BallTable* ballTable() const { return m_ballTable; }
    /// The bar's Balls button: shows or hides the ball table.
    QAction* ballsAction() const { return m_ballsAction; }

    /// The size the challenge's text starts at, as a share of the stage's height.
    static constexpr double kTextFloorShare = 0.024;

    /// The stage's clock line: the simulated time and the speed ("t = 2.00 s   ¼× speed").
    static QString clockText(double time, double timeScale);

public slots:
    /// Why the simulation stopped itself; empty hides the banner.
    void showHalted(const QString& reason);

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    struct Readout {
        QString wide;   // long lines, for a row
        QString narrow; // short lines, for a column
    };
    Readout readoutText() const;
    void updateReadout();
    Overlays withoutReadouts(Overlays overlays);

    SimulationController* m_controller; // not owned
    SettingsEditor* m_editor;           // not owned
    Canvas* m_canvas = nullptr;
    HistoryRecorder* m_history = nullptr;
    QLabel* m_haltBanner = nullptr;
    QBoxLayout* m_layout = nullptr;
    StageBar* m_bar = nullptr;
    StageSliders* m_sliders = nullptr;
    QAction* m_slidersAction = nullptr; // shows a row bar's sliders when they do not fit
    QAction* m_ballsAction = nullptr;   // shows the ball table under the box
    BallTable* m_ballTable = nullptr;
    Overlays m_ownOverlays; // the canvas's overlays before the bar took its readouts
    QString m_title;
    QString m_challenge;
};

} // namespace forcelab
