#include "stage_sliders.h"

#include "number_control.h"
#include "parameter_commands.h"
#include "simulation_controller.h"

#include "lessons/lesson_controls.h"
#include "sim/parameters.h"

#include <QGridLayout>
#include <QLabel>
#include <QUndoStack>

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

StageSliders::StageSliders(SimulationController* controller, QUndoStack* undoStack, QWidget* parent)
    : QWidget(parent)
    , m_controller(controller)
    , m_undoStack(undoStack)
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
    for (const Slider& s : m_sliders) {
        delete s.control;
        delete s.label;
    }
    m_sliders.clear();
    QFont big = font();
    big.setPointSizeF(big.pointSizeF() * 1.3);
    QStringList seen; // a row named by two controls gets one slider
    for (const QString& control : controls) {
        for (const QString& row : lessons::controlRows().value(control)) {
            if (seen.contains(row))
                continue;
            seen << row;
            const sim::Parameter* p = sim::findControl(row.toStdString());
            if (!p || (p->type != sim::ParameterType::Number && p->type != sim::ParameterType::Integer) ||
                !(p->sliderHi > p->sliderLo))
                continue;
            NumberControl::Spec spec;
            spec.min = p->lo;
            spec.max = p->hi;
            spec.sliderMin = p->sliderLo;
            spec.sliderMax = p->sliderHi;
            spec.scale = p->scale == sim::SliderScale::Log ? NumberControl::Scale::Log : NumberControl::Scale::Linear;
            spec.decimals = p->type == sim::ParameterType::Integer ? 0 : 3;
            spec.significant = p->type == sim::ParameterType::Integer ? 0 : 3;
            Slider s{p, row, new NumberControl(QStringLiteral("stage_%1").arg(row), spec, this), new QLabel(this)};
            s.control->spinBox()->hide(); // the label above shows the value, large
            s.control->slider()->setMinimumHeight(36);
            s.control->setToolTip(qs(p->help));
            s.control->slider()->setAccessibleName(qs(p->label));
            s.label->setObjectName(QStringLiteral("stage_%1Label").arg(row));
            s.label->setFont(big);
            s.label->setWordWrap(true);
            const int mergeId = kMergeIdBase + static_cast<int>(p - sim::parameters().data());
            connect(s.control, &NumberControl::dragStarted, this, [this] { ++m_dragSession; });
            connect(s.control, &NumberControl::valueEdited, this,
                    [this, p, mergeId](double value, bool dragging) { apply(p, value, dragging ? mergeId : -1); });
            m_sliders.append(s);
        }
    }
    arrange();
    refresh();
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
    for (qsizetype i = 0; i < m_sliders.size(); ++i) {
        const int row = static_cast<int>(i / m_columns) * 2, column = static_cast<int>(i % m_columns);
        m_grid->addWidget(m_sliders[i].label, row, column);
        m_grid->addWidget(m_sliders[i].control, row + 1, column);
    }
    // Room to spare goes under the last slider, so the sliders stay together
    // at the top of a tall area.
    const int rows = static_cast<int>((m_sliders.size() + m_columns - 1) / m_columns) * 2;
    m_grid->setRowStretch(rows, 1);
}

void StageSliders::apply(const sim::Parameter* p, double value, int mergeId)
{
    const sim::WorldSettings before = m_controller->world().settings();
    sim::WorldSettings after = before;
    p->set(after, p->type == sim::ParameterType::Integer ? std::round(value) : value);
    if (!m_controller->setSettings(after)) {
        refresh(); // refused: the controller said why; the slider goes back
        return;
    }
    m_undoStack->push(new SettingsCommand(m_controller, qs(p->label), before, after, mergeId, m_dragSession));
}

void StageSliders::refresh()
{
    const sim::WorldSettings& settings = m_controller->world().settings();
    for (const Slider& s : m_sliders) {
        const double value = s.parameter->get(settings);
        if (!s.control->isSliderDown())
            s.control->setValue(value);
        const QString unit = s.parameter->unit.empty() ? QString() : QStringLiteral(" ") + qs(s.parameter->unit);
        s.label->setText(QStringLiteral("%1: <b>%2</b>%3")
                             .arg(qs(s.parameter->label).toHtmlEscaped())
                             .arg(QString::number(value, 'g', 4))
                             .arg(unit.toHtmlEscaped()));
    }
}

NumberControl* StageSliders::slider(const QString& row) const
{
    for (const Slider& s : m_sliders)
        if (s.row == row)
            return s.control;
    return nullptr;
}

} // namespace forcelab
