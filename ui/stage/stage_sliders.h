#pragma once
// The lesson's own controls on the stage view, so a teacher can change
// gravity or restitution, or flip a lesson's switch, in front of the class
// without leaving the stage: one big slider per number of the lesson's
// `controls`, one big On/Off button per switch (a challenge such as "switch
// resting contacts off" is done right there), and one list per choice (the
// wall model, the integrator), each with its label and value above it in
// large text. An edit goes through the same path as the panel's: a copy of
// the settings, one row changed, pushed whole to the controller, and one
// undo step per drag or click.

#include <QList>
#include <QStringList>
#include <QWidget>

#include <utility>

class QComboBox;
class QFont;
class QGridLayout;
class QLabel;
class QPushButton;

namespace forcelab {

class NumberControl;
class SettingsEditor;
class SimulationController;
namespace sim { struct Parameter; }

class StageSliders : public QWidget {
    Q_OBJECT
public:
    /// `controller` and `editor` are not owned and must outlive the sliders.
    StageSliders(SimulationController* controller, SettingsEditor* editor, QWidget* parent = nullptr);

    /// One control per row of the lesson's `controls` (in their order): a
    /// slider for a number, a button for a switch, a list for a choice.
    void setLessonControls(const QStringList& controls);
    /// Controls side by side (2 in a column bar, all of them in a row bar).
    void setColumns(int columns);
    /// Controls shown (the stage bar hides their area when there are none).
    int count() const { return static_cast<int>(m_controls.size()); }
    /// The slider of a number row ("gravity_y"), or null.
    NumberControl* slider(const QString& row) const;
    /// The On/Off button of a switch row ("resting"), or null. The wall
    /// sides ("walls") are four buttons: "wall_left" … "wall_bottom".
    QPushButton* toggle(const QString& row) const;
    /// The list of a choice row ("wall_model"), or null.
    QComboBox* choice(const QString& row) const;

public slots:
    /// Shows the world's values (after an edit, an undo, a reset).
    void refresh();

private:
    // One control: exactly one of slider, toggle and list is set, by the
    // row's type; widget() is that one.
    struct Control {
        const sim::Parameter* parameter = nullptr;
        QString row;
        QLabel* label = nullptr;
        NumberControl* slider = nullptr;
        QPushButton* toggle = nullptr;
        QComboBox* list = nullptr;
        // The panel's own rows: the wall sides (one button per side, each
        // its table row) and the spawn's fully_inside switch (toggle set).
        QWidget* sidesField = nullptr;
        QList<std::pair<const sim::Parameter*, QPushButton*>> sides;
        bool spawnInside = false;
        int spawnSpeed = 0; // 1: the slowest random ball's speed, 2: the fastest's (slider set)
        QWidget* widget() const;
    };
    Control makeWallSides(const QFont& big);
    Control makeFullyInside(const QFont& big);
    Control makeSpawnSpeed(const QFont& big, const QString& row);
    NumberControl* makeSlider(const sim::Parameter* p, const QString& row);
    const Control* find(const QString& row) const; // the control of a row, or null

    void apply(const sim::Parameter* parameter, double value, int mergeId);

    SimulationController* m_controller; // not owned
    SettingsEditor* m_editor;            // not owned
    QGridLayout* m_grid = nullptr;
    QList<Control> m_controls;
    int m_dragSession = 0;
    int m_columns = 2;
    void arrange();
};

} // namespace forcelab
