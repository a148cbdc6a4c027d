#include "ui/docks/accuracy_dock.h"

#include "ui/canvas/canvas.h"
#include "ui/controls/readable_numbers.h"
#include "ui/drawing/display_units.h"
#include "ui/drawing/human_number.h"
#include "ui/canvas/simulation_controller.h"

#include "sim/integrators/integrator_info.h"
#include "sim/world/names.h"
#include "sim/world/world.h"

#include <QAction>
#include <QChart>
#include <QChartView>
#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineSeries>
#include <QLogValueAxis>
#include <QProgressBar>
#include <QPushButton>
#include <QTabWidget>
#include <QThread>
#include <QToolButton>
#include <QValueAxis>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <cmath>

namespace forcelab {

namespace {

constexpr int kMaxSeparationPoints = 2000;
// The separation axis before the first point, px.
constexpr double kSeparationFloor = 1e-12;

// Three significant digits as a student writes them ("1.23 × 10⁻⁵"), and
// the unit in the current units when there is one.
QString sci(double v, const QString& pixelUnit = {})
{
    return pixelUnit.isEmpty() || !std::isfinite(v) ? humanNumber(v, 3) : quantityText(v, pixelUnit, 3);
}

QString nameOf(sim::IntegratorKind k)
{
    const std::string_view n = sim::toString(k);
    return QString::fromLatin1(n.data(), static_cast<qsizetype>(n.size()));
}

// A log axis over whole decades around [lo, hi], with at most about five
// labels (a tick every k decades), so they fit a dock's height.
void setDecades(QLogValueAxis* axis, double lo, double hi)
{
    int from = int(std::floor(std::log10(lo)));
    int to = std::max(int(std::ceil(std::log10(hi))), from + 1);
    const int k = std::max(1, (to - from + 4) / 5);
    from = int(std::floor(double(from) / k)) * k;
    to = int(std::ceil(double(to) / k)) * k;
    axis->setBase(std::pow(10.0, k));
    axis->setRange(std::pow(10.0, from), std::pow(10.0, to));
}

// Charts in a dock are small: thin margins, small labels, no minor ticks.
void compact(QChart* chart)
{
    chart->setMargins(QMargins(2, 2, 2, 2));
    chart->setBackgroundRoundness(0);
    QFont font = chart->font();
    font.setPointSizeF(std::max(6.0, font.pointSizeF() * 0.85));
    for (QAbstractAxis* axis : chart->axes()) {
        axis->setLabelsFont(font);
        axis->setTitleFont(font);
        if (auto* log = qobject_cast<QLogValueAxis*>(axis))
            log->setMinorTickCount(0);
    }
    chart->legend()->setFont(font);
}

QLabel* numberLabel(const QString& objectName)
{
    auto* label = new QLabel(QStringLiteral("—"));
    label->setObjectName(objectName);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return label;
}

} // namespace

const std::vector<sim::IntegratorKind>& AccuracyDock::tradeOffIntegrators()
{
    // Every fixed-step method with an order to measure (not the adaptive
    // ones, whose step is their own, nor exact, which has no error to fit).
    static const std::vector<sim::IntegratorKind> kinds = [] {
        std::vector<sim::IntegratorKind> out;
        for (const sim::IntegratorInfo& info : sim::integrators())
            if (!info.adaptive && info.order > 0.0)
                out.push_back(info.kind);
        return out;
    }();
    return kinds;
}

AccuracyDock::AccuracyDock(SimulationController* controller, Canvas* canvas, QWidget* parent)
    : QDockWidget(tr("Accuracy"), parent)
    , m_controller(controller)
    , m_canvas(canvas)
{
    setObjectName(QStringLiteral("accuracyDock"));
    auto* tabs = new QTabWidget;
    tabs->setObjectName(QStringLiteral("accuracyTabs"));

    // --- Drift -------------------------------------------------------------
    auto* drift = new QWidget;
    createDriftGroup(drift);
    tabs->addTab(drift, tr("Drift"));

    tabs->addTab(createGhostTab(), tr("Ghost"));
    tabs->addTab(createTradeOffTab(), tr("Trade-off"));
    setWidget(tabs);

    connect(m_ghostMode, &QComboBox::currentIndexChanged, this, &AccuracyDock::applyGhost);
    connect(m_ghostIntegrator, &QComboBox::currentIndexChanged, this, &AccuracyDock::applyGhost);
    connect(m_ghostDivider, &QComboBox::currentIndexChanged, this, &AccuracyDock::applyGhost);
    connect(m_ghostShown, &QCheckBox::toggled, this, [this](bool on) {
        Overlays o = m_canvas->overlays();
        o.ghost = on;
        m_canvas->setOverlays(o);
    });
    connect(m_controller, &SimulationController::ghostChanged, this, &AccuracyDock::onGhostChanged);
    connect(m_controller, &SimulationController::stepped, this, [this] {
        recordSeparation();
        if (isVisible())
            updateNumbers();
    });
    // The books cost force evaluations: kept only while someone looks at them.
    connect(this, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        m_controller->holdAccounting(this, visible);
        updateNumbers();
    });
    // Opened from the menu while tabbed behind the plots: bring it to the front.
    connect(toggleViewAction(), &QAction::triggered, this, [this](bool on) {
        if (on)
            raise();
    });
    connect(&m_watcher, &QFutureWatcherBase::finished, this, &AccuracyDock::studyFinished);
    onGhostChanged();
}

