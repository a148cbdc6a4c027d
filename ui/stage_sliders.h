#pragma once
// The lesson's own controls on the stage view: one big slider per number of
// the lesson's `controls`, its label and value above it in large text, so a
// teacher can change gravity or restitution in front of the class without
// leaving the stage. Switches and choices stay in the Parameters panel. An
// edit goes through the same path as the panel's: a copy of the settings,
// one row changed, pushed whole to the controller, and one undo step per drag.

#include <QList>
#include <QStringList>
#include <QWidget>

class QGridLayout;
class QLabel;
class QUndoStack;

namespace forcelab {

class NumberControl;
class SimulationController;
namespace sim { struct Parameter; }

class StageSliders : public QWidget {
    Q_OBJECT
public:
    /// `controller` and `undoStack` are not owned and must outlive the sliders.
    StageSliders(SimulationController* controller, QUndoStack* undoStack, QWidget* parent = nullptr);

    /// One slider per number row of the lesson's `controls` (in their order).
    void setLessonControls(const QStringList& controls);
    /// Sliders side by side (2 in a column bar, all of them in a row bar).
    void setColumns(int columns);
    /// Sliders shown (the stage bar hides their area when there are none).
    int count() const { return static_cast<int>(m_sliders.size()); }
    /// The slider of a parameter row ("gravity_y"), or null.
    NumberControl* slider(const QString& row) const;

public slots:
    /// Shows the world's values (after an edit, an undo, a reset).
    void refresh();

private:
    struct Slider {
        const sim::Parameter* parameter = nullptr;
        QString row;
        NumberControl* control = nullptr;
        QLabel* label = nullptr;
    };

    void apply(const sim::Parameter* parameter, double value, int mergeId);

    SimulationController* m_controller; // not owned
    QUndoStack* m_undoStack;             // not owned
    QGridLayout* m_grid = nullptr;
    QList<Slider> m_sliders;
    int m_dragSession = 0;
    int m_columns = 2;
    void arrange();
};

} // namespace forcelab
