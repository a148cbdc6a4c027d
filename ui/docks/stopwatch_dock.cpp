#include "ui/docks/stopwatch_dock.h"

#include "ui/canvas/simulation_controller.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFontDatabase>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace forcelab {

StopwatchDock::StopwatchDock(SimulationController* controller, QWidget* parent)
    : QDockWidget(tr("Stopwatch"), parent)
    , m_controller(controller)
{
    setObjectName(QStringLiteral("stopwatchDock"));
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    m_time = new QLabel(body);
    m_time->setObjectName(QStringLiteral("stopwatchTime"));
    QFont big = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    big.setPointSizeF(big.pointSizeF() * 2.2);
    big.setBold(true);
    m_time->setFont(big);
    m_time->setAlignment(Qt::AlignCenter);
    layout->addWidget(m_time);

    auto* form = new QFormLayout;
    form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    m_startOn = new QComboBox(body);
    m_startOn->setObjectName(QStringLiteral("stopwatchStartOn"));
    m_startOn->addItems({tr("by hand"), tr("on the event")});
    m_startOn->setAccessibleName(tr("Start the stopwatch"));
    form->addRow(tr("Start"), m_startOn);
    auto* stopRow = new QHBoxLayout;
    m_stopOn = new QComboBox(body);
    m_stopOn->setObjectName(QStringLiteral("stopwatchStopOn"));
    m_stopOn->addItems({tr("by hand"), tr("after events:")});
    m_stopOn->setAccessibleName(tr("Stop the stopwatch"));
    m_count = new QSpinBox(body);
    m_count->setObjectName(QStringLiteral("stopwatchCount"));
    m_count->setRange(1, 1000);
    m_count->setAccessibleName(tr("Events before the stopwatch stops"));
    stopRow->addWidget(m_stopOn, 1);
    stopRow->addWidget(m_count);
    form->addRow(tr("Stop"), stopRow);
    m_event = new QComboBox(body);
    m_event->setObjectName(QStringLiteral("stopwatchEvent"));
    m_event->addItems({tr("a bounce (moving down, then up)"), tr("the top of a flight"), tr("crossing the line x ="),
                       tr("crossing the line y ="), tr("a full turn round the centre")});
    m_event->setAccessibleName(tr("Event"));
    form->addRow(tr("Event"), m_event);
    m_line = new QDoubleSpinBox(body);
    m_line->setObjectName(QStringLiteral("stopwatchLine"));
    m_line->setRange(-1e6, 1e6);
    m_line->setDecimals(1);
    m_line->setSuffix(QStringLiteral(" px"));
    m_line->setValue(300.0);
    m_line->setAccessibleName(tr("Line position"));
    form->addRow(tr("Line at"), m_line);
    m_ball = new QSpinBox(body);
    m_ball->setObjectName(QStringLiteral("stopwatchBall"));
    m_ball->setRange(0, 0);
    m_ball->setAccessibleName(tr("Ball watched"));
    form->addRow(tr("Ball"), m_ball);
    layout->addLayout(form);

    auto* buttons = new QHBoxLayout;
    m_startStop = new QPushButton(body);
    m_startStop->setObjectName(QStringLiteral("stopwatchStartStop"));
    m_reset = new QPushButton(tr("Reset"), body);
    m_reset->setObjectName(QStringLiteral("stopwatchReset"));
    buttons->addWidget(m_startStop);
    buttons->addWidget(m_reset);
    layout->addLayout(buttons);
    m_laps = new QLabel(body);
    m_laps->setObjectName(QStringLiteral("stopwatchLaps"));
    m_laps->setWordWrap(true);
    layout->addWidget(m_laps);
    layout->addStretch(1);
    setWidget(body);

    connect(m_startStop, &QPushButton::clicked, this, &StopwatchDock::startOrStop);
    connect(m_reset, &QPushButton::clicked, this, &StopwatchDock::reset);
    connect(m_startOn, &QComboBox::currentIndexChanged, this, &StopwatchDock::updateControls);
    connect(m_stopOn, &QComboBox::currentIndexChanged, this, &StopwatchDock::updateControls);
    connect(m_event, &QComboBox::currentIndexChanged, this, &StopwatchDock::updateControls);
    connect(m_controller, &SimulationController::stepped, this, &StopwatchDock::onStepped);
    connect(m_controller, &SimulationController::sceneChanged, this, [this] {
        m_ball->setRange(0, std::max(0, m_controller->world().balls().size() - 1));
        m_lapTexts.clear();
        m_laps->clear();
        reset();
    });
    m_ball->setRange(0, std::max(0, m_controller->world().balls().size() - 1));
    updateControls();
    reset();
}

void StopwatchDock::setStartOn(StartOn on)
{
    m_startOn->setCurrentIndex(on == StartOn::Hand ? 0 : 1);
}

void StopwatchDock::setStopOn(StopOn on, int events)
{
    m_stopOn->setCurrentIndex(on == StopOn::Hand ? 0 : 1);
    m_count->setValue(events);
}