// The ghost: a second run beside the live one, with its settings and the
// distance between the two runs over time.
QWidget* AccuracyDock::createGhostTab()
{
    auto* ghost = new QWidget;
    auto* ghostLayout = new QVBoxLayout(ghost);
    auto* ghostForm = new QFormLayout;
    m_ghostMode = new QComboBox;
    m_ghostMode->setObjectName(QStringLiteral("ghostMode"));
    m_ghostMode->addItem(tr("Off"));
    m_ghostMode->addItem(tr("Compare with another integrator"));
    m_ghostMode->addItem(tr("Sensitivity twin (moved 1e-10 px)"));
    m_ghostIntegrator = new QComboBox;
    m_ghostIntegrator->setObjectName(QStringLiteral("ghostIntegrator"));
    for (std::string_view n : sim::integratorNames())
        m_ghostIntegrator->addItem(QString::fromLatin1(n.data(), static_cast<qsizetype>(n.size())));
    m_ghostIntegrator->setCurrentIndex(static_cast<int>(sim::IntegratorKind::Ias15)); // the reference
    m_ghostDivider = new QComboBox;
    m_ghostDivider->setObjectName(QStringLiteral("ghostDivider"));
    for (int d : {1, 2, 4, 8, 16})
        m_ghostDivider->addItem(d == 1 ? tr("dt (same)") : tr("dt / %1").arg(d), d);
    m_ghostShown = new QCheckBox(tr("Draw the ghost on the canvas"));
    m_ghostShown->setObjectName(QStringLiteral("ghostShown"));
    m_ghostShown->setChecked(m_canvas->overlays().ghost);
    m_separation = numberLabel(QStringLiteral("separation"));
    ghostForm->addRow(tr("Ghost:"), m_ghostMode);
    ghostForm->addRow(tr("Its integrator:"), m_ghostIntegrator);
    ghostForm->addRow(tr("Its step:"), m_ghostDivider);
    ghostForm->addRow(QString(), m_ghostShown);
    ghostForm->addRow(tr("Separation:"), m_separation);
    ghostLayout->addLayout(ghostForm);
    m_separationChart = new QChart;
    m_separationChart->legend()->hide();
    m_separationSeries = new QLineSeries;
    m_separationChart->addSeries(m_separationSeries);
    m_separationTime = new QValueAxis;
    m_separationTime->setTitleText(tr("t, s"));
    m_separationTime->setTickCount(5);
    m_separationTime->setLabelFormat(QStringLiteral("%.3g"));
    m_separationAxis = new QLogValueAxis;
    m_separationAxis->setTitleText(tr("px"));
    m_separationAxis->setLabelFormat(QStringLiteral("%.0e"));
    m_separationAxis->setRange(kSeparationFloor, 1e3);
    m_separationChart->addAxis(m_separationTime, Qt::AlignBottom);
    m_separationChart->addAxis(m_separationAxis, Qt::AlignLeft);
    m_separationSeries->attachAxis(m_separationTime);
    m_separationSeries->attachAxis(m_separationAxis);
    compact(m_separationChart);
    auto* separationView = new QChartView(m_separationChart);
    separationView->setRenderHint(QPainter::Antialiasing);
    separationView->setMinimumHeight(160);
    ghostLayout->addWidget(separationView, 1);
    return ghost;
}

