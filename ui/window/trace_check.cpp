#include "ui/window/trace_check.h"

#include "ui/canvas/canvas.h"
#include "ui/canvas/simulation_controller.h"
#include "ui/drawing/display_units.h"
#include "ui/drawing/human_number.h"

#include <QAction>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QtConcurrent/QtConcurrentRun>

#include <memory>

namespace forcelab {

namespace {

QString qs(const std::string& s)
{
    return QString::fromStdString(s);
}

} // namespace

TraceCheck::TraceCheck(SimulationController* controller, Canvas* canvas, QWidget* window)
    : QObject(window)
    , m_controller(controller)
    , m_canvas(canvas)
    , m_window(window)
{
    m_action = new QAction(tr("Check a Student's &Trace…"), this);
    m_action->setObjectName(QStringLiteral("checkTraceAction"));
    m_action->setStatusTip(tr("Check a trace a student's own program wrote (CSV or JSON: step, ball, x, y, vx, vy) "
                              "against this run: where it first departs, and why"));
    connect(m_action, &QAction::triggered, this, &TraceCheck::chooseFile);
    connect(&m_watcher, &QFutureWatcher<Outcome>::finished, this, &TraceCheck::showOutcome);
}

TraceCheck::~TraceCheck()
{
    m_watcher.waitForFinished(); // the worker reads nothing of ours, but its result must not outlive us
}

void TraceCheck::chooseFile()
{
    const QString path = QFileDialog::getOpenFileName(m_window, tr("Check a Student's Trace"), QString(),
                                                      tr("Traces (*.csv *.json);;All files (*)"));
    if (!path.isEmpty())
        checkFile(path);
}

bool TraceCheck::checkFile(const QString& path)
{
    if (m_watcher.isRunning()) {
        emit error(tr("%1: a trace is still being checked; wait for its result").arg(QFileInfo(path).fileName()));
        return false;
    }
    lessons::StudentTrace trace = lessons::readStudentTrace(path);
    if (!trace.error.empty()) {
        emit error(qs(trace.error));
        return false;
    }
    // The run as it starts now: the lesson's balls with the live settings.
    sim::Scene scene = m_controller->scene();
    scene.settings = m_controller->world().settings();
    m_dt = scene.settings.time.dt;
    m_file = QFileInfo(path).fileName();
    m_trace = std::move(trace);
    auto rows = std::make_shared<const std::vector<sim::StudentRow>>(m_trace.rows);
    m_watcher.setFuture(QtConcurrent::run([scene, rows] {
        Outcome o;
        o.match = sim::matchTrace(scene, *rows, kTolerance);
        if (o.match.departure && !o.match.problem)
            o.diagnosis = sim::diagnose(scene, *rows, kTolerance, o.match);
        return o;
    }));
    return true;
}

void TraceCheck::showOutcome()
{
    const Outcome o = m_watcher.result();
    QString text;
    if (o.match.problem) {
        text = tr("%1 cannot be checked: %2").arg(m_file, qs(*o.match.problem));
    } else if (!o.match.departure) {
        text = tr("%1 agrees with the run at every one of its %2 rows (to step %3, t = %4 s): the largest "
                  "difference is %5.")
                   .arg(m_file)
                   .arg(o.match.rowsAgreeing)
                   .arg(o.match.lastStep)
                   .arg(humanNumber(static_cast<double>(o.match.lastStep) * m_dt, 4),
                        humanNumber(o.match.largestAgreeing, 3));
    } else {
        const sim::Departure& d = *o.match.departure;
        const QString unit = d.field.starts_with('v') ? QStringLiteral("px/s") : QStringLiteral("px");
        text = tr("%1 departs from the run at step %2 (t = %3 s), ball %4: %5 is %6 where the run has %7, off "
                  "by %8.")
                   .arg(m_file)
                   .arg(d.step)
                   .arg(humanNumber(static_cast<double>(d.step) * m_dt, 4))
                   .arg(d.ball)
                   .arg(qs(d.field), quantityText(d.student, unit, 10), quantityText(d.reference, unit, 10),
                        quantityText(d.size, unit, 3));
        if (o.diagnosis)
            text += QStringLiteral("\n\n") + tr("Likely cause: %1. The numbers follow the run with %2: %3")
                                                 .arg(qs(o.diagnosis->variant.cause), qs(o.diagnosis->variant.setting),
                                                      qs(o.diagnosis->variant.meaning));
        else
            text += QStringLiteral("\n\n") + tr("No known mistake explains it: %1").arg(qs(sim::usualCauses()));
        if (d.step > kMostStepsShown)
            text += QStringLiteral("\n\n") + tr("The canvas does not go there: step %1 is past the %2 steps it runs "
                                                 "to at once.").arg(d.step).arg(kMostStepsShown);
        else
            showOnCanvas(d);
    }
    m_lastResult = text;
    if (!m_box) {
        m_box = new QMessageBox(QMessageBox::Information, tr("Student's trace"), QString(), QMessageBox::Close,
                                m_window);
        m_box->setObjectName(QStringLiteral("traceCheckResult"));
        m_box->setWindowModality(Qt::NonModal);
        m_box->setAttribute(Qt::WA_DeleteOnClose);
        m_box->setTextFormat(Qt::PlainText); // the file's name and fields come from a stranger
    }
    m_box->setText(text);
    m_box->show();
    emit finished(text);
}

// The run from its start to the departing step, the ball selected and the
// student's position marked. The run is the one checked only if nothing
// changed since it started; the value the check found is compared, and
// nothing is marked when it is not there.
void TraceCheck::showOnCanvas(const sim::Departure& d)
{
    const sim::WorldSettings live = m_controller->world().settings();
    m_controller->reset();
    m_controller->setSettings(live);
    m_controller->runToStep(d.step);
    const sim::World& world = m_controller->world();
    if (world.stepCount() != d.step || d.ball >= world.balls().size())
        return;
    const double shown = d.field == "x"    ? world.balls().position(0, d.ball)
                         : d.field == "y"  ? world.balls().position(1, d.ball)
                         : d.field == "vx" ? world.balls().velocity(0, d.ball)
                                           : world.balls().velocity(1, d.ball);
    if (shown != d.reference)
        return;
    for (const sim::StudentRow& row : m_trace.rows)
        if (row.step == d.step && row.ball == d.ball) {
            m_canvas->setSelectedBall(d.ball);
            m_canvas->setTraceMark(Canvas::TraceMark{d.step, d.ball, sim::Vec2(row.x, row.y),
                                                     tr("student's ball %1, step %2").arg(d.ball).arg(d.step)});
            return;
        }
}

} // namespace forcelab
