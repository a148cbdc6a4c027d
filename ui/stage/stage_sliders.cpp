#include "ui/stage/stage_sliders.h"

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
            const sim::Parameter* p = sim::findControl(row.toStdString());
            if (!p)
                continue;
            const int mergeId = kMergeIdBase + static_cast<int>(p - sim::parameters().data());
            Control s{p, row};
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
            s.widget()->setAccessibleName(qs(p->label));
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

QWidget* StageSliders::Control::widget() const
{
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
    slider->slider()->setAccessibleName(qs(p->label));
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
        if (wide && column > 0) {
            row += 2;
            column = 0;
        }
        const int span = wide ? m_columns : 1;
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
    if (!m_editor->editSettings(qs(p->label), [p, v](sim::WorldSettings& s) { p->set(s, v); }, {mergeId, m_dragSession}))
        refresh(); // refused: the controller said why; the slider goes back
}

void StageSliders::refresh()
{
    const sim::WorldSettings& settings = m_controller->world().settings();
    for (const Control& s : m_controls) {
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
                             .arg(qs(s.parameter->label).toHtmlEscaped(), shown.toHtmlEscaped(), unit.toHtmlEscaped()));
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
    const Control* s = find(row);
    return s ? s->toggle : nullptr;
}

QComboBox* StageSliders::choice(const QString& row) const
{
    const Control* s = find(row);
    return s ? s->list : nullptr;
}

} // namespace forcelab