// The trade-off: every integrator at several steps on the current scene,
// error against cost, measured in the background.
QWidget* AccuracyDock::createTradeOffTab()
{
    m_tradeOffAction = new QAction(tr("Measure the &Trade-off"), this);
    m_tradeOffAction->setObjectName(QStringLiteral("tradeOffAction"));
    m_tradeOffAction->setStatusTip(tr("Run the current scene with every integrator at several steps and plot "
                                      "error against cost"));
    connect(m_tradeOffAction, &QAction::triggered, this, &AccuracyDock::measureTradeOff);
    m_convergenceAction = new QAction(tr("Check &Convergence"), this);
    m_convergenceAction->setObjectName(QStringLiteral("convergenceAction"));
    m_convergenceAction->setStatusTip(tr("Rerun the current scene at dt, dt/2, dt/4, dt/8 and fit the order"));
    connect(m_convergenceAction, &QAction::triggered, this, &AccuracyDock::measureConvergence);
    auto* study = new QWidget;
    auto* studyLayout = new QVBoxLayout(study);
    auto* buttons = new QHBoxLayout;
    auto* tradeOffButton = new QToolButton;
    tradeOffButton->setObjectName(QStringLiteral("tradeOffButton"));
    tradeOffButton->setDefaultAction(m_tradeOffAction);
    auto* convergenceButton = new QToolButton;
    convergenceButton->setObjectName(QStringLiteral("convergenceButton"));
    convergenceButton->setDefaultAction(m_convergenceAction);
    m_cancel = new QPushButton(tr("Cancel"));
    m_cancel->setObjectName(QStringLiteral("cancelStudy"));
    m_cancel->setEnabled(false);
    connect(m_cancel, &QPushButton::clicked, this, &AccuracyDock::cancelMeasurement);
    buttons->addWidget(tradeOffButton);
    buttons->addWidget(convergenceButton);
    buttons->addStretch(1);
    buttons->addWidget(m_cancel);
    studyLayout->addLayout(buttons);
    m_progress = new QProgressBar;
    m_progress->setObjectName(QStringLiteral("studyProgress"));
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    studyLayout->addWidget(m_progress);
    m_studyStatus = new QLabel(tr("Runs the lesson's scene for %1 s with each integrator.").arg(m_studyDuration));
    m_studyStatus->setObjectName(QStringLiteral("studyStatus"));
    m_studyStatus->setWordWrap(true);
    studyLayout->addWidget(m_studyStatus);
    m_tradeOffChart = new QChart;
    m_tradeOffChart->setToolTip(tr("Error against cost, both on log scales: lower left is better"));
    m_tradeOffChart->legend()->setAlignment(Qt::AlignRight);
    m_tradeOffView = new QChartView(m_tradeOffChart);
    m_tradeOffView->setRenderHint(QPainter::Antialiasing);
    m_tradeOffView->setMinimumHeight(200);
    studyLayout->addWidget(m_tradeOffView, 1);
    return study;
}

AccuracyDock::~AccuracyDock()
{
    // The worker reads a copy of the scene and writes only its result; it
    // must not outlive the flag it polls.
    m_cancelFlag = true;
    m_watcher.waitForFinished();
}

