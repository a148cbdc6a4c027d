#include "ui/controls/timeline_bar.h"

#include "ui/canvas/simulation_controller.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QStyle>
#include <QToolButton>

#include <algorithm>
#include <limits>

namespace forcelab {

TimelineBar::TimelineBar(SimulationController* controller, QWidget* parent)
    : QWidget(parent)
    , m_controller(controller)
    , m_back(new QToolButton(this))
    , m_slider(new QSlider(Qt::Horizontal, this))
    , m_forward(new QToolButton(this))
    , m_label(new QLabel(this))
{
    m_back->setObjectName(QStringLiteral("stepBackButton"));
    m_back->setIcon(style()->standardIcon(QStyle::SP_MediaSkipBackward));
    m_back->setToolTip(tr("Step back: pause and show the world one step dt earlier"));
    m_forward->setObjectName(QStringLiteral("stepForwardButton"));
    m_forward->setIcon(style()->standardIcon(QStyle::SP_MediaSkipForward));
    m_forward->setToolTip(tr("Step: re-run the next recorded step, or take a new one at the latest"));
    m_slider->setObjectName(QStringLiteral("timelineSlider"));
    m_slider->setToolTip(tr("The recorded past: drag to see the world at any step of it"));
    m_label->setObjectName(QStringLiteral("timelineLabel"));
    m_back->setAccessibleName(tr("Step back"));
    m_forward->setAccessibleName(tr("Step forward"));
    m_slider->setAccessibleName(tr("Timeline: the recorded steps"));
    m_label->setAccessibleName(tr("Time shown, of the time recorded"));
    m_back->setAutoRaise(true);
    m_forward->setAutoRaise(true);
    m_slider->setMinimumWidth(120);
    m_label->setMinimumWidth(m_label->fontMetrics().horizontalAdvance(timeText(9999.99, 9999.99)));

    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(4, 0, 4, 0);
    layout->addWidget(m_back);
    layout->addWidget(m_slider, 1);
    layout->addWidget(m_forward);
    layout->addWidget(m_label);

    connect(m_back, &QToolButton::clicked, m_controller, &SimulationController::stepBack);
    connect(m_forward, &QToolButton::clicked, m_controller, &SimulationController::stepOnce);
    connect(m_slider, &QSlider::valueChanged, this, &TimelineBar::seekTo);
    connect(m_controller, &SimulationController::timelineChanged, this, &TimelineBar::refresh);
    refresh();
}

QString TimelineBar::timeText(double now, double latest)
{
    return tr("t = %1 s of %2 s").arg(now, 0, 'f', 2).arg(latest, 0, 'f', 2);
}

void TimelineBar::refresh()
{
    const qint64 earliest = m_controller->earliestStep();
    const qint64 latest = m_controller->latestStep();
    const qint64 now = m_controller->world().stepCount();
    m_base = std::max<qint64>(earliest, latest - std::numeric_limits<int>::max());
    const QSignalBlocker block(m_slider);
    m_slider->setRange(0, static_cast<int>(latest - m_base));
    m_slider->setValue(static_cast<int>(std::clamp(now, m_base, latest) - m_base));
    m_back->setEnabled(now > earliest);
    m_label->setText(timeText(m_controller->world().time(), m_controller->timeline().latestTime()));
}

void TimelineBar::seekTo(int value)
{
    m_controller->seekStep(m_base + value);
}

} // namespace forcelab
