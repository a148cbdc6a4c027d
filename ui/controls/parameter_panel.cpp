#include "ui/controls/parameter_panel.h"
#include "ui/i18n/parameter_words.h"

#include "ui/controls/number_control.h"
#include "ui/controls/settings_editor.h"
#include "ui/canvas/simulation_controller.h"
#include "ui/drawing/display_units.h"

#include "lessons/lesson_controls.h"
#include "sim/world/names.h"
#include "sim/world/parameters.h"

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
#include <QVBoxLayout>
#include <QtDebug>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace forcelab {

namespace {

// Shown whatever the lesson lists: how fast the film runs.
const QStringList kAlwaysShown{QStringLiteral("time_scale")};

QString qs(std::string_view s)
{
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

} // namespace

ParameterPanel::ParameterPanel(SimulationController* controller, SettingsEditor* editor, QWidget* parent)
    : QWidget(parent)
    , m_controller(controller)
    , m_editor(editor)
{
    setObjectName(QStringLiteral("parameterPanel"));

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

    // Every setting is a row of sim/world/parameters.h: its label, unit, range,
    // slider, help and accessors come from there. A section's tick box is its
    // model's "enabled" row.
    addModelSection(QStringLiteral("gravity"), tr("Gravity"));
    addParameter("models.gravity.x");
    addParameter("models.gravity.y");

    addSection(QStringLiteral("walls"), tr("Box and walls"));
    addParameter("world.width");
    addParameter("world.height");
    addWallSides();
    addParameter("world.wall_model");
    addParameter("world.restitution");
    addParameter("world.middle_wall");
    addParameter("world.centre_only");

    addModelSection(QStringLiteral("drag"), tr("Drag"));
    addParameter("models.drag.law");
    addParameter("models.drag.k"); // its unit follows the law (addParameterWidget)
    addParameter("models.drag.scale");

    addSection(QStringLiteral("wind"), tr("Wind"));
    for (const char* key : {"models.wind.mode", "models.wind.strength", "models.wind.scale", "models.wind.smoothed_step",
                            "models.wind.frequency", "models.wind.compare"})
        addParameter(key);

    addModelSection(QStringLiteral("random_accel"), tr("Random acceleration"));
    addParameter("models.random_accel.fixed");
    addParameter("models.random_accel.strength");

    addModelSection(QStringLiteral("point"), tr("Point force"));
    for (const char* key : {"models.point.kind", "models.point.x", "models.point.y", "models.point.strength",
                            "models.point.max_accel", "models.point.scale"})
        addParameter(key);

    addModelSection(QStringLiteral("spring"), tr("Spring"));
    addParameter("models.spring.k");
    addParameter("models.spring.x");
    addParameter("models.spring.y");

    addModelSection(QStringLiteral("mutual_gravity"), tr("Gravity between balls"));
    addParameter("models.mutual_gravity.G");
    addParameter("models.mutual_gravity.softening");

    addModelSection(QStringLiteral("homing"), tr("Homing"));
    addParameter("models.homing.strength");

    addModelSection(QStringLiteral("pointer"), tr("Pointer force"));
    addParameter("models.pointer.strength");
    addParameter("models.pointer.max_accel");

    addModelSection(QStringLiteral("speed_limit"), tr("Speed limit"));
    addParameter("models.speed_limit.max");

    addSection(QStringLiteral("collisions"), tr("Collisions"));
    for (const char* key : {"models.collisions.detection", "models.collisions.response",
                            "models.collisions.restitution", "models.collisions.continuous",
                            "models.collisions.resting"})
        addParameter(key);

    addSection(QStringLiteral("time"), tr("Time"));
    addTimeScale();
    for (const char* key : {"time.integrator", "time.dt", "time.substeps", "time.tolerance", "time.per_frame",
                            "time.step_past_close_passes"})
        addParameter(key);
    addSeed();

    // Every row of the table gets its control with nothing written here: a
    // model the panel does not place above gets a section of its own, and a
    // row the sections above do not place goes at the end of its own
    // section, in table order.
    addUnplacedRows();

    addSection(QStringLiteral("balls"), tr("Balls"));
    addBallCount();
    addSpawnSpeed(QStringLiteral("spawn_min_speed"));
    addSpawnSpeed(QStringLiteral("spawn_max_speed"));
    addFullyInside();

    connect(m_controller, &SimulationController::settingsChanged, this, &ParameterPanel::refresh);
    connect(m_controller, &SimulationController::sceneChanged, this, &ParameterPanel::refresh);
    connect(m_controller, &SimulationController::timeScaleChanged, this, &ParameterPanel::refresh);
    updateVisibility();
    refresh();
}

void ParameterPanel::addUnplacedRows()
{
    for (const sim::Parameter& p : sim::parameters()) {
        const QString key = qs(p.key);
        const QString section = key.startsWith(QStringLiteral("models.")) ? key.section(QLatin1Char('.'), 1, 1)
                                : key.startsWith(QStringLiteral("world.")) ? QStringLiteral("walls")
                                : key.startsWith(QStringLiteral("time."))  ? QStringLiteral("time")
                                                                           : QString();
        if (section.isEmpty())
            continue;
        const bool placed = std::any_of(m_sections.begin(), m_sections.end(),
                                        [&](const Section& s) { return s.key == section; });
        if (key.endsWith(QStringLiteral(".enabled"))) {
            if (!placed)
                addModelSection(section, parameterLabel(p)); // its tick box is this row's control
        } else if (placed && !controlWidget(qs(p.control))) {
            m_currentSection = section;
            addParameter(p.key);
        }
    }
}

QWidget* ParameterPanel::controlWidget(const QString& control) const
{
    if (const int i = rowIndex(control); i >= 0)
        return m_rows[std::size_t(i)].field;
    if (const sim::Parameter* p = sim::findControl(control.toStdString())) {
        const QString key = qs(p->key);
        if (key.startsWith(QStringLiteral("models.")) && key.endsWith(QStringLiteral(".enabled")))
            for (const Section& s : m_sections)
                if (s.key == key.section(QLatin1Char('.'), 1, 1))
                    return s.box;
    }
    return m_otherControls.value(control);
}

ParameterPanel::Section& ParameterPanel::currentSection()
{
    for (Section& s : m_sections)
        if (s.key == m_currentSection)
            return s;
    return m_sections.back();
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
    return lessons::controlRows().value(control);
}

void ParameterPanel::setLessonControls(const QStringList& controls)
{
    m_controls.clear();
    for (const QString& name : controls) {
        if (!lessons::controlRows().contains(name)) {
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
        for (const QString& row : lessons::controlRows().value(control))
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
    const int index = rowIndex(key);
    const QString label = index >= 0 ? m_rows[std::size_t(index)].label : key;
    // On success the controller's settingsChanged refreshes every control;
    // on failure the error is signalled and the control goes back.
    if (!m_editor->editSettings(tr("Change %1").arg(label), change, {dragging ? index : -1, m_dragSession}))
        refresh();
}

void ParameterPanel::editSpawn(const QString& text, const sim::SpawnSettings& spawn)
{
    if (m_refreshing)
        return;
    if (!m_editor->editSpawn(text, spawn))
        refresh();
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
    // In a narrow dock a label goes above its field rather than cutting it.
    form->setRowWrapPolicy(QFormLayout::WrapLongRows);
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
    Section& section = currentSection();
    auto* text = new QLabel(label, section.box);
    text->setBuddy(field);
    if (!tip.isEmpty()) {
        text->setToolTip(tip);
        field->setToolTip(tip);
    }
    section.form->addRow(text, field);
    QString plain = label;
    plain.remove(QStringLiteral("<sub>")).remove(QStringLiteral("</sub>"));
    // A screen reader names each part of the row after its label.
    field->setAccessibleName(plain);
    if (auto* number = qobject_cast<NumberControl*>(field))
        number->setSpokenName(plain);
    m_rows.push_back(Row{key, section.key, section.box->title() + QLatin1Char(' ') + plain.toLower(), field});
}

QGroupBox* ParameterPanel::addModelSection(const QString& model, const QString& title)
{
    const sim::Parameter* on = sim::findParameter("models." + model.toStdString() + ".enabled");
    Q_ASSERT(on);
    return addSection(model, title, [on](const Settings& s) { return on->get(s) != 0.0; },
                      [on](Settings& s, bool enabled) { on->set(s, enabled ? 1.0 : 0.0); });
}

QString ParameterPanel::objectStem(std::string_view control)
{
    QString out;
    bool upper = false;
    for (const char c : control) {
        if (c == '_') {
            upper = true;
            continue;
        }
        out += upper ? QChar(c).toUpper() : QChar(c);
        upper = false;
    }
    return out;
}

QWidget* ParameterPanel::addParameterWidget(std::string_view key)
{
    const sim::Parameter* row = sim::findParameter(key);
    Q_ASSERT_X(row, "ParameterPanel", "a key that is not in sim/world/parameters.cpp");
    const sim::Parameter& p = *row;
    const QString control = qs(p.control);
    const QString stem = objectStem(p.control);
    const QString label = parameterLabel(p);
    auto get = [&p](const Settings& s) { return p.get(s); };
    switch (p.type) {
    case sim::ParameterType::Boolean:
        return addSwitch(control, stem + QStringLiteral("Check"), label, parameterHelp(p),
                         [get](const Settings& s) { return get(s) != 0.0; },
                         [&p](Settings& s, bool on) { p.set(s, on ? 1.0 : 0.0); });
    case sim::ParameterType::Choice: {
        QComboBox* combo = addChoice(control, stem + QStringLiteral("Combo"), label, p.choices(),
                                     [get](const Settings& s) { return static_cast<int>(get(s)); },
                                     [&p](Settings& s, int i) { p.set(s, i); });
        combo->setToolTip(parameterHelp(p));
        return combo;
    }
    case sim::ParameterType::Number:
    case sim::ParameterType::Integer:
        break;
    }
    // dt reads better in ms; everything else in the row's own unit, or in
    // SI (ui/drawing/display_units.h) when the view shows SI.
    const bool ms = key == "time.dt";
    Number spec;
    spec.lo = p.lo;
    spec.hi = p.hi;
    spec.sliderLo = p.sliderLo;
    spec.sliderHi = p.sliderHi;
    spec.log = p.scale == sim::SliderScale::Log;
    spec.whole = p.type == sim::ParameterType::Integer;
    spec.extraFactor = ms ? 1e3 : 1.0;
    spec.fixedSuffix = ms ? QStringLiteral(" ms") : QString();
    if (key == "models.drag.k") {
        // The unit of k follows the law: a = −k v (1/s) or a = −k |v| v (1/px).
        spec.pixelUnit = [this] {
            return m_controller->world().settings().drag.law == sim::DragLaw::Linear ? QStringLiteral("1/s")
                                                                                      : QStringLiteral("1/px");
        };
    } else {
        const QString unit = qs(p.unit);
        spec.pixelUnit = [unit] { return unit; };
    }
    const bool whole = spec.whole;
    NumberControl* number = addNumber(control, stem, label, spec, get, [&p, whole](Settings& s, double v) {
        p.set(s, whole ? static_cast<double>(std::lround(v)) : v);
    });
    number->setToolTip(parameterHelp(p));
    return number;
}

NumberControl::Spec ParameterPanel::controlSpec(const Number& spec, const ShownUnit& unit)
{
    const double k = spec.extraFactor;
    const bool converted = unit.px != 0 || unit.mass != 0;
    NumberControl::Spec s;
    s.min = unit.toShown(spec.lo) * k;
    s.max = unit.toShown(spec.hi) * k;
    s.sliderMin = unit.toShown(spec.sliderLo) * k;
    s.sliderMax = unit.toShown(spec.sliderHi) * k;
    s.scale = spec.log ? NumberControl::Scale::Log : NumberControl::Scale::Linear;
    // Whole numbers; four significant figures across decades or in SI (the
    // scale makes any number of decimals wrong for some lesson); otherwise
    // decimals that suit the slider's span.
    s.decimals = spec.whole ? 0 : spec.log ? 4 : spec.sliderHi - spec.sliderLo <= 1.0 ? 3 : 1;
    s.significant = !spec.whole && (spec.log || converted) ? 4 : 0;
    s.suffix = !spec.fixedSuffix.isEmpty() ? spec.fixedSuffix
               : unit.text.isEmpty()       ? QString()
                                           : QLatin1Char(' ') + unit.text;
    return s;
}

NumberControl* ParameterPanel::addNumber(const QString& key, const QString& objectName, const QString& label,
                                         const Number& spec, std::function<double(const Settings&)> get,
                                         std::function<void(Settings&, double)> set)
{
    // The unit the control shows now; the refresher changes it (and the
    // control's range and suffix) when the view's units or drag's law change.
    auto unit = std::make_shared<ShownUnit>(shownUnit(spec.pixelUnit(), displayUnits()));
    const NumberControl::Spec s = controlSpec(spec, *unit);
    auto* control = new NumberControl(objectName, s, currentSection().box);
    const double k = spec.extraFactor;
    // A shown value goes back to px (and mass units) before it reaches the world.
    auto apply = [this, key, set, unit, k](double shown, bool dragging) {
        edit(key, [&](Settings& st) { set(st, unit->fromShown(shown / k)); }, dragging);
    };
    connect(control, &NumberControl::valueEdited, this, apply);
    // Typed outside the range: passed on, so the world refuses it with its message.
    connect(control, &NumberControl::outOfRange, this, [apply](double shown) { apply(shown, false); });
    connect(control, &NumberControl::dragStarted, this, [this] { ++m_dragSession; });
    auto rangeTip = [](const NumberControl::Spec& shown) {
        return tr("%1 to %2%3").arg(QLocale().toString(shown.min, 'g', 4), QLocale().toString(shown.max, 'g', 4),
                                    shown.suffix);
    };
    QFormLayout* form = currentSection().form;
    m_refreshers.push_back([this, control, get, unit, spec, k, form, rangeTip] {
        const double value = get(m_controller->world().settings());
        const ShownUnit now = shownUnit(spec.pixelUnit(), displayUnits());
        if (now.text != unit->text || now.factor() != unit->factor()) {
            *unit = now;
            const NumberControl::Spec shown = controlSpec(spec, now);
            control->setSpec(shown, now.toShown(value) * k);
            if (auto* text = qobject_cast<QLabel*>(form->labelForField(control)))
                text->setToolTip(rangeTip(shown));
            return;
        }
        control->setValue(unit->toShown(value) * k);
    });
    addRow(key, label, control, rangeTip(s));
    return control;
}

QComboBox* ParameterPanel::addChoice(const QString& key, const QString& objectName, const QString& label,
                                     std::span<const std::string_view> names, std::function<int(const Settings&)> get,
                                     std::function<void(Settings&, int)> set)
{
    auto* combo = new QComboBox(currentSection().box);
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
    auto* box = new QCheckBox(currentSection().box);
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
    auto* field = new QWidget(currentSection().box);
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
        m_otherControls.insert(QStringLiteral("wall_%1").arg(QLatin1String(side.name).toString().toLower()), box);
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
    auto* edit = new QLineEdit(currentSection().box);
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
    auto* control = new NumberControl(QStringLiteral("ballCount"), s, currentSection().box);
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

void ParameterPanel::addSpawnSpeed(const QString& row)
{
    // The range random balls' speeds are drawn from (stage 2: "change the
    // spawn speed range"). Like the count, a final value places the balls
    // again; a slowest speed above the fastest is refused by the world with
    // its message, and the panel shows the range that stands.
    const bool slowest = row == QLatin1String("spawn_min_speed");
    // In the shown units (m/s in SI), converted back to px/s for the world,
    // as every row of the parameter table is.
    auto specIn = [](const ShownUnit& unit) {
        NumberControl::Spec s = NumberControl::spawnSpeedSpec();
        s.max = unit.toShown(s.max);
        s.sliderMax = unit.toShown(s.sliderMax);
        if (unit.px != 0 && unit.factor() != 1.0) {
            s.decimals = 3;
            s.significant = 4;
        }
        s.suffix = QLatin1Char(' ') + unit.text;
        return s;
    };
    auto unit = std::make_shared<ShownUnit>(shownUnit(QStringLiteral("px/s"), displayUnits()));
    auto* control = new NumberControl(slowest ? QStringLiteral("spawnMinSpeed") : QStringLiteral("spawnMaxSpeed"),
                                      specIn(*unit), currentSection().box);
    auto apply = [this, slowest, unit](double shown) {
        if (!m_refreshing && !m_editor->editSpawnSpeed(slowest, unit->fromShown(shown)))
            refresh();
    };
    connect(control, &NumberControl::valueEdited, this, [apply](double v, bool dragging) {
        if (!dragging)
            apply(v);
    });
    connect(control->slider(), &QSlider::sliderReleased, this, [apply, control] { apply(control->value()); });
    m_refreshers.push_back([this, control, slowest, unit, specIn] {
        const double speed = slowest ? m_controller->spawn().minSpeed : m_controller->spawn().maxSpeed;
        const ShownUnit now = shownUnit(QStringLiteral("px/s"), displayUnits());
        if (now.text != unit->text || now.factor() != unit->factor()) {
            *unit = now;
            control->setSpec(specIn(now), now.toShown(speed));
            return;
        }
        control->setValue(unit->toShown(speed));
    });
    addRow(row, slowest ? tr("Slowest random ball") : tr("Fastest random ball"), control,
           slowest ? tr("Random balls start with a speed of at least this; changing it starts again")
                   : tr("Random balls start with a speed of at most this; changing it starts again"));
}

void ParameterPanel::addFullyInside()
{
    auto* box = new QCheckBox(currentSection().box);
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
    auto* control = new NumberControl(QStringLiteral("timeScale"), s, currentSection().box);
    auto apply = [this](double v, bool dragging) {
        if (m_refreshing)
            return;
        m_editor->editTimeScale(v, dragging ? m_dragSession : -1);
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