void StopwatchDock::setEvent(sim::EventKind kind, int ball, double line)
{
    m_event->setCurrentIndex(static_cast<int>(kind));
    m_ball->setValue(ball);
    m_line->setValue(m_lineUnit.toShown(line));
}

void StopwatchDock::unitsChanged()
{
    const double px = m_lineUnit.fromShown(m_line->value());
    m_lineUnit = shownUnit(QStringLiteral("px"), displayUnits());
    // A tenth of a px either way: 0.001 m at 100 px = 1 m.
    const int decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(0.1 * m_lineUnit.factor()) - 1e-9)), 1, 6);
    const QSignalBlocker block(m_line);
    m_line->setDecimals(decimals);
    m_line->setRange(m_lineUnit.toShown(-1e6), m_lineUnit.toShown(1e6));
    m_line->setSuffix(QLatin1Char(' ') + m_lineUnit.text);
    m_line->setValue(m_lineUnit.toShown(px));
}

void StopwatchDock::setBall(int ball)
{
    if (ball >= 0 && m_state == State::Idle)
        m_ball->setValue(ball);
}

void StopwatchDock::updateControls()
{
    const bool events = m_startOn->currentIndex() == 1 || m_stopOn->currentIndex() == 1;
    const auto kind = static_cast<sim::EventKind>(m_event->currentIndex());
    m_count->setEnabled(m_stopOn->currentIndex() == 1);
    m_event->setEnabled(events);
    m_ball->setEnabled(events);
    m_line->setEnabled(events && (kind == sim::EventKind::CrossX || kind == sim::EventKind::CrossY));
    switch (m_state) {
    case State::Idle:
        m_startStop->setText(m_startOn->currentIndex() == 0 ? tr("Start") : tr("Arm"));
        break;
    case State::Armed:
        m_startStop->setText(tr("Waiting…"));
        break;
    case State::Running:
        m_startStop->setText(tr("Stop"));
        break;
    case State::Stopped:
        m_startStop->setText(tr("Start again"));
        break;
    }
    m_startStop->setEnabled(m_state != State::Armed && !(m_state == State::Running && m_stopOn->currentIndex() == 1));
}

sim::EventSpec StopwatchDock::spec() const
{
    sim::EventSpec s;
    s.kind = static_cast<sim::EventKind>(m_event->currentIndex());
    s.ball = m_ball->value();
    s.value = m_lineUnit.fromShown(m_line->value()); // the world's px
    // A full turn round what the ball circles: the spring's anchor or the
    // attracting point, or else the middle of the box.
    const sim::WorldSettings& w = m_controller->world().settings();
    s.centre = w.spring.enabled ? w.spring.anchor
             : w.point.enabled  ? w.point.position
                                : sim::Vec2(0.5 * w.box.width, 0.5 * w.box.height);
    return s;
}

void StopwatchDock::startOrStop()
{
    const sim::World& world = m_controller->world();
    if (m_state == State::Running) { // by hand
        m_stop = world.time();
        m_state = State::Stopped;
    } else {
        m_watch.start(spec(), world.balls(), world.time());
        m_eventsLeft = m_count->value();
        if (m_startOn->currentIndex() == 0) {
            m_start = world.time();
            m_state = State::Running;
        } else {
            m_state = State::Armed;
        }
    }
    if (m_state == State::Stopped)
        m_lapTexts.prepend(tr("%1 s").arg(elapsed(), 0, 'f', 3));
    updateControls();
    showTime();
}

void StopwatchDock::reset()
{
    m_state = State::Idle;
    m_start = m_stop = 0.0;
    updateControls();
    showTime();
}

void StopwatchDock::onStepped()
{
    const sim::World& world = m_controller->world();
    if (m_state == State::Armed || (m_state == State::Running && m_stopOn->currentIndex() == 1)) {
        if (const auto t = m_watch.update(world.balls(), world.time())) {
            if (m_state == State::Armed) {
                m_start = *t;
                m_state = State::Running;
            } else if (--m_eventsLeft == 0) {
                m_stop = *t;
                m_state = State::Stopped;
                m_lapTexts.prepend(tr("%1 s").arg(elapsed(), 0, 'f', 3));
            }
            updateControls();
        }
    }
    showTime();
}

double StopwatchDock::elapsed() const
{
    switch (m_state) {
    case State::Running:
        return m_controller->world().time() - m_start;
    case State::Stopped:
        return m_stop - m_start;
    default:
        return 0.0;
    }
}

void StopwatchDock::showTime()
{
    m_time->setText(tr("%1 s").arg(std::max(0.0, elapsed()), 0, 'f', 3));
    while (m_lapTexts.size() > 5)
        m_lapTexts.removeLast();
    m_laps->setText(m_lapTexts.isEmpty() ? QString() : tr("Last times: %1").arg(m_lapTexts.join(QStringLiteral(", "))));
}

} // namespace forcelab
