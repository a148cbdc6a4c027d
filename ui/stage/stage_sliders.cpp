#include "ui/stage/stage_sliders.h"
#include "ui/i18n/parameter_words.h"

#include "ui/drawing/display_units.h"
#include "ui/controls/number_control.h"
#include "ui/controls/settings_editor.h"
#include "ui/canvas/simulation_controller.h"

#include "lessons/lesson_controls.h"
#include "sim/world/parameters.h"

#include <QComboBox>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>

#include <algorithm>
#include <cmath>

namespace forcelab {

namespace {

QString qs(std::string_view s)
{
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

// Undo ids of the stage's sliders: one per parameter row, apart from the panel's.
constexpr int kMergeIdBase = 2'000'000;

} // namespace

StageSliders::StageSliders(SimulationController* controller, SettingsEditor* editor, QWidget* parent)
    : QWidget(parent)
    , m_controller(controller)
    , m_editor(editor)
{
    setObjectName(QStringLiteral("stageSliders"));
    m_grid = new QGridLayout(this);
    m_grid->setContentsMargins(0, 4, 0, 0);
    m_grid->setHorizontalSpacing(12);
    m_grid->setVerticalSpacing(2);
    connect(m_controller, &SimulationController::settingsChanged, this, &StageSliders::refresh);
    connect(m_controller, &SimulationController::sceneChanged, this, &StageSliders::refresh);
}

void StageSliders::setLessonControls(const QStringList& controls)
{
    for (const Control& s : m_controls) {
        delete s.widget();
        delete s.label;
    }
    m_controls.clear();
    QFont big = font();
    big.setPointSizeF(big.pointSizeF() * 1.3);
    QStringList seen; // a row named by two controls gets one control
    for (const QString& control : controls) {
        for (const QString& row : lessons::controlRows().value(control)) {
            if (seen.contains(row))
                continue;
            seen << row;
            // Rows of the Parameters panel itself, not of the parameter table.
            if (row == QStringLiteral("wall_sides")) {
                m_controls.append(makeWallSides(big));
                continue;
            }
            if (row == QStringLiteral("fully_inside")) {
                m_controls.append(makeFullyInside(big));
                continue;
            }
            if (row == QStringLiteral("spawn_min_speed") || row == QStringLiteral("spawn_max_speed")) {
                m_controls.append(makeSpawnSpeed(big, row));
                continue;
            }
            // The others are left to the panel on purpose (the seed, the ball
            // count, the speed: see tests/test_gui_stage.cpp for why).
            const sim::Parameter* p = sim::findControl(row.toStdString());
            if (!p)
                continue;
            const int mergeId = kMergeIdBase + static_cast<int>(p - sim::parameters().data());
            Control s;
            s.parameter = p;
            s.row = row;
            switch (p->type) {
            case sim::ParameterType::Number:
            case sim::ParameterType::Integer:
                if (!(p->sliderHi > p->sliderLo))
                    continue; // no slider range: the Parameters panel's box only
                s.slider = makeSlider(p, row);
                connect(s.slider, &NumberControl::valueEdited, this,
                        [this, p, mergeId](double value, bool dragging) { apply(p, value, dragging ? mergeId : -1); });
                break;
            case sim::ParameterType::Boolean:
                // A button as tall as a slider's handle row, easier to hit
                // from the front of a room than a tick box.
                s.toggle = new QPushButton(this);
                s.toggle->setObjectName(QStringLiteral("stage_%1Toggle").arg(row));
                s.toggle->setCheckable(true);
                s.toggle->setFont(big);
                s.toggle->setMinimumHeight(36);
                connect(s.toggle, &QPushButton::clicked, this, [this, p](bool on) { apply(p, on ? 1.0 : 0.0, -1); });
                break;
            case sim::ParameterType::Choice:
                s.list = new QComboBox(this);
                s.list->setObjectName(QStringLiteral("stage_%1Choice").arg(row));
                s.list->setFont(big);
                s.list->setMinimumHeight(36);
                for (std::string_view name : p->choices())
                    s.list->addItem(qs(name));
                // As narrow as the column: a long name ("semi-implicit-euler")
                // is cut in the box, and shown whole in the label above it
                // and in the open list.
                s.list->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
                s.list->setMinimumContentsLength(6);
                connect(s.list, &QComboBox::activated, this, [this, p](int index) { apply(p, index, -1); });
                break;
            }
            // A button or a list is as wide as its column gives, whatever its
            // text asks: in a narrow column beside the box the controls never
            // push the column wider than the screen has room for.
            if (!s.slider)
                s.widget()->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
            s.widget()->setToolTip(qs(p->help));
            s.widget()->setAccessibleName(parameterLabel(*p));
            s.label = new QLabel(this);
            s.label->setObjectName(QStringLiteral("stage_%1Label").arg(row));
            s.label->setFont(big);
            s.label->setWordWrap(true);
            m_controls.append(s);
        }
    }
    arrange();
    refresh();
}

StageSliders::Control StageSliders::makeWallSides(const QFont& big)
{
    // Four buttons under one label, rather than four rows of
    // "Switch off": the class sees at a glance which walls are there. Each
    // button edits its own row of the parameter table (wall_left, …), so a
    // click is one undo step like the panel's tick boxes.
    Control s;
    s.row = QStringLiteral("wall_sides");
    s.sidesField = new QWidget(this);
    s.sidesField->setObjectName(QStringLiteral("stage_wall_sides"));
    // Two by two, so each word keeps its room in a narrow column beside the box.
    auto* layout = new QGridLayout(s.sidesField);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(6);
    int at = 0;
    const std::pair<const char*, QString> sides[] = {
        {"wall_left", tr("Left")}, {"wall_right", tr("Right")}, {"wall_top", tr("Top")}, {"wall_bottom", tr("Bottom")}};
    for (const auto& [row, text] : sides) {
        const sim::Parameter* p = sim::findControl(row);
        Q_ASSERT(p);
        auto* button = new QPushButton(text, s.sidesField);
        button->setObjectName(QStringLiteral("stage_%1Toggle").arg(QLatin1String(row)));
        button->setCheckable(true);
        button->setFont(big);
        button->setMinimumHeight(36);
        button->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
        button->setToolTip(qs(p->help));
        button->setAccessibleName(parameterLabel(*p));
        connect(button, &QPushButton::clicked, this, [this, p](bool on) { apply(p, on ? 1.0 : 0.0, -1); });
        layout->addWidget(button, at / 2, at % 2);
        ++at;
        s.sides.append({p, button});
    }
    s.sidesField->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    s.sidesField->setToolTip(tr("A wall whose button is not pressed is open: a ball leaves through it"));
    s.label = new QLabel(this);
    s.label->setObjectName(QStringLiteral("stage_wall_sidesLabel"));
    s.label->setFont(big);
    s.label->setWordWrap(true);
    return s;
}

StageSliders::Control StageSliders::makeFullyInside(const QFont& big)
{
    // A spawn setting, not a world setting: it places the balls again, as
    // the panel's tick box does (lesson 04's bug is seen at the start).
    Control s;
    s.row = QStringLiteral("fully_inside");
    s.spawnInside = true;
    s.toggle = new QPushButton(this);
    s.toggle->setObjectName(QStringLiteral("stage_fully_insideToggle"));
    s.toggle->setCheckable(true);
    s.toggle->setFont(big);
    s.toggle->setMinimumHeight(36);
    s.toggle->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    s.toggle->setToolTip(tr("Off: a ball's centre may be anywhere in the box, so it can start partly outside a wall. "
                            "Changing it places the balls again"));
    connect(s.toggle, &QPushButton::clicked, this, [this](bool on) {
        sim::SpawnSettings spawn = m_controller->spawn();
        spawn.fullyInside = on;
        if (!m_editor->editSpawn(on ? tr("Place balls fully inside") : tr("Let balls start partly outside"), spawn))
            refresh();
    });
    s.label = new QLabel(this);
    s.label->setObjectName(QStringLiteral("stage_fully_insideLabel"));
    s.label->setFont(big);
    s.label->setWordWrap(true);
    return s;
}

StageSliders::Control StageSliders::makeSpawnSpeed(const QFont& big, const QString& row)
{
    // Stage 2 asks the class to change the range random balls' speeds are
    // drawn from: a slider per end, which places the balls again when let
    // go (not at every pixel of the drag), as the panel's field does. A
    // slowest speed above the fastest is refused by the world, not clamped.
    Control s;
    s.row = row;
    s.spawnSpeed = row == QLatin1String("spawn_min_speed") ? 1 : 2;
    s.slider = new NumberControl(QStringLiteral("stage_%1").arg(row), NumberControl::spawnSpeedSpec(), this);
    s.slider->spinBox()->hide();
    s.slider->slider()->setMinimumHeight(36);
    s.slider->slider()->setAccessibleName(s.spawnSpeed == 1 ? tr("Slowest random ball") : tr("Fastest random ball"));
    const bool slowest = s.spawnSpeed == 1;
    auto apply = [this, slowest](double v) {
        if (!m_editor->editSpawnSpeed(slowest, v))
            refresh();
    };
    NumberControl* slider = s.slider;
    connect(slider, &NumberControl::valueEdited, this, [apply](double v, bool dragging) {
        if (!dragging)
            apply(v);
    });
    connect(slider->slider(), &QSlider::sliderReleased, this, [apply, slider] { apply(slider->value()); });
    s.label = new QLabel(this);
    s.label->setObjectName(QStringLiteral("stage_%1Label").arg(row));
    s.label->setFont(big);
    s.label->setWordWrap(true);
    return s;
}

QWidget* StageSliders::Control::widget() const
{
    if (sidesField)
        return sidesField;
    if (slider)
        return slider;
    if (toggle)
        return toggle;
    return list;
}

NumberControl* StageSliders::makeSlider(const sim::Parameter* p, const QString& row)
{
    NumberControl::Spec spec;
    spec.min = p->lo;
    spec.max = p->hi;
    spec.sliderMin = p->sliderLo;
    spec.sliderMax = p->sliderHi;
    spec.scale = p->scale == sim::SliderScale::Log ? NumberControl::Scale::Log : NumberControl::Scale::Linear;
    spec.decimals = p->type == sim::ParameterType::Integer ? 0 : 3;
    spec.significant = p->type == sim::ParameterType::Integer ? 0 : 3;
    auto* slider = new NumberControl(QStringLiteral("stage_%1").arg(row), spec, this);
    slider->spinBox()->hide(); // the label above shows the value, large
    slider->slider()->setMinimumHeight(36);
    slider->slider()->setAccessibleName(parameterLabel(*p));
    connect(slider, &NumberControl::dragStarted, this, [this] { ++m_dragSession; });
    return slider;
}

void StageSliders::setColumns(int columns)
{
    m_columns = std::max(1, columns);
    arrange();
}

void StageSliders::arrange()
{
    while (m_grid->count() > 0)
        delete m_grid->takeAt(0); // the layout item only; the widgets stay
    for (int k = 0; k < m_grid->rowCount(); ++k)
        m_grid->setRowStretch(k, 0);
    // Sliders go side by side; in a bar of one or two columns a button or a
    // list takes a row of its own, so its words are not squeezed into half
    // a narrow column.
    int row = 0, column = 0;
    for (const Control& s : m_controls) {
        const bool wide = !s.slider && m_columns <= 2;
        // Four wall buttons need two columns' width to keep their words.
        const int span = wide ? m_columns : s.sidesField ? std::min(2, m_columns) : 1;
        if (column > 0 && (wide || column + span > m_columns)) {
            row += 2;
            column = 0;
        }
        m_grid->addWidget(s.label, row, column, 1, span);
        m_grid->addWidget(s.widget(), row + 1, column, 1, span);
        column += span;
        if (column >= m_columns) {
            row += 2;
            column = 0;
        }
    }
    // Room to spare goes under the last control, so the controls stay
    // together at the top of a tall area.
    m_grid->setRowStretch(column > 0 ? row + 2 : row, 1);
}

void StageSliders::apply(const sim::Parameter* p, double value, int mergeId)
{
    const double v = p->type == sim::ParameterType::Integer ? std::round(value) : value;
    if (!m_editor->editSettings(parameterLabel(*p), [p, v](sim::WorldSettings& s) { p->set(s, v); }, {mergeId, m_dragSession}))
        refresh(); // refused: the controller said why; the slider goes back
}

void StageSliders::refresh()
{
    const sim::WorldSettings& settings = m_controller->world().settings();
    for (const Control& s : m_controls) {
        if (s.sidesField) {
            QStringList on;
            for (const auto& [p, button] : s.sides) {
                const bool there = p->get(settings) != 0.0;
                const QSignalBlocker block(button);
                button->setChecked(there);
                if (there)
                    on << button->text().toLower();
            }
            s.label->setText(tr("Walls: <b>%1</b>").arg(on.isEmpty() ? tr("none") : on.join(QStringLiteral(", "))));
            continue;
        }
        if (s.spawnSpeed != 0) {
            const double speed = s.spawnSpeed == 1 ? m_controller->spawn().minSpeed : m_controller->spawn().maxSpeed;
            if (!s.slider->isSliderDown())
                s.slider->setValue(speed);
            const ShownUnit u = shownUnit(QStringLiteral("px/s"), displayUnits());
            s.label->setText((s.spawnSpeed == 1 ? tr("Slowest random ball: <b>%1</b> %2")
                                                : tr("Fastest random ball: <b>%1</b> %2"))
                                 .arg(QString::number(u.toShown(speed), 'g', 4), u.text.toHtmlEscaped()));
            continue;
        }
        if (s.spawnInside) {
            const bool inside = m_controller->spawn().fullyInside;
            const QSignalBlocker block(s.toggle);
            s.toggle->setChecked(inside);
            s.toggle->setText(inside ? tr("Switch off") : tr("Switch on"));
            s.label->setText(tr("Start fully inside: <b>%1</b>").arg(inside ? tr("on") : tr("off")));
            continue;
        }
        const double value = s.parameter->get(settings);
        QString shown, unit;
        if (s.slider) {
            if (!s.slider->isSliderDown())
                s.slider->setValue(value);
            // The slider moves in px; its label speaks the view's units (SI or px).
            const ShownUnit u = shownUnit(qs(s.parameter->unit), displayUnits());
            unit = u.text.isEmpty() ? QString() : QStringLiteral(" ") + u.text;
            shown = QString::number(u.toShown(value), 'g', 4);
        } else if (s.toggle) {
            const QSignalBlocker block(s.toggle);
            s.toggle->setChecked(value != 0.0);
            shown = value != 0.0 ? tr("on") : tr("off");
            // The button says what a click does.
            s.toggle->setText(value != 0.0 ? tr("Switch off") : tr("Switch on"));
        } else if (s.list) {
            const QSignalBlocker block(s.list);
            s.list->setCurrentIndex(static_cast<int>(value));
            shown = s.list->currentText();
        }
        s.label->setText(QStringLiteral("%1: <b>%2</b>%3")
                             .arg(parameterLabel(*s.parameter).toHtmlEscaped(), shown.toHtmlEscaped(), unit.toHtmlEscaped()));
    }
}

const StageSliders::Control* StageSliders::find(const QString& row) const
{
    for (const Control& s : m_controls)
        if (s.row == row)
            return &s;
    return nullptr;
}

NumberControl* StageSliders::slider(const QString& row) const
{
    const Control* s = find(row);
    return s ? s->slider : nullptr;
}

QPushButton* StageSliders::toggle(const QString& row) const
{
    for (const Control& c : m_controls)
        for (const auto& side : c.sides)
            if (qs(side.first->control) == row)
                return side.second;
    const Control* s = find(row);
    return s ? s->toggle : nullptr;
}

QComboBox* StageSliders::choice(const QString& row) const
{
    const Control* s = find(row);
    return s ? s->list : nullptr;
}

} // namespace forcelab
