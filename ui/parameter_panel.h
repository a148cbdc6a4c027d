#pragma once
// The Parameters panel: live controls for the world's settings. Each edit
// copies the world's settings, changes one field and pushes the whole struct
// through the controller. A refused push shows its error (the controller
// signals it) and every control returns to the world's value. Controls carry
// objectNames so tests and lessons can find them.

#include "sim/world_settings.h"

#include <QString>
#include <QWidget>

#include <functional>
#include <span>
#include <string_view>
#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QGroupBox;
class QSpinBox;
class QVBoxLayout;

namespace forcelab {

class SimulationController;

class ParameterPanel : public QWidget {
    Q_OBJECT
public:
    /// `controller` is not owned and must outlive the panel.
    explicit ParameterPanel(SimulationController* controller, QWidget* parent = nullptr);

public slots:
    /// Shows the world's current values (after a new scene, a reset or a refused edit).
    void refresh();

private:
    using Settings = sim::WorldSettings;

    /// A number control: range and step in the shown unit; `toShown` converts
    /// the stored value to the shown one (e.g. s → ms).
    struct Number {
        double min = 0.0;
        double max = 1.0;
        double step = 0.1;
        int decimals = 2;
        QString suffix;
        double toShown = 1.0;
    };

    QGroupBox* addGroup(const QString& objectName, const QString& title,
                        std::function<bool(const Settings&)> enabled = {},
                        std::function<void(Settings&, bool)> setEnabled = {});
    QDoubleSpinBox* addNumber(QGroupBox* group, const QString& objectName, const QString& label, const Number& spec,
                              std::function<double(const Settings&)> get, std::function<void(Settings&, double)> set);
    QSpinBox* addInteger(QGroupBox* group, const QString& objectName, const QString& label, int min, int max,
                         std::function<int(const Settings&)> get, std::function<void(Settings&, int)> set);
    /// A combo box of names listed in the enum's declaration order.
    QComboBox* addChoice(QGroupBox* group, const QString& objectName, const QString& label,
                         std::span<const std::string_view> names, std::function<int(const Settings&)> get,
                         std::function<void(Settings&, int)> set);
    void addTimeScale(QGroupBox* group);

    /// Copies the world's settings, applies `change`, pushes the whole struct.
    void edit(const std::function<void(Settings&)>& change);

    SimulationController* m_controller; // not owned
    QVBoxLayout* m_layout = nullptr;
    std::vector<std::function<void()>> m_refreshers; // one per control: world → widget
    bool m_refreshing = false; // true while widgets are set from the world
};

} // namespace forcelab
