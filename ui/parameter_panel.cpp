#include "parameter_panel.h"

#include "number_control.h"
#include "parameter_commands.h"
#include "simulation_controller.h"

#include "sim/names.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QRegularExpressionValidator>
#include <QSignalBlocker>
#include <QSlider>
#include <QUndoStack>
#include <QVBoxLayout>
#include <QtDebug>

#include <algorithm>
#include <cmath>
#include <limits>

namespace forcelab {

namespace {

// Which rows each lesson `controls` name shows. A name may show rows of
// several sections ("restitution": the walls' and the balls').
const QHash<QString, QStringList>& controlRows()
{
    static const QHash<QString, QStringList> rows{
        {QStringLiteral("gravity"), {"gravity_x", "gravity_y"}},
        {QStringLiteral("drag"), {"drag_law", "drag_k", "drag_scale"}},
        {QStringLiteral("wind"), {"wind_mode", "wind_strength", "wind_scale", "wind_smoothed_step", "wind_frequency"}},
        {QStringLiteral("wind_compare"), {"wind_mode", "wind_compare", "wind_strength"}},
        {QStringLiteral("random_accel"), {"random_fixed", "random_strength"}},
        {QStringLiteral("point"), {"point_kind", "point_x", "point_y", "point_strength", "point_clamp", "point_scale"}},
        {QStringLiteral("spring"), {"spring_k", "spring_x", "spring_y"}},
        {QStringLiteral("mutual_gravity"), {"mutual_g", "mutual_softening"}},
        {QStringLiteral("homing"), {"homing_strength"}},
        {QStringLiteral("pointer"), {"pointer_strength", "pointer_clamp"}},
        {QStringLiteral("speed_limit"), {"speed_limit"}},
        {QStringLiteral("collisions"), {"detection", "response", "ball_restitution", "continuous", "resting"}},
        {QStringLiteral("walls"), {"wall_sides", "wall_model", "wall_restitution"}},
        {QStringLiteral("wall_model"), {"wall_model"}},
        {QStringLiteral("restitution"), {"wall_restitution", "ball_restitution"}},
        {QStringLiteral("middle_wall"), {"middle_wall"}},
        {QStringLiteral("centre_only"), {"centre_only"}},
        {QStringLiteral("integrator"), {"integrator"}},
        {QStringLiteral("dt"), {"dt"}},
        {QStringLiteral("substeps"), {"substeps"}},
        {QStringLiteral("tolerance"), {"tolerance"}},
        {QStringLiteral("per_frame"), {"per_frame"}},
        {QStringLiteral("seed"), {"seed"}},
        {QStringLiteral("spawn"), {"ball_count"}},
        {QStringLiteral("fully_inside"), {"fully_inside"}},
        {QStringLiteral("point_clamp"), {"point_clamp"}},
        {QStringLiteral("response"), {"response"}},
        {QStringLiteral("detection"), {"detection"}},
        {QStringLiteral("resting"), {"resting"}},
        {QStringLiteral("time_scale"), {"time_scale"}},
    };
    return rows;
}

// Shown whatever the lesson lists: how fast the film runs.
const QStringList kAlwaysShown{QStringLiteral("time_scale")};

QString qs(std::string_view s)
{
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

} // namespace

ParameterPanel::ParameterPanel(SimulationController* controller, QWidget* parent)
    : QWidget(parent)
    , m_controller(controller)
{
    setObjectName(QStringLiteral("parameterPanel"));
    m_undoStack = new QUndoStack(this);
    m_undoStack->setObjectName(QStringLiteral("parameterUndoStack"));

    auto* outer = new QVBoxLayout(this);
    m_showAllBox = new QCheckBox(tr("Show all parameters"), this);
    m_showAllBox->setObjectName(QStringLiteral("showAllCheck"));
    m_showAllBox->setToolTip(tr("Besides the lesson's own controls, show every setting of the world"));
    connect(m_showAllBox, &QCheckBox::toggled, this, &ParameterPanel::setShowAll);
    outer->addWidget(m_showAllBox);
    m_sectionsLayout = new QVBoxLayout;
    m_sectionsLayout->setContentsMargins(0, 0, 0, 0);
    outer->addLayout(m_sectionsLayout);
    m_hiddenNote = new QLabel(this);
    m_hiddenNote->setObjectName(QStringLiteral("hiddenNote"));
    m_hiddenNote->setWordWrap(true);
    m_hiddenNote->setStyleSheet(QStringLiteral("color: #5a6270"));
    outer->addWidget(m_hiddenNote);
    outer->addStretch(1);

    using S = Settings;
    const QString accel = QStringLiteral(" px/s²");
    const QString inverseSquare = QStringLiteral(" px³/s²");

    addSection(QStringLiteral("gravity"), tr("Gravity"), [](const S& s) { return s.gravity.enabled; },
               [](S& s, bool on) { s.gravity.enabled = on; });
    const Number g{-1e7, 1e7, -2000.0, 2000.0, false, 1, 0, accel};
    addNumber(QStringLiteral("gravity_x"), QStringLiteral("gravityX"), tr("g<sub>x</sub> (right)"), g,
              [](const S& s) { return s.gravity.g.x(); }, [](S& s, double v) { s.gravity.g.x() = v; });
    addNumber(QStringLiteral("gravity_y"), QStringLiteral("gravityY"), tr("g<sub>y</sub> (down)"), g,
              [](const S& s) { return s.gravity.g.y(); }, [](S& s, double v) { s.gravity.g.y() = v; });

    addSection(QStringLiteral("walls"), tr("Walls"));
    addWallSides();
    addChoice(QStringLiteral("wall_model"), QStringLiteral("wallModelCombo"), tr("Model"), sim::wallModelNames(),
              [](const S& s) { return static_cast<int>(s.walls.model); },
              [](S& s, int i) { s.walls.model = static_cast<sim::WallModel>(i); });
    const Number unit{0.0, 1.0, 0.0, 1.0, false, 3, 0, {}};
    addNumber(QStringLiteral("wall_restitution"), QStringLiteral("restitution"), tr("Restitution"), unit,
              [](const S& s) { return s.walls.restitution; }, [](S& s, double v) { s.walls.restitution = v; });
    addSwitch(QStringLiteral("middle_wall"), QStringLiteral("middleWallCheck"), tr("Middle wall"),
              tr("A wall down the middle of the box; each ball stays on its side"),
              [](const S& s) { return s.walls.middle; }, [](S& s, bool on) { s.walls.middle = on; });
    addSwitch(QStringLiteral("centre_only"), QStringLiteral("centreOnlyCheck"), tr("Test the centre only"),
              tr("The wall test uses the ball's centre instead of its edge (stage 3's bug)"),
              [](const S& s) { return s.walls.centreOnly; }, [](S& s, bool on) { s.walls.centreOnly = on; });

    addSection(QStringLiteral("drag"), tr("Drag"), [](const S& s) { return s.drag.enabled; },
               [](S& s, bool on) { s.drag.enabled = on; });
    addChoice(QStringLiteral("drag_law"), QStringLiteral("dragLawCombo"), tr("Law"), sim::dragLawNames(),
              [](const S& s) { return static_cast<int>(s.drag.law); },
              [](S& s, int i) { s.drag.law = static_cast<sim::DragLaw>(i); });
    NumberControl* k = addNumber(QStringLiteral("drag_k"), QStringLiteral("dragK"), tr("k"),
                                 Number{0.0, 1e6, 1e-4, 10.0, true, 4, 4, {}},
                                 [](const S& s) { return s.drag.k; }, [](S& s, double v) { s.drag.k = v; });
    addChoice(QStringLiteral("drag_scale"), QStringLiteral("dragScaleCombo"), tr("Scaling"), sim::forceScaleNames(),
              [](const S& s) { return static_cast<int>(s.drag.scale); },
              [](S& s, int i) { s.drag.scale = static_cast<sim::ForceScale>(i); });
    // The unit of k follows the law: a = -k v (1/s) or a = -k |v| v (1/px).
    m_refreshers.push_back([this, k] {
        const bool linear = m_controller->world().settings().drag.law == sim::DragLaw::Linear;
        k->spinBox()->setSuffix(linear ? QStringLiteral(" 1/s") : QStringLiteral(" 1/px"));
    });

    addSection(QStringLiteral("wind"), tr("Wind"));
    addChoice(QStringLiteral("wind_mode"), QStringLiteral("windModeCombo"), tr("Mode"), sim::windModeNames(),
              [](const S& s) { return static_cast<int>(s.wind.mode); },
              [](S& s, int i) { s.wind.mode = static_cast<sim::WindMode>(i); });
    addNumber(QStringLiteral("wind_strength"), QStringLiteral("windStrength"), tr("Strength"),
              Number{0.0, 1e7, 1.0, 1e4, true, 4, 4, accel},
              [](const S& s) { return s.wind.strength; }, [](S& s, double v) { s.wind.strength = v; });
    addChoice(QStringLiteral("wind_scale"), QStringLiteral("windScaleCombo"), tr("Scaling"), sim::forceScaleNames(),
              [](const S& s) { return static_cast<int>(s.wind.scale); },
              [](S& s, int i) { s.wind.scale = static_cast<sim::ForceScale>(i); });
    addNumber(QStringLiteral("wind_smoothed_step"), QStringLiteral("windSmoothedStep"), tr("Smoothed step"),
              Number{0.0, 1.0, 0.001, 1.0, true, 4, 3, {}},
              [](const S& s) { return s.wind.smoothedStep; }, [](S& s, double v) { s.wind.smoothedStep = v; });
    addNumber(QStringLiteral("wind_frequency"), QStringLiteral("windFrequency"), tr("Noise frequency"),
              Number{0.0, 1e3, 0.01, 100.0, true, 4, 3, QStringLiteral(" Hz")},
              [](const S& s) { return s.wind.noiseFrequency; }, [](S& s, double v) { s.wind.noiseFrequency = v; });
    addChoice(QStringLiteral("wind_compare"), QStringLiteral("windCompareCombo"), tr("Compare with"),
              sim::windModeNames(), [](const S& s) { return static_cast<int>(s.wind.compare); },
              [](S& s, int i) { s.wind.compare = static_cast<sim::WindMode>(i); });

    addSection(QStringLiteral("random_accel"), tr("Random acceleration"),
               [](const S& s) { return s.randomAccel.enabled; }, [](S& s, bool on) { s.randomAccel.enabled = on; });
    addSwitch(QStringLiteral("random_fixed"), QStringLiteral("randomFixedCheck"), tr("One value per ball"),
              tr("Off: a new random value every step. On: each ball keeps the value it drew first"),
              [](const S& s) { return s.randomAccel.fixed; }, [](S& s, bool on) { s.randomAccel.fixed = on; });
    addNumber(QStringLiteral("random_strength"), QStringLiteral("randomStrength"), tr("Strength"),
              Number{0.0, 1e7, 1.0, 1e4, true, 4, 4, accel},
              [](const S& s) { return s.randomAccel.strength; }, [](S& s, double v) { s.randomAccel.strength = v; });

    addSection(QStringLiteral("point"), tr("Point force"), [](const S& s) { return s.point.enabled; },
               [](S& s, bool on) { s.point.enabled = on; });
    addChoice(QStringLiteral("point_kind"), QStringLiteral("pointKindCombo"), tr("Kind"), sim::pointKindNames(),
              [](const S& s) { return static_cast<int>(s.point.kind); },
              [](S& s, int i) { s.point.kind = static_cast<sim::PointKind>(i); });
    const Number position{-1e7, 1e7, 0.0, 1000.0, false, 1, 0, QStringLiteral(" px")};
    addNumber(QStringLiteral("point_x"), QStringLiteral("pointX"), tr("x"), position,
              [](const S& s) { return s.point.position.x(); }, [](S& s, double v) { s.point.position.x() = v; });
    addNumber(QStringLiteral("point_y"), QStringLiteral("pointY"), tr("y"), position,
              [](const S& s) { return s.point.position.y(); }, [](S& s, double v) { s.point.position.y() = v; });
    addNumber(QStringLiteral("point_strength"), QStringLiteral("pointStrength"), tr("Strength"),
              Number{0.0, 1e15, 1e3, 1e9, true, 4, 4, inverseSquare},
              [](const S& s) { return s.point.strength; }, [](S& s, double v) { s.point.strength = v; });
    addNumber(QStringLiteral("point_clamp"), QStringLiteral("pointClamp"), tr("Clamp (0 = off)"),
              Number{0.0, 1e9, 10.0, 1e6, true, 4, 4, accel},
              [](const S& s) { return s.point.maxAccel; }, [](S& s, double v) { s.point.maxAccel = v; });
    addChoice(QStringLiteral("point_scale"), QStringLiteral("pointScaleCombo"), tr("Scaling"),
              sim::forceScaleNames(), [](const S& s) { return static_cast<int>(s.point.scale); },
              [](S& s, int i) { s.point.scale = static_cast<sim::ForceScale>(i); });

    addSection(QStringLiteral("spring"), tr("Spring"), [](const S& s) { return s.spring.enabled; },
               [](S& s, bool on) { s.spring.enabled = on; });
    addNumber(QStringLiteral("spring_k"), QStringLiteral("springK"), tr("k"),
              Number{0.0, 1e6, 0.01, 1e3, true, 4, 4, QStringLiteral(" 1/s²")},
              [](const S& s) { return s.spring.k; }, [](S& s, double v) { s.spring.k = v; });
    addNumber(QStringLiteral("spring_x"), QStringLiteral("springX"), tr("Anchor x"), position,
              [](const S& s) { return s.spring.anchor.x(); }, [](S& s, double v) { s.spring.anchor.x() = v; });
    addNumber(QStringLiteral("spring_y"), QStringLiteral("springY"), tr("Anchor y"), position,
              [](const S& s) { return s.spring.anchor.y(); }, [](S& s, double v) { s.spring.anchor.y() = v; });

    addSection(QStringLiteral("mutual_gravity"), tr("Gravity between balls"),
               [](const S& s) { return s.mutualGravity.enabled; },
               [](S& s, bool on) { s.mutualGravity.enabled = on; });
    addNumber(QStringLiteral("mutual_g"), QStringLiteral("mutualG"), tr("G"),
              Number{-1e12, 1e12, 1.0, 1e8, true, 4, 4, QStringLiteral(" px³/(m·s²)")},
              [](const S& s) { return s.mutualGravity.G; }, [](S& s, double v) { s.mutualGravity.G = v; });
    addNumber(QStringLiteral("mutual_softening"), QStringLiteral("mutualSoftening"), tr("Softening ε"),
              Number{0.0, 1e6, 0.1, 100.0, true, 4, 3, QStringLiteral(" px")},
              [](const S& s) { return s.mutualGravity.softening; },
              [](S& s, double v) { s.mutualGravity.softening = v; });

    addSection(QStringLiteral("homing"), tr("Homing"), [](const S& s) { return s.homing.enabled; },
               [](S& s, bool on) { s.homing.enabled = on; });
    addNumber(QStringLiteral("homing_strength"), QStringLiteral("homingStrength"), tr("Strength"),
              Number{0.0, 1e6, 0.01, 1e3, true, 4, 4, QStringLiteral(" 1/s²")},
              [](const S& s) { return s.homing.strength; }, [](S& s, double v) { s.homing.strength = v; });

    addSection(QStringLiteral("pointer"), tr("Pointer force"), [](const S& s) { return s.pointer.enabled; },
               [](S& s, bool on) { s.pointer.enabled = on; });
    addNumber(QStringLiteral("pointer_strength"), QStringLiteral("pointerStrength"), tr("Strength"),
              Number{0.0, 1e15, 1e3, 1e9, true, 4, 4, inverseSquare},
              [](const S& s) { return s.pointer.strength; }, [](S& s, double v) { s.pointer.strength = v; });
    addNumber(QStringLiteral("pointer_clamp"), QStringLiteral("pointerClamp"), tr("Clamp (0 = off)"),
              Number{0.0, 1e9, 10.0, 1e6, true, 4, 4, accel},
              [](const S& s) { return s.pointer.maxAccel; }, [](S& s, double v) { s.pointer.maxAccel = v; });

    addSection(QStringLiteral("speed_limit"), tr("Speed limit"), [](const S& s) { return s.speedLimit.enabled; },
               [](S& s, bool on) { s.speedLimit.enabled = on; });
    addNumber(QStringLiteral("speed_limit"), QStringLiteral("speedLimit"), tr("Largest speed"),
              Number{0.0, 1e9, 10.0, 1e5, true, 4, 4, QStringLiteral(" px/s")},
              [](const S& s) { return s.speedLimit.max; }, [](S& s, double v) { s.speedLimit.max = v; });

    addSection(QStringLiteral("collisions"), tr("Collisions"));
    addChoice(QStringLiteral("detection"), QStringLiteral("detectionCombo"), tr("Detection"), sim::detectionNames(),
              [](const S& s) { return static_cast<int>(s.collisions.detection); },
              [](S& s, int i) { s.collisions.detection = static_cast<sim::Detection>(i); });
    addChoice(QStringLiteral("response"), QStringLiteral("responseCombo"), tr("Response"), sim::responseNames(),
              [](const S& s) { return static_cast<int>(s.collisions.response); },
              [](S& s, int i) { s.collisions.response = static_cast<sim::Response>(i); });
    addNumber(QStringLiteral("ball_restitution"), QStringLiteral("ballRestitution"), tr("Restitution"), unit,
              [](const S& s) { return s.collisions.restitution; },
              [](S& s, double v) { s.collisions.restitution = v; });
    addSwitch(QStringLiteral("continuous"), QStringLiteral("continuousCheck"), tr("Continuous"),
              tr("Find the moment of impact inside the step"),
              [](const S& s) { return s.collisions.continuous; }, [](S& s, bool on) { s.collisions.continuous = on; });
    addSwitch(QStringLiteral("resting"), QStringLiteral("restingCheck"), tr("Resting contacts"),
              tr("Under gravity, solve the contacts of a pile several times per step so it stands; "
                 "off: one pass, and a pile sinks into itself"),
              [](const S& s) { return s.collisions.resting; }, [](S& s, bool on) { s.collisions.resting = on; });

    addSection(QStringLiteral("time"), tr("Time"));
    addTimeScale();
    addChoice(QStringLiteral("integrator"), QStringLiteral("integratorCombo"), tr("Integrator"),
              sim::integratorNames(), [](const S& s) { return static_cast<int>(s.time.integrator); },
              [](S& s, int i) { s.time.integrator = static_cast<sim::IntegratorKind>(i); });
    addNumber(QStringLiteral("dt"), QStringLiteral("dt"), tr("Step dt"),
              Number{0.0, 1000.0, 0.1, 100.0, true, 3, 4, QStringLiteral(" ms"), 1e3},
              [](const S& s) { return s.time.dt; }, [](S& s, double v) { s.time.dt = v; });
    addNumber(QStringLiteral("substeps"), QStringLiteral("substeps"), tr("Sub-steps"),
              Number{1.0, 1000.0, 1.0, 1000.0, true, 0, 0, {}},
              [](const S& s) { return static_cast<double>(s.time.substeps); },
              [](S& s, double v) { s.time.substeps = static_cast<int>(std::lround(v)); });
    addNumber(QStringLiteral("tolerance"), QStringLiteral("tolerance"), tr("rk45 tolerance"),
              Number{1e-15, 1.0, 1e-12, 1e-2, true, 3, 3, {}},
              [](const S& s) { return s.time.tolerance; }, [](S& s, double v) { s.time.tolerance = v; });
    addSwitch(QStringLiteral("per_frame"), QStringLiteral("perFrameCheck"), tr("Move per frame"),
              tr("Ignore dt: every step moves the balls as if 1/60 s had passed (stage 5's bug)"),
              [](const S& s) { return s.time.perFrame; }, [](S& s, bool on) { s.time.perFrame = on; });
    addSeed();

    addSection(QStringLiteral("balls"), tr("Balls"));
    addBallCount();
    addFullyInside();

    connect(m_controller, &SimulationController::settingsChanged, this, &ParameterPanel::refresh);
    connect(m_controller, &SimulationController::sceneChanged, this, &ParameterPanel::refresh);
    connect(m_controller, &SimulationController::timeScaleChanged, this, &ParameterPanel::refresh);
    updateVisibility();
    refresh();
}

void ParameterPanel::refresh()
{
    m_refreshing = true;
    for (const auto& refresher : m_refreshers)
        refresher();
    m_refreshing = false;
}

QStringList ParameterPanel::rowsForControl(const QString& control)
{
    return controlRows().value(control);
}

void ParameterPanel::setLessonControls(const QStringList& controls)
{
    m_controls.clear();
    for (const QString& name : controls) {
        if (!controlRows().contains(name)) {
            qWarning("Parameters: the lesson control \"%s\" has no widgets here; ignored", qPrintable(name));
            continue;
        }
        m_controls.append(name);
    }
    updateVisibility();
}

void ParameterPanel::setShowAll(bool on)
{
    m_showAll = on;
    {
        const QSignalBlocker block(m_showAllBox);
        m_showAllBox->setChecked(on);
    }
    updateVisibility();
}

int ParameterPanel::rowIndex(const QString& key) const
{
    for (std::size_t i = 0; i < m_rows.size(); ++i)
        if (m_rows[i].key == key)
            return static_cast<int>(i);
    return -1;
}

void ParameterPanel::updateVisibility()
{
    // The lesson's rows, in the order its controls name them; then the rest.
    QStringList lessonRows;
    for (const QString& control : m_controls)
        for (const QString& row : controlRows().value(control))
            if (!lessonRows.contains(row))
                lessonRows.append(row);
    const bool everything = m_showAll || m_controls.isEmpty();

    // Sections in order of their first lesson row, then the others in panel order.
    QStringList sectionOrder;
    for (const QString& row : lessonRows)
        if (const int i = rowIndex(row); i >= 0 && !sectionOrder.contains(m_rows[std::size_t(i)].section))
            sectionOrder.append(m_rows[std::size_t(i)].section);
    for (const QString& always : kAlwaysShown)
        if (const int i = rowIndex(always); i >= 0 && !sectionOrder.contains(m_rows[std::size_t(i)].section))
            sectionOrder.append(m_rows[std::size_t(i)].section);
    for (const Section& section : m_sections)
        if (!sectionOrder.contains(section.key))
            sectionOrder.append(section.key);

    int hidden = 0;
    for (const Row& row : m_rows) {
        const bool shown = everything || lessonRows.contains(row.key) || kAlwaysShown.contains(row.key);
        hidden += shown ? 0 : 1;
        for (const Section& section : m_sections)
            if (section.key == row.section)
                section.form->setRowVisible(row.field, shown);
    }
    for (const Section& section : m_sections) {
        bool any = false;
        for (const Row& row : m_rows)
            any = any || (row.section == section.key &&
                          (everything || lessonRows.contains(row.key) || kAlwaysShown.contains(row.key)));
        section.box->setVisible(any);
        m_sectionsLayout->removeWidget(section.box);
    }
    for (const QString& key : sectionOrder)
        for (const Section& section : m_sections)
            if (section.key == key)
                m_sectionsLayout->addWidget(section.box);

    m_showAllBox->setVisible(!m_controls.isEmpty());
    m_hiddenNote->setText(hidden > 0 ? tr("%n more setting(s) under \"Show all parameters\".", nullptr, hidden)
                                     : QString());
    m_hiddenNote->setVisible(hidden > 0);
}

QStringList ParameterPanel::rowKeys() const
{
    QStringList keys;
    for (const Row& row : m_rows)
        keys.append(row.key);
    return keys;
}

QStringList ParameterPanel::visibleRows() const
{
    // In the order shown: by section position in the layout, then row order.
    QStringList keys;
    for (int i = 0; i < m_sectionsLayout->count(); ++i) {
        QWidget* box = m_sectionsLayout->itemAt(i)->widget();
        for (const Section& section : m_sections) {
            if (section.box != box || box->isHidden())
                continue;
            for (const Row& row : m_rows)
                if (row.section == section.key && section.form->isRowVisible(row.field))
                    keys.append(row.key);
        }
    }
    return keys;
}

QStringList ParameterPanel::visibleSections() const
{
    QStringList keys;
    for (int i = 0; i < m_sectionsLayout->count(); ++i) {
        QWidget* box = m_sectionsLayout->itemAt(i)->widget();
        for (const Section& section : m_sections)
            if (section.box == box && !box->isHidden())
                keys.append(section.key);
    }
    return keys;
}

void ParameterPanel::edit(const QString& key, const std::function<void(Settings&)>& change, bool dragging)
{
    if (m_refreshing)
        return;
    const Settings before = m_controller->world().settings();
    Settings after = before;
    change(after);
    // On success the controller's settingsChanged refreshes every control;
    // on failure the error is signalled and the control goes back.
    if (!m_controller->setSettings(after)) {
        refresh();
        return;
    }
    const int index = rowIndex(key);
    const QString label = index >= 0 ? m_rows[std::size_t(index)].label : key;
    m_undoStack->push(new SettingsCommand(m_controller, tr("Change %1").arg(label), before, after,
                                          dragging ? index : -1, m_dragSession));
}

void ParameterPanel::editSpawn(const QString& text, const sim::SpawnSettings& spawn)
{
    if (m_refreshing)
        return;
    const sim::SpawnSettings before = m_controller->spawn();
    if (!m_controller->respawn(spawn)) {
        refresh();
        return;
    }
    m_undoStack->push(new SpawnCommand(m_controller, text, before, spawn));
}

QGroupBox* ParameterPanel::addSection(const QString& key, const QString& title,
                                      std::function<bool(const Settings&)> enabled,
                                      std::function<void(Settings&, bool)> setEnabled)
{
    auto* box = new QGroupBox(title, this);
    box->setObjectName(key == QStringLiteral("mutual_gravity") ? QStringLiteral("mutualGravityGroup")
                       : key == QStringLiteral("speed_limit")  ? QStringLiteral("speedLimitGroup")
                       : key == QStringLiteral("random_accel") ? QStringLiteral("randomAccelGroup")
                                                               : key + QStringLiteral("Group"));
    auto* form = new QFormLayout(box);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    form->setLabelAlignment(Qt::AlignRight | Qt::AlignVCenter);
    if (enabled && setEnabled) {
        // A checkable section: the model is on when ticked; its fields are
        // greyed out while it is off.
        box->setCheckable(true);
        box->setToolTip(tr("Tick to switch %1 on").arg(title.toLower()));
        connect(box, &QGroupBox::toggled, this,
                [this, key, setEnabled](bool on) { edit(key, [&](Settings& s) { setEnabled(s, on); }); });
        m_refreshers.push_back([this, box, enabled] {
            const QSignalBlocker block(box);
            box->setChecked(enabled(m_controller->world().settings()));
        });
    }
    m_sections.push_back(Section{key, box, form});
    m_sectionsLayout->addWidget(box);
    m_currentSection = key;
    return box;
}

void ParameterPanel::addRow(const QString& key, const QString& label, QWidget* field, const QString& tip)
{
    Section& section = m_sections.back();
    auto* text = new QLabel(label, section.box);
    text->setBuddy(field);
    if (!tip.isEmpty()) {
        text->setToolTip(tip);
        field->setToolTip(tip);
    }
    section.form->addRow(text, field);
    QString plain = label;
    plain.remove(QStringLiteral("<sub>")).remove(QStringLiteral("</sub>"));
    m_rows.push_back(Row{key, section.key, section.box->title() + QLatin1Char(' ') + plain.toLower(), field});
}

NumberControl* ParameterPanel::addNumber(const QString& key, const QString& objectName, const QString& label,
                                         const Number& spec, std::function<double(const Settings&)> get,
                                         std::function<void(Settings&, double)> set)
{
    NumberControl::Spec s;
    s.min = spec.min;
    s.max = spec.max;
    s.sliderMin = spec.sliderMin;
    s.sliderMax = spec.sliderMax;
    s.scale = spec.log ? NumberControl::Scale::Log : NumberControl::Scale::Linear;
    s.decimals = spec.decimals;
    s.significant = spec.significant;
    s.suffix = spec.suffix;
    auto* control = new NumberControl(objectName, s, m_sections.back().box);
    const double toShown = spec.toShown;
    auto apply = [this, key, set, toShown](double shown, bool dragging) {
        edit(key, [&](Settings& st) { set(st, shown / toShown); }, dragging);
    };
    connect(control, &NumberControl::valueEdited, this, apply);
    // Typed outside the range: passed on, so the world refuses it with its message.
    connect(control, &NumberControl::outOfRange, this, [apply](double shown) { apply(shown, false); });
    connect(control, &NumberControl::dragStarted, this, [this] { ++m_dragSession; });
    m_refreshers.push_back([this, control, get, toShown] {
        control->setValue(get(m_controller->world().settings()) * toShown);
    });
    addRow(key, label, control,
           tr("%1 to %2%3").arg(QLocale().toString(spec.min, 'g', 4), QLocale().toString(spec.max, 'g', 4),
                                spec.suffix));
    return control;
}

QComboBox* ParameterPanel::addChoice(const QString& key, const QString& objectName, const QString& label,
                                     std::span<const std::string_view> names, std::function<int(const Settings&)> get,
                                     std::function<void(Settings&, int)> set)
{
    auto* combo = new QComboBox(m_sections.back().box);
    combo->setObjectName(objectName);
    for (std::string_view name : names)
        combo->addItem(qs(name));
    connect(combo, &QComboBox::currentIndexChanged, this, [this, key, set](int index) {
        if (index >= 0)
            edit(key, [&](Settings& s) { set(s, index); });
    });
    m_refreshers.push_back([this, combo, get] {
        const QSignalBlocker block(combo);
        combo->setCurrentIndex(get(m_controller->world().settings()));
    });
    addRow(key, label, combo);
    return combo;
}

QCheckBox* ParameterPanel::addSwitch(const QString& key, const QString& objectName, const QString& label,
                                     const QString& tip, std::function<bool(const Settings&)> get,
                                     std::function<void(Settings&, bool)> set)
{
    auto* box = new QCheckBox(m_sections.back().box);
    box->setObjectName(objectName);
    connect(box, &QCheckBox::toggled, this,
            [this, key, set](bool on) { edit(key, [&](Settings& s) { set(s, on); }); });
    m_refreshers.push_back([this, box, get] {
        const QSignalBlocker block(box);
        box->setChecked(get(m_controller->world().settings()));
    });
    addRow(key, label, box, tip);
    return box;
}

void ParameterPanel::addWallSides()
{
    auto* field = new QWidget(m_sections.back().box);
    field->setObjectName(QStringLiteral("wallSides"));
    auto* layout = new QHBoxLayout(field);
    layout->setContentsMargins(0, 0, 0, 0);
    struct Side {
        const char* name;
        QString text;
        bool sim::WallSettings::*member;
    };
    const Side sides[] = {{"Left", tr("left"), &sim::WallSettings::left},
                          {"Right", tr("right"), &sim::WallSettings::right},
                          {"Top", tr("top"), &sim::WallSettings::top},
                          {"Bottom", tr("bottom"), &sim::WallSettings::bottom}};
    for (const Side& side : sides) {
        auto* box = new QCheckBox(side.text, field);
        box->setObjectName(QStringLiteral("wall%1Check").arg(QLatin1String(side.name)));
        const auto member = side.member;
        connect(box, &QCheckBox::toggled, this, [this, member](bool on) {
            edit(QStringLiteral("wall_sides"), [&](Settings& s) { s.walls.*member = on; });
        });
        m_refreshers.push_back([this, box, member] {
            const QSignalBlocker block(box);
            box->setChecked(m_controller->world().settings().walls.*member);
        });
        layout->addWidget(box);
    }
    layout->addStretch(1);
    addRow(QStringLiteral("wall_sides"), tr("Walls"), field, tr("A wall that is not ticked is open"));
}

void ParameterPanel::addSeed()
{
    auto* edit = new QLineEdit(m_sections.back().box);
    edit->setObjectName(QStringLiteral("seedEdit"));
    edit->setValidator(new QRegularExpressionValidator(QRegularExpression(QStringLiteral("[0-9]{1,20}")), edit));
    connect(edit, &QLineEdit::editingFinished, this, [this, edit] {
        bool ok = false;
        const qulonglong seed = edit->text().toULongLong(&ok);
        if (!ok) {
            emit m_controller->errorOccurred(
                tr("time.seed: \"%1\" is not a whole number from 0 to 18446744073709551615").arg(edit->text()));
            refresh();
            return;
        }
        if (seed != m_controller->world().settings().time.seed)
            this->edit(QStringLiteral("seed"), [&](Settings& s) { s.time.seed = seed; });
    });
    m_refreshers.push_back([this, edit] {
        const QSignalBlocker block(edit);
        edit->setText(QString::number(static_cast<qulonglong>(m_controller->world().settings().time.seed)));
    });
    addRow(QStringLiteral("seed"), tr("Seed"), edit,
           tr("Random numbers (wind, random acceleration) start from this seed when the balls are placed again"));
}

void ParameterPanel::addBallCount()
{
    NumberControl::Spec s;
    s.min = 0.0;
    s.max = static_cast<double>(sim::kMaxBalls);
    s.sliderMin = 1.0;
    s.sliderMax = 50000.0;
    s.scale = NumberControl::Scale::Log;
    s.decimals = 0;
    auto* control = new NumberControl(QStringLiteral("ballCount"), s, m_sections.back().box);
    // Placing balls restarts the world: only when the value is final (not at
    // every pixel of a drag).
    auto apply = [this](double v) {
        sim::SpawnSettings spawn = m_controller->spawn();
        spawn.count = static_cast<int>(std::lround(v));
        if (spawn.count != m_controller->spawn().count)
            editSpawn(tr("Place %n random ball(s)", nullptr, spawn.count), spawn);
    };
    connect(control, &NumberControl::valueEdited, this, [apply](double v, bool dragging) {
        if (!dragging)
            apply(v);
    });
    connect(control->slider(), &QSlider::sliderReleased, this, [apply, control] { apply(control->value()); });
    connect(control, &NumberControl::outOfRange, this, [this](double v) {
        sim::SpawnSettings spawn = m_controller->spawn();
        spawn.count = v < 0 ? -1 : static_cast<int>(std::min(v, 1e9));
        editSpawn(tr("Place random balls"), spawn);
    });
    m_refreshers.push_back([this, control] { control->setValue(m_controller->spawn().count); });
    addRow(QStringLiteral("ball_count"), tr("Random balls"), control,
           tr("How many balls are placed at random (besides the lesson's own); changing it starts again"));
}

void ParameterPanel::addFullyInside()
{
    auto* box = new QCheckBox(m_sections.back().box);
    box->setObjectName(QStringLiteral("fullyInsideCheck"));
    connect(box, &QCheckBox::toggled, this, [this](bool on) {
        sim::SpawnSettings spawn = m_controller->spawn();
        spawn.fullyInside = on;
        editSpawn(on ? tr("Place balls fully inside") : tr("Let balls start partly outside"), spawn);
    });
    m_refreshers.push_back([this, box] {
        const QSignalBlocker block(box);
        box->setChecked(m_controller->spawn().fullyInside);
    });
    addRow(QStringLiteral("fully_inside"), tr("Start fully inside"), box,
           tr("Off: a ball's centre may be anywhere in the box, so it can start partly outside a wall "
              "(stage 4's bug). Changing it places the balls again"));
}

void ParameterPanel::addTimeScale()
{
    // Not a world setting: how fast real time drives simulated time.
    NumberControl::Spec s;
    s.min = SimulationController::kMinTimeScale;
    s.max = SimulationController::kMaxTimeScale;
    s.sliderMin = SimulationController::kMinTimeScale;
    s.sliderMax = SimulationController::kMaxTimeScale;
    s.scale = NumberControl::Scale::Log;
    s.decimals = 2;
    s.suffix = QStringLiteral(" ×");
    auto* control = new NumberControl(QStringLiteral("timeScale"), s, m_sections.back().box);
    auto apply = [this](double v, bool dragging) {
        if (m_refreshing)
            return;
        const double before = m_controller->timeScale();
        m_controller->setTimeScale(v);
        if (m_controller->timeScale() != before)
            m_undoStack->push(new TimeScaleCommand(m_controller, before, m_controller->timeScale(),
                                                   dragging ? m_dragSession : -1));
    };
    connect(control, &NumberControl::valueEdited, this, apply);
    connect(control, &NumberControl::outOfRange, this, [apply](double v) { apply(v, false); });
    connect(control, &NumberControl::dragStarted, this, [this] { ++m_dragSession; });
    m_refreshers.push_back([this, control] { control->setValue(m_controller->timeScale()); });
    addRow(QStringLiteral("time_scale"), tr("Speed"), control,
           tr("Simulated seconds per real second: below 1 is slow motion (%1× to %2×)")
               .arg(SimulationController::kMinTimeScale)
               .arg(SimulationController::kMaxTimeScale));
}

} // namespace forcelab