void AccuracyDock::createDriftGroup(QWidget* page)
{
    auto* form = new QFormLayout(page);
    m_energyDrift = numberLabel(QStringLiteral("energyDrift"));
    m_energyDrift->setToolTip(tr("(E now − E at the start − energy added or removed on purpose) / |E at the start|: "
                                 "the integrator's own error"));
    m_booked = numberLabel(QStringLiteral("bookedEnergy"));
    m_booked->setToolTip(tr("Energy added (+) or removed (−) on purpose by drag, wind, walls, collisions, the "
                            "pointer and edits, relative to |E at the start|"));
    m_momentumDrift = numberLabel(QStringLiteral("momentumDrift"));
    m_momentumDrift->setToolTip(tr("|p now − p at the start − impulse of the outside forces|"));
    m_evaluationsPerSecond = numberLabel(QStringLiteral("evaluationsPerSecond"));
    m_stepCost = numberLabel(QStringLiteral("stepCost"));
    form->addRow(tr("Energy drift ΔE/|E₀|:"), m_energyDrift);
    form->addRow(tr("Booked on purpose /|E₀|:"), m_booked);
    form->addRow(tr("Momentum drift |Δp|:"), m_momentumDrift);
    form->addRow(tr("Force evaluations per simulated s:"), m_evaluationsPerSecond);
    form->addRow(tr("Step cost:"), m_stepCost);
    auto* explain = new QLabel(tr("Energy added or taken away on purpose (drag, wind, walls, collisions, your "
                                  "pointer, edits) is booked apart. What is left should be zero: it is the "
                                  "integrator's own error."));
    explain->setWordWrap(true);
    form->addRow(explain);
    auto* restart = new QPushButton(tr("Start Counting Again"));
    restart->setObjectName(QStringLiteral("restartDrift"));
    connect(restart, &QPushButton::clicked, this, &AccuracyDock::restartDrift);
    form->addRow(QString(), restart);
}

bool AccuracyDock::isGhostDrawn() const
{
    return m_ghostShown->isChecked();
}

void AccuracyDock::restartDrift()
{
    sim::World& world = m_controller->mutableWorld();
    world.setAccounting(false);
    world.setAccounting(true);
    updateNumbers();
}

void AccuracyDock::updateNumbers()
{
    const sim::World& w = m_controller->world();
    if (w.accounting()) {
        // Relative to the starting energy; with E₀ = 0 (e.g. balls at rest
        // under a spring) the drift is shown in energy units instead.
        const double scale = std::abs(w.startEnergy()) > 0.0 ? std::abs(w.startEnergy()) : 1.0;
        m_energyDrift->setText(sci(w.energyDrift() / scale));
        m_booked->setText(sci(w.bookedEnergy() / scale));
        m_momentumDrift->setText(sci(w.momentumDrift().norm(), QStringLiteral("mass·px/s")));
    } else {
        m_energyDrift->setText(QStringLiteral("—"));
        m_booked->setText(QStringLiteral("—"));
        m_momentumDrift->setText(QStringLiteral("—"));
    }
    m_evaluationsPerSecond->setText(
        w.time() > 0.0 ? QString::number(std::llround(double(w.totals().forceEvaluations) / w.time())) : QStringLiteral("—"));
    m_stepCost->setText(tr("%1 ms, %2")
                            .arg(w.lastStep().seconds * 1e3, 0, 'f', 3)
                            .arg(countText(w.lastStep().forceEvaluations, tr("force evaluation"), tr("force evaluations"))));
}

void AccuracyDock::applyGhost()
{
    const auto mode = static_cast<SimulationController::GhostMode>(m_ghostMode->currentIndex());
    m_controller->setGhost(mode, static_cast<sim::IntegratorKind>(m_ghostIntegrator->currentIndex()),
                           m_ghostDivider->currentData().toInt());
}

// The controller's ghost restarted (switched, new scene, reset): a new plot.
void AccuracyDock::onGhostChanged()
{
    m_separationSeries->clear();
    const bool on = m_controller->ghost() != nullptr;
    {
        // Show what the controller runs (it may have been set from elsewhere).
        const QSignalBlocker b1(m_ghostMode), b2(m_ghostIntegrator), b3(m_ghostDivider);
        m_ghostMode->setCurrentIndex(static_cast<int>(m_controller->ghostMode()));
        m_ghostIntegrator->setCurrentIndex(static_cast<int>(m_controller->ghostIntegrator()));
        m_ghostDivider->setCurrentIndex(std::max(0, m_ghostDivider->findData(m_controller->ghostDivider())));
        // The twin always runs the live integrator and step.
        const bool twin = m_controller->ghostMode() == SimulationController::GhostMode::Twin;
        m_ghostIntegrator->setEnabled(!twin);
        m_ghostDivider->setEnabled(!twin);
    }
    m_separation->setText(on ? sci(m_controller->ghostSeparation(), QStringLiteral("px")) : QStringLiteral("—"));
    m_separationTime->setRange(m_controller->world().time(), m_controller->world().time() + 1.0);
    recordSeparation();
}

