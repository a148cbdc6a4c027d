// File → Check a Student's Trace: a trace written by another program is
// checked against the run on screen, the first departure is named with its
// cause, and the canvas shows the run at that step with the student's
// position marked.

#include "gui_workbench.h"

#include "ui/canvas/canvas.h"
#include "ui/window/trace_check.h"

#include "sim/world/world.h"

#include <QFile>
#include <QLabel>
#include <QMessageBox>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>

#include <cstdio>

using namespace forcelab;

namespace {

// A student's CSV trace of `scene`: every ball at steps 0 to `steps`, with
// 17 significant digits (what a JavaScript program prints).
QString writeTrace(const QString& path, const sim::Scene& scene, int steps)
{
    sim::World world;
    if (world.reset(scene))
        return {};
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Text))
        return {};
    f.write("step,ball,x,y,vx,vy\n");
    char line[256];
    for (int s = 0; s <= steps; ++s) {
        if (s > 0)
            world.step();
        const sim::BallState& b = world.balls();
        for (int i = 0; i < b.size(); ++i) {
            std::snprintf(line, sizeof line, "%d,%d,%.17g,%.17g,%.17g,%.17g\n", s, i, b.position(0, i),
                          b.position(1, i), b.velocity(0, i), b.velocity(1, i));
            f.write(line);
        }
    }
    return path;
}

} // namespace

class GuiTraceTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }
    void updateOrderBugIsFoundAndShown();
    void theRunsOwnTraceAgrees();
    void aBadFileIsOneLineAndChangesNothing();
};

// Lesson 07 runs semi-implicit Euler; a student who moves the ball with the
// old velocity (explicit Euler) departs at step 1, ball 0, by g·dt² in y.
void GuiTraceTest::updateOrderBugIsFoundAndShown()
{
    test::Workbench w(QStringLiteral("gravity"));
    QVERIFY(w.ready());
    QTemporaryDir dir;
    sim::Scene euler = w.controller()->scene();
    euler.settings.time.integrator = sim::IntegratorKind::Euler;
    const QString path = writeTrace(dir.filePath(QStringLiteral("euler.csv")), euler, 60);
    QVERIFY(!path.isEmpty());
    TraceCheck* check = w.window.traceCheck();
    QVERIFY(check->checkFile(path));
    QTRY_VERIFY_WITH_TIMEOUT(!check->lastResult().isEmpty(), 30000);
    const QString text = check->lastResult();
    QVERIFY2(text.contains(QStringLiteral("departs from the run at step 1")) && text.contains(QStringLiteral("ball 0")),
             qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("update order")), qPrintable(text));
    // The result is on screen, in a window of its own.
    auto* box = w.window.findChild<QMessageBox*>(QStringLiteral("traceCheckResult"));
    QVERIFY(box && box->isVisible() && box->text() == text);
    // The canvas shows the run at step 1, ball 0 selected, and the student's
    // position g·dt² = 980/3600 px above the run's.
    const sim::World& world = w.controller()->world();
    QCOMPARE(world.stepCount(), std::int64_t(1));
    QCOMPARE(w.window.canvas()->selectedBall(), 0);
    QVERIFY(w.window.canvas()->showsTraceMark());
    const Canvas::TraceMark mark = *w.window.canvas()->traceMark();
    QCOMPARE(mark.ball, 0);
    const double dy = world.balls().position(1, 0) - mark.student.y();
    QVERIFY2(std::abs(dy - 980.0 / 3600.0) < 1e-9, qPrintable(QString::number(dy, 'g', 17)));
    QCOMPARE(mark.student.x(), world.balls().position(0, 0));
    // The mark is drawn: the picture with it differs from the one without.
    const QImage with = w.window.canvas()->grab().toImage();
    w.window.canvas()->setTraceMark(std::nullopt);
    QVERIFY(w.window.canvas()->grab().toImage() != with);
}

// The run's own numbers agree, row for row.
void GuiTraceTest::theRunsOwnTraceAgrees()
{
    test::Workbench w(QStringLiteral("gravity"));
    QVERIFY(w.ready());
    QTemporaryDir dir;
    sim::Scene scene = w.controller()->scene();
    scene.settings = w.controller()->world().settings();
    const QString path = writeTrace(dir.filePath(QStringLiteral("same.csv")), scene, 120);
    TraceCheck* check = w.window.traceCheck();
    QVERIFY(check->checkFile(path));
    QTRY_VERIFY_WITH_TIMEOUT(!check->lastResult().isEmpty(), 30000);
    QVERIFY2(check->lastResult().contains(QStringLiteral("agrees with the run at every one of its")) &&
                 check->lastResult().contains(QStringLiteral("to step 120")),
             qPrintable(check->lastResult()));
    QVERIFY(!w.window.canvas()->traceMark());
    QCOMPARE(w.controller()->world().stepCount(), std::int64_t(0)); // nothing to show: the run stays where it was
}

// A broken file: one line naming the file, the line and the field; no check runs.
void GuiTraceTest::aBadFileIsOneLineAndChangesNothing()
{
    test::Workbench w(QStringLiteral("gravity"));
    QVERIFY(w.ready());
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("bad.csv"));
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("step,ball,x,y\n0,0,1.5,2\n1,0,one,2\n");
    f.close();
    QString error;
    connect(w.window.traceCheck(), &TraceCheck::error, this, [&](const QString& m) { error = m; });
    QVERIFY(!w.window.traceCheck()->checkFile(path));
    QVERIFY2(error.contains(QStringLiteral("bad.csv:3:")) && error.contains(QStringLiteral("x:")) &&
                 !error.contains(QLatin1Char('\n')),
             qPrintable(error));
    QVERIFY(w.window.statusBar()->currentMessage().contains(QStringLiteral("bad.csv:3:")));
    QVERIFY(w.window.traceCheck()->lastResult().isEmpty());
    QVERIFY(!w.window.traceCheck()->isRunning());
}

QTEST_MAIN(GuiTraceTest)
#include "test_gui_trace.moc"
