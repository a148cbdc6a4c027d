// The Accuracy dock and the ghost, driven as a student would: the drift
// numbers are the world's own books, the ghost runs the same scene beside the
// live one (by default with the reference integrator) and restarts with it,
// the sensitivity twin shows chaos in the three-body lesson and none on a
// spring or an orbit, and the trade-off and convergence studies run in the
// background, can be cancelled, and report what theory predicts.

#include "tests/sim_test_util.h"
#include "ui/docks/accuracy_dock.h"
#include "ui/canvas/canvas.h"
#include "ui/drawing/human_number.h"
#include "ui/window/main_window.h"
#include "ui/canvas/simulation_controller.h"

#include "sim/world/world.h"

#include <QAbstractSeries>
#include <QAction>
#include <QChart>
#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QMenuBar>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTest>
#include <QToolButton>
#include <QXYSeries>

#include <cmath>

using namespace forcelab;

namespace {

// A ball on a spring with linear drag: energy leaves on purpose, so the books
// have something to book.
sim::Scene springScene(sim::IntegratorKind integrator, double dt, bool drag)
{
    sim::Scene s;
    s.settings.box = {600.0, 400.0};
    s.settings.walls = sim::WallSettings{false, false, false, false, sim::WallModel::Clamp, 1.0};
    s.settings.spring = sim::SpringSettings{true, sim::Vec2(300, 200), 4.0};
    if (drag)
        s.settings.drag = sim::DragSettings{true, sim::DragLaw::Linear, 0.5, sim::ForceScale::None};
    s.settings.time.integrator = integrator;
    s.settings.time.dt = dt;
    s.balls = {sim::ballAt(400, 200, 0, 120, 10, 1)};
    return s;
}

Lesson lessonOf(const sim::Scene& scene)
{
    Lesson lesson;
    lesson.id = QStringLiteral("test-scene");
    lesson.title = QStringLiteral("Test scene");
    lesson.scene = scene;
    return lesson;
}

double numberIn(const QWidget* root, const char* name)
{
    auto* label = root->findChild<QLabel*>(QString::fromLatin1(name));
    if (!label)
        return std::nan("");
    // As a student reads it: "1.23 × 10⁻⁵", maybe with a unit after it.
    return humanNumberValue(label->text()).value_or(std::nan(""));
}

// Runs the paused controller for `seconds` of simulated time in one frame.
void runFor(SimulationController* c, double seconds)
{
    c->pause();
    c->setMaxStepsPerFrame(1'000'000);
    c->advance(seconds);
}

bool close(double shown, double actual)
{
    // The dock shows three significant digits.
    return std::abs(shown - actual) <= 6e-3 * std::abs(actual) + 1e-300;
}

} // namespace

class GuiAccuracyTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void dockIsInTheMenus();
    void driftNumbersAreTheWorlds();
    void ghostFollowsTheScene();
    void twinShowsChaosInThreeBodies();
    void twinStaysCloseOnSpringAndOrbit_data();
    void twinStaysCloseOnSpringAndOrbit();
    void tradeOffRunsToTheEnd();
    void tradeOffCanBeCancelled();
    void convergenceReportsTheOrder_data();
    void convergenceReportsTheOrder();
};

void GuiAccuracyTest::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("ForceLabTest"));
    QCoreApplication::setApplicationName(QStringLiteral("test_gui_accuracy"));
    QSettings().clear();
}

void GuiAccuracyTest::dockIsInTheMenus()
{
    MainWindow window;
    AccuracyDock* dock = window.findChild<AccuracyDock*>(QStringLiteral("accuracyDock"));
    QVERIFY(dock);
    QCOMPARE(window.accuracyDock(), dock);
    bool inView = false, tradeOff = false;
    for (QAction* menu : window.menuBar()->actions())
        for (QAction* a : menu->menu()->actions()) {
            inView |= a == dock->toggleViewAction();
            tradeOff |= a == dock->tradeOffAction();
        }
    QVERIFY(inView);
    QVERIFY(tradeOff);
}