void AccuracyDock::recordSeparation()
{
    if (!m_controller->ghost())
        return;
    const double d = m_controller->ghostSeparation();
    m_separation->setText(sci(d, QStringLiteral("px")));
    if (!(std::isfinite(d) && d > 0.0))
        return; // nothing to draw on a log axis (a ghost starts where the balls are)
    const double t = m_controller->world().time();
    if (m_separationSeries->count() > 0 && m_separationSeries->at(m_separationSeries->count() - 1).x() >= t)
        return;
    if (m_separationSeries->count() >= kMaxSeparationPoints)
        m_separationSeries->removePoints(0, m_separationSeries->count() / 2);
    m_separationSeries->append(t, d);
    const double t0 = m_separationSeries->at(0).x();
    m_separationTime->setRange(t0, std::max(t, t0 + 1.0));
    // The y range: whole decades around what has been seen.
    double lo = 1e300, hi = 0.0;
    for (const QPointF& p : m_separationSeries->points()) {
        lo = std::min(lo, p.y());
        hi = std::max(hi, p.y());
    }
    setDecades(m_separationAxis, lo, hi);
}

// The scene as it runs now: the lesson's balls and spawn with the live settings.
sim::Scene AccuracyDock::currentScene() const
{
    sim::Scene scene = m_controller->scene();
    scene.settings = m_controller->world().settings();
    scene.spawn = m_controller->spawn();
    scene.spawn.perStep = 0.0; // every run must hold the same balls
    return scene;
}

void AccuracyDock::measureTradeOff()
{
    startStudy(Study::TradeOff);
}

void AccuracyDock::measureConvergence()
{
    startStudy(Study::Convergence);
}

void AccuracyDock::cancelMeasurement()
{
    m_cancelFlag = true;
}

void AccuracyDock::startStudy(Study kind)
{
    if (isMeasuring())
        return;
    const sim::Scene scene = currentScene();
    // The integrator's own step: the world's step split into its sub-steps.
    const double h = scene.settings.time.dt / std::max(1, scene.settings.time.substeps);
    sim::WorkPrecisionSettings settings;
    settings.duration = std::max(1.0, std::ceil(m_studyDuration / h)) * h;
    settings.dts = {h, h / 2, h / 4, h / 8};
    settings.threads = std::max(1, QThread::idealThreadCount()); // the lesson's own steps are cheap beside these
    m_study = kind;
    m_convergenceIntegrator = scene.settings.time.integrator;
    settings.integrators = kind == Study::TradeOff ? tradeOffIntegrators()
                                                   : std::vector<sim::IntegratorKind>{m_convergenceIntegrator};
    const int total = 1 + static_cast<int>(settings.integrators.size() * settings.dts.size());
    m_progress->setRange(0, total);
    m_progress->setValue(0);
    m_studyStatus->setText(kind == Study::TradeOff
                               ? tr("Measuring %1 runs of %2 s…").arg(total).arg(settings.duration)
                               : tr("Running %1 at dt, dt/2, dt/4, dt/8 for %2 s…")
                                     .arg(nameOf(m_convergenceIntegrator))
                                     .arg(settings.duration));
    m_tradeOffAction->setEnabled(false);
    m_convergenceAction->setEnabled(false);
    m_cancel->setEnabled(true);
    m_cancelFlag = false;
    m_measuring = true;
    // The worker gets its own copy of everything it reads; progress comes
    // back to this thread through queued calls.
    auto progress = [this](int done, int) {
        QMetaObject::invokeMethod(this, [this, done] { m_progress->setValue(done); }, Qt::QueuedConnection);
    };
    m_watcher.setFuture(QtConcurrent::run([scene, settings, progress, flag = &m_cancelFlag] {
        return sim::measureWorkPrecision(scene, settings, progress, flag);
    }));
}

