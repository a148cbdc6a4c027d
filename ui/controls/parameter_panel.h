#pragma once
// The Parameters panel: live controls for every setting of the world. An edit
// copies the world's settings, changes one field and pushes the whole struct
// through the controller; an accepted edit goes on the undo stack, a refused
// one is reported (the controller signals it) and the control snaps back to the
// world's value. Nothing is clamped on the way: a typed value outside a
// control's range is passed on, so the world refuses it with its own message.
//
// The controls are rows grouped into sections. A lesson's `controls` names
// pick the rows shown first; "Show all" adds every other row after them.
// Every widget has an objectName (e.g. "gravityYSpin", "wallModelCombo").

#include "ui/controls/number_control.h"
#include "ui/drawing/display_units.h"

#include "sim/world/scene.h"
#include "sim/world/world_settings.h"

#include <QHash>
#include <QString>
#include <QStringList>
#include <QWidget>

#include <functional>
#include <span>
#include <string_view>
#include <vector>

class QCheckBox;
class QComboBox;
class QFormLayout;
class QGroupBox;
class QLabel;
class QVBoxLayout;

namespace forcelab {

class SettingsEditor;
class SimulationController;

class ParameterPanel : public QWidget {
    Q_OBJECT
public:
    /// `controller` is not owned and must outlive the panel.
    /// Every edit goes through `editor` (not owned), which keeps the undo steps.
    ParameterPanel(SimulationController* controller, SettingsEditor* editor, QWidget* parent = nullptr);

    SettingsEditor* editor() const { return m_editor; }

    /// The lesson's `controls`: their rows are shown first, in this order.
    /// Names the panel does not know are ignored with a warning. An empty list shows every row.
    void setLessonControls(const QStringList& controls);
    const QStringList& lessonControls() const { return m_controls; }
    bool showAll() const { return m_showAll; }

    /// Row keys ("gravity_x", "wall_model", …) in panel order, and the visible ones.
    QStringList rowKeys() const;
    QStringList visibleRows() const;
    /// Section keys in their current order (the lesson's first), visible ones only.
    QStringList visibleSections() const;
    /// The widget that edits a control of the parameter table (sim/world/parameters.h):
    /// its row's field, a model's tick box for its "enabled" row, a wall's
    /// tick box; nullptr for a name the panel has no control for.
    QWidget* controlWidget(const QString& control) const;
    /// The rows a control name shows (empty for an unknown name).
    static QStringList rowsForControl(const QString& control);
    /// The objectName stem of a row's widgets: "wind_smoothed_step" gives
    /// "windSmoothedStep", then "…Check", "…Combo", "…Control", "…Spin", "…Slider".
    static QString objectStem(std::string_view control);

public slots:
    /// Shows the world's current values (after a new scene, a reset, an undo or a refused edit).
    void refresh();
    void setShowAll(bool on);

private:
    using Settings = sim::WorldSettings;

    struct Row {
        QString key;
        QString section;
        QString label; // for undo texts
        QWidget* field = nullptr;
    };
    struct Section {
        QString key;
        QGroupBox* box = nullptr;
        QFormLayout* form = nullptr;
    };
    /// A number row, in the world's units (px, mass units, s): the control
    /// shows it in the units of the view (ui/drawing/display_units.h).
    struct Number {
        double lo = 0.0;
        double hi = 1.0;
        double sliderLo = 0.0;
        double sliderHi = 1.0;
        bool log = false;
        bool whole = false;
        std::function<QString()> pixelUnit; ///< the row's unit as the world has it ("px/s²")
        double extraFactor = 1.0; ///< on top of the units' conversion (dt: s → ms)
        QString fixedSuffix;      ///< instead of the shown unit (dt: " ms")
    };
    /// The control's range, digits and suffix for `spec` shown in `unit`.
    static NumberControl::Spec controlSpec(const Number& spec, const ShownUnit& unit);

    QGroupBox* addSection(const QString& key, const QString& title, std::function<bool(const Settings&)> enabled = {},
                          std::function<void(Settings&, bool)> setEnabled = {});
    /// A section whose tick box is the model's "enabled" row ("models.<model>.enabled").
    QGroupBox* addModelSection(const QString& model, const QString& title);
    /// The row of sim/world/parameters.h with this key, as a spin box and slider, a
    /// combo box or a check box named after its control ("dragK" + "Spin").
    QWidget* addParameterWidget(std::string_view key);
    template <class W = QWidget>
    W* addParameter(std::string_view key)
    {
        return static_cast<W*>(addParameterWidget(key));
    }
    NumberControl* addNumber(const QString& key, const QString& objectName, const QString& label, const Number& spec,
                             std::function<double(const Settings&)> get, std::function<void(Settings&, double)> set);
    QComboBox* addChoice(const QString& key, const QString& objectName, const QString& label,
                         std::span<const std::string_view> names, std::function<int(const Settings&)> get,
                         std::function<void(Settings&, int)> set);
    QCheckBox* addSwitch(const QString& key, const QString& objectName, const QString& label, const QString& tip,
                         std::function<bool(const Settings&)> get, std::function<void(Settings&, bool)> set);
    void addWallSides();
    void addSeed();
    void addBallCount();
    void addSpawnSpeed(const QString& row);
    void addFullyInside();
    void addTimeScale();
    void addRow(const QString& key, const QString& label, QWidget* field, const QString& tip = {});

    /// Copies the world's settings, applies `change`, pushes the whole struct;
    /// on success puts it on the undo stack (merging slider drags).
    void edit(const QString& key, const std::function<void(Settings&)>& change, bool dragging = false);
    void editSpawn(const QString& text, const sim::SpawnSettings& spawn);
    void updateVisibility();
    void addUnplacedRows();
    Section& currentSection(); // the one being built
    int rowIndex(const QString& key) const;

    SimulationController* m_controller; // not owned
    SettingsEditor* m_editor; // not owned
    QVBoxLayout* m_sectionsLayout = nullptr;
    QCheckBox* m_showAllBox = nullptr;
    QLabel* m_hiddenNote = nullptr;
    std::vector<Section> m_sections;
    std::vector<Row> m_rows;
    QString m_currentSection; // while building
    QHash<QString, QWidget*> m_otherControls; // controls that are part of a row: the four walls
    std::vector<std::function<void()>> m_refreshers; // world → widget
    QStringList m_controls;
    bool m_showAll = false;
    bool m_refreshing = false;
    int m_dragSession = 0; // a new number per slider press: one drag merges into one undo step
};

} // namespace forcelab
