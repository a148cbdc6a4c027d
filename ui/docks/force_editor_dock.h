#pragma once
// The Force editor: the student writes a force law as formulas (F_x, F_y and,
// for a conservative law, its potential U) of the ball's x, y, vx, vy, m, r,
// q, the time t, the box's W and H, and named constants with sliders. An
// edit is compiled when the field is left (or Enter): a bad formula is
// refused with its column and what was expected, under the field, and the
// world keeps its last good law; a good one goes to the world as a settings
// edit, with one undo step.

#include <QDockWidget>
#include <QList>

class QCheckBox;
class QComboBox;
class QGridLayout;
class QLabel;
class QLineEdit;
class QPushButton;

namespace forcelab {

class NumberControl;
class SettingsEditor;
class SimulationController;

class ForceEditorDock : public QDockWidget {
    Q_OBJECT
public:
    /// `controller` and `editor` are not owned and must outlive the dock.
    ForceEditorDock(SimulationController* controller, SettingsEditor* editor, QWidget* parent = nullptr);

    /// The message shown under a field ("fx", "fy", "potential", "constants"), empty when fine.
    QString problem(const QString& field) const;

public slots:
    /// Shows the world's law (after a lesson, a reset, an undo).
    void refresh();

private:
    /// Compiles the fields into a copy of the settings and pushes it.
    void apply(const QString& changedField);
    void addConstant();
    void rebuildConstants();

    SimulationController* m_controller; // not owned
    SettingsEditor* m_editor;            // not owned
    QCheckBox* m_enabled = nullptr;
    QComboBox* m_kind = nullptr;
    QLineEdit* m_fx = nullptr;
    QLineEdit* m_fy = nullptr;
    QLineEdit* m_potential = nullptr;
    QLabel* m_fxProblem = nullptr;
    QLabel* m_fyProblem = nullptr;
    QLabel* m_potentialProblem = nullptr;
    QLabel* m_constantsProblem = nullptr;
    QWidget* m_constantsBox = nullptr;
    QGridLayout* m_constantsGrid = nullptr;
    QList<NumberControl*> m_constantSliders;
    QLineEdit* m_newName = nullptr;
    QPushButton* m_add = nullptr;
    bool m_refreshing = false;
};

} // namespace forcelab