void GuiAccuracyTest::driftNumbersAreTheWorlds()
{
    MainWindow window;
    QVERIFY(window.setLesson(lessonOf(springScene(sim::IntegratorKind::SemiImplicitEuler, 1.0 / 60, true))));
    window.show();
    AccuracyDock* dock = window.accuracyDock();
    SimulationController* c = window.controller();
    QVERIFY(!c->world().accounting()); // closed: no books, no extra cost
    dock->toggleViewAction()->trigger(); // View > Accuracy
    QTRY_VERIFY(c->world().accounting());
    runFor(c, 3.0);
    const sim::World& w = c->world();
    QVERIFY(w.bookedEnergy() < 0.0); // drag took energy out
    const double e0 = std::abs(w.startEnergy());
    QVERIFY2(close(numberIn(dock, "energyDrift"), w.energyDrift() / e0),
             qPrintable(QStringLiteral("%1 vs %2").arg(numberIn(dock, "energyDrift")).arg(w.energyDrift() / e0)));
    QVERIFY(close(numberIn(dock, "bookedEnergy"), w.bookedEnergy() / e0));
    QVERIFY(close(numberIn(dock, "momentumDrift"), w.momentumDrift().norm()));
    // The booking takes the drag's work out: what is left is far smaller.
    QVERIFY(std::abs(w.energyDrift()) < 0.1 * std::abs(w.bookedEnergy()));
    // One evaluation per step for semi-implicit Euler plus the books' own.
    QVERIFY(numberIn(dock, "evaluationsPerSecond") >= 60.0);

    // A reset restarts the books, and they stay on while the dock is open.
    c->reset();
    QVERIFY(c->world().accounting());
    QCOMPARE(c->world().bookedEnergy(), 0.0);
    QCOMPARE(c->world().startEnergy(), c->world().energy().total());

    dock->toggleViewAction()->trigger();
    QTRY_VERIFY(!c->world().accounting());
}

void GuiAccuracyTest::ghostFollowsTheScene()
{
    MainWindow window;
    QVERIFY(window.openLesson(QStringLiteral("two-bodies-in-orbit")));
    window.show();
    AccuracyDock* dock = window.accuracyDock();
    SimulationController* c = window.controller();
    auto* mode = dock->findChild<QComboBox*>(QStringLiteral("ghostMode"));
    auto* integrator = dock->findChild<QComboBox*>(QStringLiteral("ghostIntegrator"));
    QVERIFY(mode && integrator);
    QCOMPARE(integrator->currentText(), QStringLiteral("ias15")); // the reference by default
    QVERIFY(!c->ghost());

    mode->setCurrentIndex(int(SimulationController::GhostMode::Compare));
    QVERIFY(c->ghost());
    QCOMPARE(c->ghost()->settings().time.integrator, sim::IntegratorKind::Ias15);
    QCOMPARE(window.canvas()->paintOptions().ghost, c->ghost());
    QCOMPARE(c->ghostSeparation(), 0.0);
    runFor(c, 2.0);
    QCOMPARE(c->ghost()->time(), c->world().time());
    const double apart = c->ghostSeparation();
    QVERIFY(apart > 0.0);      // semi-implicit Euler is not ias15
    QVERIFY(apart < 50.0);     // but it is the same orbit
    QCOMPARE(numberIn(dock, "separation"), humanNumberValue(humanNumber(apart, 3)).value());
    QVERIFY2(dock->findChild<QLabel*>(QStringLiteral("separation"))->text().endsWith(QStringLiteral(" px")),
             qPrintable(dock->findChild<QLabel*>(QStringLiteral("separation"))->text()));
    QVERIFY(dock->separationChart()->series().size() == 1);
    // Drawn: the outlines change the picture of the same state.
    const QImage with = window.canvas()->renderImage();
    auto* drawn = dock->findChild<QCheckBox*>(QStringLiteral("ghostShown"));
    QVERIFY(drawn->isChecked());
    drawn->setChecked(false);
    QVERIFY(window.canvas()->renderImage() != with);

    QVERIFY(!window.canvas()->overlays().ghost);
    QVERIFY(window.openLesson(QStringLiteral("three-bodies"))); // the switch outlives the lesson
    QVERIFY(!window.canvas()->overlays().ghost);
    QVERIFY(window.openLesson(QStringLiteral("two-bodies-in-orbit")));
    runFor(c, 2.0);
    drawn->setChecked(true);
    QVERIFY(window.canvas()->overlays().ghost);

    // A step of dt/4 lands on the same times.
    const double t0 = c->world().time();
    dock->findChild<QComboBox*>(QStringLiteral("ghostDivider"))->setCurrentIndex(2);
    QCOMPARE(c->ghost()->settings().time.dt, c->world().settings().time.dt / 4);
    runFor(c, 0.5);
    QVERIFY(std::abs(c->ghost()->time() - (c->world().time() - t0)) < 1e-9);

    // Reset: the ghost restarts with the scene.
    c->reset();
    QVERIFY(c->ghost());
    QCOMPARE(c->ghost()->time(), 0.0);
    QCOMPARE(c->ghostSeparation(), 0.0);

    // A ball added by hand: the ghost starts again from the edited balls, so
    // every ball has its ghost and the separation is a number, not ∞.
    runFor(c, 1.0);
    QVERIFY(c->ghostSeparation() > 0.0);
    window.canvas()->addBall();
    QCOMPARE(c->world().balls().size(), 3);
    QCOMPARE(c->ghost()->balls().size(), 3);
    QCOMPARE(c->ghostSeparation(), 0.0);
    runFor(c, 1.0);
    const double afterAdd = c->ghostSeparation();
    QVERIFY2(std::isfinite(afterAdd) && afterAdd > 0.0, qPrintable(QString::number(afterAdd)));
    mode->setCurrentIndex(0);
    QVERIFY(!c->ghost());
}

