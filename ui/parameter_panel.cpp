#include "parameter_panel.h"

#include "simulation_controller.h"

#include "sim/names.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>

#include <cmath>

namespace forcelab {

ParameterPanel::ParameterPanel(SimulationController* controller, QWidget* parent)
    : QWidget(parent)
    , m_controller(controller)
{
    setObjectName(QStringLiteral("parameterPanel"));
    m_layout = new QVBoxLayout(this);

    using S = Settings;
    QGroupBox* gravity = addGroup(QStringLiteral("gravityGroup"), tr("Gravity"),
                                  [](const S& s) { return s.gravity.enabled; },
                                  [](S& s, bool on) { s.gravity.enabled = on; });
    const Number accel{-1e6, 1e6, 10.0, 1, QStringLiteral(" px/s²")};
    addNumber(gravity, QStringLiteral("gravityXSpin"), tr("g<sub>x</sub> (right)"), accel,
              [](const S& s) { return s.gravity.g.x(); }, [](S& s, double v) { s.gravity.g.x() = v; });
    addNumber(gravity, QStringLiteral("gravityYSpin"), tr("g<sub>y</sub> (down)"), accel,
              [](const S& s) { return s.gravity.g.y(); }, [](S& s, double v) { s.gravity.g.y() = v; });

    QGroupBox* walls = addGroup(QStringLiteral("wallsGroup"), tr("Walls"));
    addChoice(walls, QStringLiteral("wallModelCombo"), tr("Model"), sim::wallModelNames(),
              [](const S& s) { return static_cast<int>(s.walls.model); },
              [](S& s, int i) { s.walls.model = static_cast<sim::WallModel>(i); });
    addNumber(walls, QStringLiteral("restitutionSpin"), tr("Restitution"), Number{0.0, 1.0, 0.05, 3, {}},
              [](const S& s) { return s.walls.restitution; }, [](S& s, double v) { s.walls.restitution = v; });

    QGroupBox* drag = addGroup(QStringLiteral("dragGroup"), tr("Drag"),
                               [](const S& s) { return s.drag.enabled; },
                               [](S& s, bool on) { s.drag.enabled = on; });
    addChoice(drag, QStringLiteral("dragLawCombo"), tr("Law"), sim::dragLawNames(),
              [](const S& s) { return static_cast<int>(s.drag.law); },
              [](S& s, int i) { s.drag.law = static_cast<sim::DragLaw>(i); });
    QDoubleSpinBox* k = addNumber(drag, QStringLiteral("dragKSpin"), tr("k"), Number{0.0, 1e4, 0.01, 4, {}},
                                  [](const S& s) { return s.drag.k; }, [](S& s, double v) { s.drag.k = v; });
    // The unit of k follows the law: a = -k v (1/s) or a = -k |v| v (1/px).
    m_refreshers.push_back([this, k] {
        const bool linear = m_controller->world().settings().drag.law == sim::DragLaw::Linear;
        k->setSuffix(linear ? QStringLiteral(" 1/s") : QStringLiteral(" 1/px"));
    });

    QGroupBox* collisions = addGroup(QStringLiteral("collisionsGroup"), tr("Collisions"));
    addChoice(collisions, QStringLiteral("responseCombo"), tr("Response"), sim::responseNames(),
              [](const S& s) { return static_cast<int>(s.collisions.response); },
              [](S& s, int i) { s.collisions.response = static_cast<sim::Response>(i); });
    addChoice(collisions, QStringLiteral("detectionCombo"), tr("Detection"), sim::detectionNames(),
              [](const S& s) { return static_cast<int>(s.collisions.detection); },
              [](S& s, int i) { s.collisions.detection = static_cast<sim::Detection>(i); });
    addNumber(collisions, QStringLiteral("ballRestitutionSpin"), tr("Restitution"), Number{0.0, 1.0, 0.05, 3, {}},
              [](const S& s) { return s.collisions.restitution; },
              [](S& s, double v) { s.collisions.restitution = v; });

    QGroupBox* time = addGroup(QStringLiteral("timeGroup"), tr("Time"));
    addChoice(time, QStringLiteral("integratorCombo"), tr("Integrator"), sim::integratorNames(),
              [](const S& s) { return static_cast<int>(s.time.integrator); },
              [](S& s, int i) { s.time.integrator = static_cast<sim::IntegratorKind>(i); });
    addNumber(time, QStringLiteral("dtSpin"), tr("Step dt"), Number{0.001, 500.0, 1.0, 3, QStringLiteral(" ms"), 1e3},
              [](const S& s) { return s.time.dt; }, [](S& s, double v) { s.time.dt = v; });
    addInteger(time, QStringLiteral("substepsSpin"), tr("Sub-steps"), 1, 1000,
               [](const S& s) { return s.time.substeps; }, [](S& s, int v) { s.time.substeps = v; });
    addTimeScale(time);

    m_layout->addStretch(1);

    connect(m_controller, &SimulationController::settingsChanged, this, &ParameterPanel::refresh);
    connect(m_controller, &SimulationController::timeScaleChanged, this, &ParameterPanel::refresh);
    refresh();
}

void ParameterPanel::refresh()
{
    m_refreshing = true;
    for (const auto& refresher : m_refreshers)
        refresher();
    m_refreshing = false;
}

void ParameterPanel::edit(const std::function<void(Settings&)>& change)
{
    if (m_refreshing)
        return;
    Settings s = m_controller->world().settings();
    change(s);
    // On success the controller's settingsChanged refreshes every control;
    // on failure put the refused control back to the world's value.
    if (!m_controller->setSettings(s))
        refresh();
}

QGroupBox* ParameterPanel::addGroup(const QString& objectName, const QString& title,
                                    std::function<bool(const Settings&)> enabled,
                                    std::function<void(Settings&, bool)> setEnabled)
{
    auto* group = new QGroupBox(title, this);
    group->setObjectName(objectName);
    auto* form = new QFormLayout(group);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    if (enabled && setEnabled) {
        // A checkable group: the model is on when ticked, and its fields are
        // greyed out while it is off.
        group->setCheckable(true);
        connect(group, &QGroupBox::toggled, this,
                [this, setEnabled](bool on) { edit([&](Settings& s) { setEnabled(s, on); }); });
        m_refreshers.push_back([this, group, enabled] {
            const QSignalBlocker block(group);
            group->setChecked(enabled(m_controller->world().settings()));
        });
    }
    m_layout->addWidget(group);
    return group;
}

QDoubleSpinBox* ParameterPanel::addNumber(QGroupBox* group, const QString& objectName, const QString& label,
                                          const Number& spec, std::function<double(const Settings&)> get,
                                          std::function<void(Settings&, double)> set)
{
    auto* box = new QDoubleSpinBox(group);
    box->setObjectName(objectName);
    box->setRange(spec.min, spec.max);
    box->setDecimals(spec.decimals);
    box->setSingleStep(spec.step);
    box->setSuffix(spec.suffix);
    box->setAlignment(Qt::AlignRight);
    // Edits arrive when the user presses Enter or leaves the field, not at
    // every typed digit (typing "980" must not push 9 and 98 on the way).
    box->setKeyboardTracking(false);
    box->setAccelerated(true);
    const double toShown = spec.toShown;
    connect(box, &QDoubleSpinBox::valueChanged, this,
            [this, set, toShown](double shown) { edit([&](Settings& s) { set(s, shown / toShown); }); });
    m_refreshers.push_back([this, box, get, toShown] {
        const QSignalBlocker block(box);
        box->setValue(get(m_controller->world().settings()) * toShown);
    });
    auto* text = new QLabel(label, group);
    text->setBuddy(box);
    static_cast<QFormLayout*>(group->layout())->addRow(text, box);
    return box;
}

QSpinBox* ParameterPanel::addInteger(QGroupBox* group, const QString& objectName, const QString& label, int min,
                                     int max, std::function<int(const Settings&)> get,
                                     std::function<void(Settings&, int)> set)
{
    auto* box = new QSpinBox(group);
    box->setObjectName(objectName);
    box->setRange(min, max);
    box->setAlignment(Qt::AlignRight);
    box->setKeyboardTracking(false);
    connect(box, &QSpinBox::valueChanged, this, [this, set](int v) { edit([&](Settings& s) { set(s, v); }); });
    m_refreshers.push_back([this, box, get] {
        const QSignalBlocker block(box);
        box->setValue(get(m_controller->world().settings()));
    });
    static_cast<QFormLayout*>(group->layout())->addRow(label, box);
    return box;
}

QComboBox* ParameterPanel::addChoice(QGroupBox* group, const QString& objectName, const QString& label,
                                     std::span<const std::string_view> names, std::function<int(const Settings&)> get,
                                     std::function<void(Settings&, int)> set)
{
    auto* combo = new QComboBox(group);
    combo->setObjectName(objectName);
    for (std::string_view name : names)
        combo->addItem(QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size())));
    connect(combo, &QComboBox::currentIndexChanged, this, [this, set](int index) {
        if (index >= 0)
            edit([&](Settings& s) { set(s, index); });
    });
    m_refreshers.push_back([this, combo, get] {
        const QSignalBlocker block(combo);
        combo->setCurrentIndex(get(m_controller->world().settings()));
    });
    static_cast<QFormLayout*>(group->layout())->addRow(label, combo);
    return combo;
}

void ParameterPanel::addTimeScale(QGroupBox* group)
{
    // Not a world setting: how fast real time drives simulated time.
    auto* box = new QDoubleSpinBox(group);
    box->setObjectName(QStringLiteral("timeScaleSpin"));
    box->setRange(SimulationController::kMinTimeScale, SimulationController::kMaxTimeScale);
    box->setDecimals(2);
    box->setSingleStep(0.05);
    box->setSuffix(QStringLiteral(" ×"));
    box->setAlignment(Qt::AlignRight);
    box->setKeyboardTracking(false);
    box->setToolTip(tr("Simulated seconds per real second: below 1 is slow motion"));
    connect(box, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        if (!m_refreshing)
            m_controller->setTimeScale(v);
    });
    m_refreshers.push_back([this, box] {
        const QSignalBlocker block(box);
        box->setValue(m_controller->timeScale());
    });
    static_cast<QFormLayout*>(group->layout())->addRow(tr("Speed"), box);
}

} // namespace forcelab