void AccuracyDock::studyFinished()
{
    m_measuring = false;
    m_tradeOffAction->setEnabled(true);
    m_convergenceAction->setEnabled(true);
    m_cancel->setEnabled(false);
    m_lastStudy = m_watcher.future().result();
    const sim::WorkPrecisionResult& r = m_lastStudy;
    if (r.error) {
        m_studyStatus->setText(tr("Could not measure: %1").arg(QString::fromStdString(*r.error)));
        return;
    }
    if (r.cancelled) {
        m_studyStatus->setText(tr("Cancelled after %1 runs.").arg(r.runs.size()));
        return;
    }
    m_progress->setValue(m_progress->maximum());
    if (m_study == Study::TradeOff) {
        showTradeOff(r);
        // The slope of each line is its order: fitted the same way as the
        // convergence check, over the integrator's four steps.
        QStringList orders;
        for (sim::IntegratorKind kind : tradeOffIntegrators()) {
            std::vector<double> dts, errors;
            for (const sim::PrecisionRun& run : r.runs)
                if (run.integrator == kind && run.refused.empty() && !run.blewUp) {
                    dts.push_back(run.dt);
                    errors.push_back(run.positionError);
                }
            const double p = sim::fittedOrder(dts, errors);
            if (!std::isnan(p))
                orders << QStringLiteral("%1 %2").arg(nameOf(kind)).arg(p, 0, 'f', 1);
        }
        m_studyStatus->setText(tr("Done: %1 runs against ias15 at dt/8. Each dot is one run; a steeper line is a "
                                  "higher order. Fitted orders: %2.")
                                   .arg(r.runs.size())
                                   .arg(orders.join(QStringLiteral(", "))));
        return;
    }
    std::vector<double> dts, errors;
    QStringList lines;
    for (const sim::PrecisionRun& run : r.runs) {
        if (!run.refused.empty()) {
            m_studyStatus->setText(tr("%1 cannot run this scene: %2")
                                       .arg(nameOf(run.integrator), QString::fromStdString(run.refused)));
            return;
        }
        dts.push_back(run.dt);
        errors.push_back(run.blewUp ? std::nan("") : run.positionError);
        lines << tr("dt = %1 s: error %2").arg(humanNumber(run.dt, 4), sci(run.positionError, QStringLiteral("px")));
    }
    m_lastOrder = sim::fittedOrder(dts, errors);
    const double theory = sim::theoreticalOrder(m_convergenceIntegrator);
    QString verdict = tr("%1: fitted order %2").arg(nameOf(m_convergenceIntegrator),
                                                    std::isnan(m_lastOrder) ? QStringLiteral("—")
                                                                            : QString::number(m_lastOrder, 'f', 2));
    if (!std::isnan(theory))
        verdict += tr(" (theory: %1)").arg(theory);
    m_studyStatus->setText(verdict + QStringLiteral("\n") + lines.join(QLatin1Char('\n')));
}

// Error against force evaluations, both on log axes, one line per integrator
// through its four step sizes.
void AccuracyDock::showTradeOff(const sim::WorkPrecisionResult& r)
{
    m_tradeOffChart->removeAllSeries();
    for (QAbstractAxis* axis : m_tradeOffChart->axes())
        m_tradeOffChart->removeAxis(axis);
    auto* x = new QLogValueAxis;
    x->setTitleText(tr("cost: force evaluations"));
    x->setLabelFormat(QStringLiteral("%.0e"));
    auto* y = new QLogValueAxis;
    y->setTitleText(tr("error, px"));
    y->setLabelFormat(QStringLiteral("%.0e"));
    m_tradeOffChart->addAxis(x, Qt::AlignBottom);
    m_tradeOffChart->addAxis(y, Qt::AlignLeft);
    double xlo = 1e300, xhi = 0, ylo = 1e300, yhi = 0;
    for (sim::IntegratorKind kind : tradeOffIntegrators()) {
        auto* series = new QLineSeries;
        series->setName(nameOf(kind));
        series->setPointsVisible(true);
        for (const sim::PrecisionRun& run : r.runs) {
            if (run.integrator != kind || !run.refused.empty() || run.blewUp || run.forceEvaluations <= 0)
                continue;
            // An error of exactly 0 (the motion is exact) sits on the floor.
            const double e = std::max(run.positionError, 1e-14);
            const double c = double(run.forceEvaluations);
            series->append(c, e);
            xlo = std::min(xlo, c);
            xhi = std::max(xhi, c);
            ylo = std::min(ylo, e);
            yhi = std::max(yhi, e);
        }
        if (series->count() == 0) {
            delete series; // this integrator cannot run the scene
            continue;
        }
        m_tradeOffChart->addSeries(series);
        series->attachAxis(x);
        series->attachAxis(y);
    }
    if (xhi > 0) {
        setDecades(x, xlo, xhi);
        setDecades(y, ylo, yhi);
    }
    compact(m_tradeOffChart);
}

} // namespace forcelab