void GuiAccuracyTest::twinShowsChaosInThreeBodies()
{
    MainWindow window;
    QVERIFY(window.openLesson(QStringLiteral("three-bodies")));
    SimulationController* c = window.controller();
    window.accuracyDock()->findChild<QComboBox*>(QStringLiteral("ghostMode"))
        ->setCurrentIndex(int(SimulationController::GhostMode::Twin));
    QVERIFY(c->ghost());
    QCOMPARE(c->ghost()->settings().time.integrator, c->world().settings().time.integrator);
    const double start = c->ghostSeparation();
    QVERIFY(start > 0.0 && start < 1e-9);
    // With Plummer softening the pull is smooth, so the growth is the
    // physics' own: the twin's 1e-10 px measured 3.1e-7 px by 20 s and
    // 4.9e-4 px (×4.9e6) by 30 s.
    runFor(c, 30.0);
    QVERIFY(std::abs(c->world().time() - 30.0) < 1e-9);
    const double end = c->ghostSeparation();
    qInfo("three bodies: twin separation %.3g px at 0 s, %.3g px at 30 s", start, end);
    QVERIFY(end > 1e6 * start); // a tenth of a nanometre becomes visible
}

void GuiAccuracyTest::twinStaysCloseOnSpringAndOrbit_data()
{
    QTest::addColumn<QString>("lesson");
    QTest::newRow("spring") << QStringLiteral("elastic-band");
    QTest::newRow("orbit") << QStringLiteral("two-bodies-in-orbit");
}

void GuiAccuracyTest::twinStaysCloseOnSpringAndOrbit()
{
    QFETCH(QString, lesson);
    MainWindow window;
    QVERIFY(window.openLesson(lesson));
    SimulationController* c = window.controller();
    c->setGhost(SimulationController::GhostMode::Twin);
    runFor(c, 10.0);
    const double end = c->ghostSeparation();
    qInfo("%s: twin separation %.3g px at 10 s", qPrintable(lesson), end);
    QVERIFY(end < 1e-6);
}

void GuiAccuracyTest::tradeOffRunsToTheEnd()
{
    MainWindow window;
    QVERIFY(window.setLesson(lessonOf(springScene(sim::IntegratorKind::SemiImplicitEuler, 1.0 / 64, false))));
    window.controller()->pause();
    AccuracyDock* dock = window.accuracyDock();
    dock->setStudyDuration(0.5);
    dock->tradeOffAction()->trigger();
    QVERIFY(dock->isMeasuring());
    QVERIFY(!dock->tradeOffAction()->isEnabled());
    dock->studyFuture().waitForFinished();
    QTRY_VERIFY(dock->tradeOffAction()->isEnabled());
    const sim::WorkPrecisionResult& r = dock->lastStudy();
    QVERIFY(!r.error && !r.cancelled);
    QCOMPARE(r.runs.size(), AccuracyDock::tradeOffIntegrators().size() * 4);
    const QList<QAbstractSeries*> series = dock->tradeOffChart()->series();
    QCOMPARE(series.size(), qsizetype(AccuracyDock::tradeOffIntegrators().size()));
    for (QAbstractSeries* s : series)
        QCOMPARE(static_cast<QXYSeries*>(s)->count(), 4);
    QCOMPARE(series[3]->name(), QStringLiteral("rk4"));
    // rk4's smallest step beats Euler's smallest step by orders of magnitude.
    QVERIFY(static_cast<QXYSeries*>(series[3])->at(3).y() < 1e-3 * static_cast<QXYSeries*>(series[0])->at(3).y());
    QCOMPARE(dock->findChild<QProgressBar*>(QStringLiteral("studyProgress"))->value(), 1 + 5 * 4);
    // The status names each line's slope; on a spring Verlet's is 2.
    const QString status = dock->findChild<QLabel*>(QStringLiteral("studyStatus"))->text();
    QVERIFY2(status.contains(QStringLiteral("verlet 2.0")), qPrintable(status));
}

void GuiAccuracyTest::tradeOffCanBeCancelled()
{
    MainWindow window;
    QVERIFY(window.setLesson(lessonOf(springScene(sim::IntegratorKind::SemiImplicitEuler, 1.0 / 64, false))));
    window.controller()->pause();
    AccuracyDock* dock = window.accuracyDock();
    dock->setStudyDuration(2000.0); // minutes of work: only a cancel ends it soon
    dock->tradeOffAction()->trigger();
    auto* cancel = dock->findChild<QPushButton*>(QStringLiteral("cancelStudy"));
    QVERIFY(cancel->isEnabled());
    QTest::mouseClick(cancel, Qt::LeftButton);
    QVERIFY(dock->studyFuture().isStarted());
    dock->studyFuture().waitForFinished();
    QTRY_VERIFY(dock->tradeOffAction()->isEnabled());
    QVERIFY(dock->lastStudy().cancelled);
    QVERIFY(dock->lastStudy().runs.size() < AccuracyDock::tradeOffIntegrators().size() * 4);
    QVERIFY(!cancel->isEnabled());
    QVERIFY(dock->findChild<QLabel*>(QStringLiteral("studyStatus"))->text().contains(QStringLiteral("Cancelled")));
}

void GuiAccuracyTest::convergenceReportsTheOrder_data()
{
    QTest::addColumn<int>("kind");
    QTest::addColumn<double>("dt");
    QTest::addColumn<double>("order");
    QTest::newRow("semi-implicit-euler") << int(sim::IntegratorKind::SemiImplicitEuler) << 1.0 / 512 << 1.0;
    QTest::newRow("verlet") << int(sim::IntegratorKind::Verlet) << 1.0 / 64 << 2.0;
    QTest::newRow("rk4") << int(sim::IntegratorKind::Rk4) << 1.0 / 16 << 4.0;
}

void GuiAccuracyTest::convergenceReportsTheOrder()
{
    QFETCH(int, kind);
    QFETCH(double, dt);
    QFETCH(double, order);
    MainWindow window;
    QVERIFY(window.setLesson(lessonOf(springScene(static_cast<sim::IntegratorKind>(kind), dt, false))));
    window.controller()->pause();
    AccuracyDock* dock = window.accuracyDock();
    dock->setStudyDuration(2.0);
    auto* button = dock->findChild<QToolButton*>(QStringLiteral("convergenceButton"));
    QVERIFY(button);
    QTest::mouseClick(button, Qt::LeftButton);
    QVERIFY(dock->isMeasuring());
    dock->studyFuture().waitForFinished();
    QTRY_VERIFY(dock->convergenceAction()->isEnabled());
    QVERIFY2(std::abs(dock->lastOrder() - order) < 0.15, qPrintable(QString::number(dock->lastOrder())));
    const QString status = dock->findChild<QLabel*>(QStringLiteral("studyStatus"))->text();
    QVERIFY2(status.contains(QStringLiteral("fitted order %1").arg(dock->lastOrder(), 0, 'f', 2)), qPrintable(status));
}

QTEST_MAIN(GuiAccuracyTest)
#include "test_gui_accuracy.moc"
