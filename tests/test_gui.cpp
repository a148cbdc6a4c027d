// The workbench driven as a user would: controls change the world they edit,
// the canvas shows balls where the world says they are, keyboard shortcuts
// act, pointer events reach the world, and the frame loop takes whole steps.

#include "tests/sim_test_util.h"
#include "ui/canvas/canvas.h"
#include "ui/window/main_window.h"
#include "ui/controls/parameter_panel.h"
#include "ui/controls/settings_editor.h"
#include "ui/canvas/simulation_controller.h"
#include "ui/drawing/view_transform.h"
#include "ui/drawing/world_painter.h"

#include "lessons/lesson_loader.h"
#include "sim/world/names.h"

#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QGroupBox>
#include <QImage>
#include <QPainter>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTest>
#include <QTimer>

#include <cmath>

using namespace forcelab;

namespace {

// A 600 × 400 box with three resting balls at places off the grid lines.
sim::Scene threeBalls()
{
    sim::Scene scene;
    scene.settings.box = {600.0, 400.0};
    scene.balls = {forcelab::test::coloured(sim::ballAt(110, 120, 0, 0, 20), 0xe05050),
                   forcelab::test::coloured(sim::ballAt(310, 210, 0, 0, 30), 0x50b050),
                   forcelab::test::coloured(sim::ballAt(520, 330, 0, 0, 15), 0x3090d0)};
    return scene;
}

// One ball falling in a tall box under gravity.
sim::Scene fallingBall()
{
    sim::Scene scene;
    scene.settings.box = {600.0, 2000.0};
    scene.settings.gravity.enabled = true;
    scene.settings.gravity.g = {0.0, 980.0};
    sim::Ball ball;
    ball.position = {300.0, 100.0};
    ball.velocity = {20.0, -50.0};
    ball.radius = 10.0;
    scene.balls = {ball};
    return scene;
}

// Largest channel difference between two colours.
int colorDistance(QRgb a, QRgb b)
{
    return std::max({std::abs(qRed(a) - qRed(b)), std::abs(qGreen(a) - qGreen(b)), std::abs(qBlue(a) - qBlue(b))});
}

QRgb pixelAt(const QImage& image, QPointF p, double dpr = 1.0)
{
    return image.pixel(static_cast<int>(std::floor(p.x() * dpr)), static_cast<int>(std::floor(p.y() * dpr)));
}

// An enumeration's name as in lesson files, for readable comparisons.
template <class Enum>
QString nameOf(Enum v)
{
    const std::string_view s = sim::toString(v);
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

} // namespace

class GuiTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void viewTransformLetterboxesAndInverts();
    void gravityControlChangesWorldAndFall();
    void refusedEditShowsErrorAndControlReturns();
    void canvasShowsBallsWhereTheWorldSays();
    void spritesAreSharpAtDevicePixelRatioTwo();
    void pointerEventsReachTheWorld();
    void frameLoopTakesWholeStepsAndCapsThem();
    void shortcutsPlayStepAndReset();
    void opensShowcaseAndRemembersLastLesson();
    void damagedSettingsAreNamedAndReplaced();
};

void GuiTest::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("ForceLabTest"));
    QCoreApplication::setApplicationName(QStringLiteral("test_gui"));
    QSettings().clear();
}

void GuiTest::viewTransformLetterboxesAndInverts()
{
    // 600 × 400 in 1000 × 500 with a 10 px margin: height limits, scale 480/400 = 1.2,
    // the box is 720 px wide and centred: left edge at 500 - 360 = 140.
    const ViewTransform t = ViewTransform::fit(sim::BoxSettings{600.0, 400.0}, QRectF(0, 0, 1000, 500), 10.0);
    QCOMPARE(t.scale(), 1.2);
    QCOMPARE(t.boxRect(), QRectF(140.0, 10.0, 720.0, 480.0));
    QCOMPARE(t.toWidget(sim::Vec2(600.0, 400.0)), QPointF(860.0, 490.0));
    const sim::Vec2 p(123.25, 321.5);
    QVERIFY((t.toWorld(t.toWidget(p)) - p).norm() < 1e-12);
    // A tall widget letterboxes top and bottom instead.
    const ViewTransform tall = ViewTransform::fit(sim::BoxSettings{600.0, 400.0}, QRectF(0, 0, 320, 900), 10.0);
    QCOMPARE(tall.scale(), 0.5);
    QCOMPARE(tall.boxRect(), QRectF(10.0, 350.0, 300.0, 200.0));
}

void GuiTest::gravityControlChangesWorldAndFall()
{
    SimulationController controller;
    QVERIFY(!controller.setScene(fallingBall()));
    SettingsEditor editor(&controller);
    ParameterPanel panel(&controller, &editor);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));

    // Type a new value as a user would: select, type, Enter.
    auto* gy = panel.findChild<QDoubleSpinBox*>(QStringLiteral("gravityYSpin"));
    QVERIFY(gy);
    QCOMPARE(gy->value(), 980.0);
    gy->setFocus();
    gy->selectAll();
    QTest::keyClicks(gy, QStringLiteral("500"));
    QTest::keyClick(gy, Qt::Key_Return);
    QCOMPARE(controller.world().settings().gravity.g.y(), 500.0);

    auto* gx = panel.findChild<QDoubleSpinBox*>(QStringLiteral("gravityXSpin"));
    QVERIFY(gx);
    gx->setValue(-120.0);
    QCOMPARE(controller.world().settings().gravity.g.x(), -120.0);

    auto* integrator = panel.findChild<QComboBox*>(QStringLiteral("integratorCombo"));
    QVERIFY(integrator);
    integrator->setCurrentIndex(integrator->findText(QStringLiteral("exact")));
    QCOMPARE(nameOf(controller.world().settings().time.integrator), QStringLiteral("exact"));
    integrator->setCurrentIndex(integrator->findText(QStringLiteral("rk4")));
    QCOMPARE(nameOf(controller.world().settings().time.integrator), QStringLiteral("rk4"));
    integrator->setCurrentIndex(integrator->findText(QStringLiteral("exact")));

    // The fall now follows the new gravity: x = x0 + u t + ½ g t² per axis,
    // exact for the `exact` integrator up to rounding.
    const sim::Vec2 x0 = controller.world().balls().position.col(0);
    const sim::Vec2 u = controller.world().balls().velocity.col(0);
    const sim::Vec2 g(-120.0, 500.0);
    for (int k = 0; k < 30; ++k)
        controller.stepOnce();
    const double t = controller.world().time();
    QVERIFY(std::abs(t - 30.0 / 60.0) < 1e-12);
    const sim::Vec2 expected = x0 + u * t + 0.5 * g * t * t;
    const sim::Vec2 got = controller.world().balls().position.col(0);
    QVERIFY2((got - expected).norm() < 1e-9 * expected.norm(),
             qPrintable(QStringLiteral("got (%1, %2), expected (%3, %4)")
                            .arg(got.x(), 0, 'g', 17).arg(got.y(), 0, 'g', 17)
                            .arg(expected.x(), 0, 'g', 17).arg(expected.y(), 0, 'g', 17)));
    QVERIFY((controller.world().balls().velocity.col(0) - (u + g * t)).norm() < 1e-9 * (u + g * t).norm());

    auto* restitution = panel.findChild<QDoubleSpinBox*>(QStringLiteral("wallRestitutionSpin"));
    QVERIFY(restitution);
    restitution->setValue(0.8);
    QCOMPARE(controller.world().settings().walls.restitution, 0.8);

    auto* dt = panel.findChild<QDoubleSpinBox*>(QStringLiteral("dtSpin"));
    QVERIFY(dt);
    QCOMPARE(dt->suffix(), QStringLiteral(" ms"));
    dt->setValue(5.0);
    QCOMPARE(controller.world().settings().time.dt, 0.005);
}

void GuiTest::refusedEditShowsErrorAndControlReturns()
{
    SimulationController controller;
    QVERIFY(!controller.setScene(fallingBall()));
    SettingsEditor editor(&controller);
    ParameterPanel panel(&controller, &editor);
    QSignalSpy errors(&controller, &SimulationController::errorOccurred);

    auto* drag = panel.findChild<QGroupBox*>(QStringLiteral("dragGroup"));
    auto* k = panel.findChild<QDoubleSpinBox*>(QStringLiteral("dragKSpin"));
    auto* law = panel.findChild<QComboBox*>(QStringLiteral("dragLawCombo"));
    QVERIFY(drag && k && law);
    QVERIFY(!drag->isChecked());
    drag->setChecked(true);
    QVERIFY(controller.world().settings().drag.enabled);
    k->setValue(0.25);
    QCOMPARE(controller.world().settings().drag.k, 0.25);
    QCOMPARE(k->suffix(), QStringLiteral(" 1/s"));
    law->setCurrentIndex(law->findText(QStringLiteral("quadratic")));
    QCOMPARE(nameOf(controller.world().settings().drag.law), QStringLiteral("quadratic"));
    QCOMPARE(k->suffix(), QStringLiteral(" 1/px"));
    QCOMPARE(errors.count(), 0);

    // `exact` needs a constant acceleration; drag is not one. The world
    // refuses the whole struct, the error is signalled, the combo goes back.
    auto* integrator = panel.findChild<QComboBox*>(QStringLiteral("integratorCombo"));
    QVERIFY(integrator);
    const QString before = integrator->currentText();
    const sim::IntegratorKind kindBefore = controller.world().settings().time.integrator;
    integrator->setCurrentIndex(integrator->findText(QStringLiteral("exact")));
    QCOMPARE(errors.count(), 1);
    QVERIFY(errors.first().first().toString().startsWith(QStringLiteral("time.integrator")));
    QCOMPARE(nameOf(controller.world().settings().time.integrator), nameOf(kindBefore));
    QCOMPARE(integrator->currentText(), before);
    QVERIFY(controller.world().settings().drag.enabled);
}

void GuiTest::canvasShowsBallsWhereTheWorldSays()
{
    SimulationController controller;
    QVERIFY(!controller.setScene(threeBalls()));
    Canvas canvas(&controller);
    canvas.resize(900, 500);
    const sim::BallState& balls = controller.world().balls();

    auto check = [&](const QImage& image) {
        QCOMPARE(image.size(), QSize(900, 500));
        for (int i = 0; i < balls.size(); ++i) {
            const QRgb want = balls.color[static_cast<std::size_t>(i)];
            const sim::Vec2 c = balls.position.col(i);
            const double r = balls.radius[i];
            // The centre and four points at 0.8 r are the ball's colour; a point
            // 1.25 r away (3 o'clock) is background.
            for (const sim::Vec2& d : {sim::Vec2(0, 0), sim::Vec2(0.8 * r, 0), sim::Vec2(-0.8 * r, 0),
                                       sim::Vec2(0, 0.8 * r), sim::Vec2(0, -0.8 * r)}) {
                const QRgb got = pixelAt(image, canvas.worldToWidget(c + d));
                QVERIFY2(colorDistance(got, want) <= 2,
                         qPrintable(QStringLiteral("ball %1: %2 at offset (%3, %4), want %5")
                                        .arg(i).arg(got, 8, 16).arg(d.x()).arg(d.y()).arg(want, 6, 16)));
            }
            QCOMPARE(colorDistance(pixelAt(image, canvas.worldToWidget(c + sim::Vec2(1.25 * r, 0))),
                                   canvas_colors::kBackground), 0);
        }
        // Background inside the box, letterbox outside it (box starts at x = 90).
        QCOMPARE(colorDistance(pixelAt(image, canvas.worldToWidget(sim::Vec2(25.0, 375.0))), canvas_colors::kBackground), 0);
        QCOMPARE(colorDistance(image.pixel(40, 250), canvas_colors::kLetterbox), 0);
    };

    // 900 × 500 for a 600 × 400 box: scale 1.2, box at x 90 … 810.
    QCOMPARE(canvas.viewTransform().boxRect(), QRectF(90.0, 10.0, 720.0, 480.0));
    check(canvas.grab().toImage());

    // Move ball 0 while paused: the picture follows the world.
    const sim::Vec2 old = balls.position.col(0);
    controller.mutableWorld().mutableBalls().position.col(0) = sim::Vec2(455.0, 85.0);
    controller.notifyBallsChanged();
    const QImage moved = canvas.grab().toImage();
    check(moved);
    QCOMPARE(colorDistance(pixelAt(moved, canvas.worldToWidget(old)), canvas_colors::kBackground), 0);

    // Colliding balls are drawn in the marked colour when the overlay is on.
    QCOMPARE(balls.colliding.size(), std::size_t{3});
    controller.mutableWorld().mutableBalls().colliding[2] = 1;
    controller.notifyBallsChanged();
    const QPointF c2 = canvas.worldToWidget(balls.position.col(2));
    QCOMPARE(colorDistance(pixelAt(canvas.grab().toImage(), c2), 0x3090d0), 0);
    Overlays overlays = canvas.overlays();
    overlays.colliding = true;
    canvas.setOverlays(overlays);
    canvas.setMarkedColor(QColor(0xff, 0x2a, 0x2a));
    QCOMPARE(colorDistance(pixelAt(canvas.grab().toImage(), c2), qRgb(0xff, 0x2a, 0x2a)), 0);
}

void GuiTest::spritesAreSharpAtDevicePixelRatioTwo()
{
    // A HiDPI screen: the image has twice the pixels of its logical size and
    // ball sprites are made in device pixels.
    SimulationController controller;
    QVERIFY(!controller.setScene(threeBalls()));
    QImage image(1800, 1000, QImage::Format_ARGB32_Premultiplied);
    image.setDevicePixelRatio(2.0);
    WorldPainter painter;
    const QRectF area(0, 0, 900, 500);
    {
        QPainter p(&image);
        painter.paint(p, area, controller.world(), PaintOptions{}, 2.0);
    }
    const ViewTransform view = WorldPainter::view(controller.world(), area);
    const sim::BallState& balls = controller.world().balls();
    for (int i = 0; i < balls.size(); ++i) {
        const sim::Vec2 c = balls.position.col(i);
        const double r = balls.radius[i];
        QCOMPARE(colorDistance(pixelAt(image, view.toWidget(c), 2.0), balls.color[static_cast<std::size_t>(i)]), 0);
        QCOMPARE(colorDistance(pixelAt(image, view.toWidget(c + sim::Vec2(0.85 * r, 0)), 2.0),
                               balls.color[static_cast<std::size_t>(i)]), 0);
        QCOMPARE(colorDistance(pixelAt(image, view.toWidget(c + sim::Vec2(1.1 * r, 0)), 2.0), canvas_colors::kBackground),
                 0);
    }
    // Every sprite was made at ratio 2 (device radius = 2 × 1.2 × r).
    QVERIFY(painter.sprites().size() >= 3);
}

void GuiTest::pointerEventsReachTheWorld()
{
    SimulationController controller;
    sim::Scene scene = threeBalls();
    scene.settings.pointer.enabled = true;
    QVERIFY(!controller.setScene(scene));
    Canvas canvas(&controller);
    canvas.resize(900, 500);
    canvas.show();
    QVERIFY(QTest::qWaitForWindowExposed(&canvas));

    // Widget (400, 250) → world ((400 - 90) / 1.2, (250 - 10) / 1.2).
    QTest::mouseMove(&canvas, QPoint(400, 250));
    sim::PointerInput p = controller.world().pointer();
    QVERIFY(p.inside);
    QVERIFY(!p.pressed);
    QVERIFY((p.position - sim::Vec2(310.0 / 1.2, 200.0)).norm() < 1e-9);

    // Pressing on ball 1 (world (310, 210) → widget (462, 262)) selects and
    // holds it: pointer forces stay off while a ball is in the hand.
    QTest::mousePress(&canvas, Qt::LeftButton, {}, QPoint(462, 262));
    QCOMPARE(canvas.selectedBall(), 1);
    QVERIFY(!controller.world().pointer().inside);
    QTest::mouseRelease(&canvas, Qt::LeftButton, {}, QPoint(462, 262));

    // Pressing on empty space repels from there; releasing goes back to hovering.
    QTest::mousePress(&canvas, Qt::LeftButton, {}, QPoint(400, 250));
    p = controller.world().pointer();
    QVERIFY(p.inside);
    QVERIFY(p.pressed);
    QVERIFY((p.position - sim::Vec2(310.0 / 1.2, 200.0)).norm() < 1e-9);
    QTest::mouseRelease(&canvas, Qt::LeftButton, {}, QPoint(400, 250));
    QVERIFY(controller.world().pointer().inside);
    QVERIFY(!controller.world().pointer().pressed);

    // Leaving the canvas switches pointer forces off.
    QEvent leave(QEvent::Leave);
    QCoreApplication::sendEvent(&canvas, &leave);
    QVERIFY(!controller.world().pointer().inside);
    QVERIFY(!controller.world().pointer().pressed);

    // A press on empty space clears the selection.
    QTest::mousePress(&canvas, Qt::LeftButton, {}, QPoint(700, 100));
    QCOMPARE(canvas.selectedBall(), -1);
    QTest::mouseRelease(&canvas, Qt::LeftButton, {}, QPoint(700, 100));
}

void GuiTest::frameLoopTakesWholeStepsAndCapsThem()
{
    SimulationController controller;
    QVERIFY(!controller.setScene(fallingBall()));
    const double dt = controller.world().settings().time.dt;
    QCOMPARE(dt, 1.0 / 60.0);

    // 0.04 s of real time: two whole steps, 0.04 - 2 dt waits.
    QCOMPARE(controller.advance(0.04), 2);
    QVERIFY(std::abs(controller.accumulator() - (0.04 - 2 * dt)) < 1e-15);
    QCOMPARE(controller.advance(0.02), 1); // 0.00667 + 0.02 = 0.02667 → 1 step
    QCOMPARE(controller.world().stepCount(), std::int64_t{3});

    // Slow motion: half the real time is simulated.
    controller.setTimeScale(0.5);
    const double before = controller.accumulator();
    const int steps = controller.advance(0.1); // before + 0.05
    QCOMPARE(steps, static_cast<int>(std::floor((before + 0.05) / dt)));
    controller.setTimeScale(1.0);

    // The speed does not depend on the frame rate: one second at 144 Hz and
    // at 30 Hz take the same number of steps (60, ± the one waiting in the accumulator).
    for (int hz : {144, 30}) {
        QVERIFY(!controller.setScene(fallingBall()));
        int total = 0;
        for (int f = 0; f < hz; ++f)
            total += controller.advance(1.0 / hz);
        QVERIFY2(std::abs(total - 60) <= 1, qPrintable(QStringLiteral("%1 Hz: %2 steps").arg(hz).arg(total)));
    }

    // A slow frame does not spiral: at most the cap, the rest is dropped and reported.
    QVERIFY(!controller.setScene(fallingBall()));
    controller.setMaxStepsPerFrame(4);
    QSignalSpy dropped(&controller, &SimulationController::timeDropped);
    QCOMPARE(controller.advance(0.5), 4); // wants 30 steps (29.999…: floor is 29 or 30)
    QCOMPARE(dropped.count(), 1);
    const double lost = dropped.first().first().toDouble();
    QVERIFY(lost >= 25 * dt - 1e-12 && lost <= 26 * dt + 1e-12);
    QCOMPARE(controller.droppedTime(), lost);
    QVERIFY(controller.accumulator() < dt);
    QVERIFY(std::abs(controller.world().time() - 4 * dt) < 1e-12);

    // An out-of-range time scale is refused, not clamped.
    QSignalSpy errors(&controller, &SimulationController::errorOccurred);
    controller.setTimeScale(20.0); // above the fastest, 16×
    QCOMPARE(errors.count(), 1);
    QCOMPARE(controller.timeScale(), 1.0);
}

void GuiTest::shortcutsPlayStepAndReset()
{
    MainWindow window;
    Lesson lesson;
    lesson.title = QStringLiteral("Falling ball");
    lesson.scene = fallingBall();
    QVERIFY(window.setLesson(lesson));
    SimulationController* controller = window.controller();
    window.show();
    QVERIFY(QTest::qWaitForWindowActive(&window));
    window.canvas()->setFocus();
    controller->pause();
    QVERIFY(!controller->isTimerActive());

    QTest::keyClick(&window, Qt::Key_Space);
    QVERIFY(controller->isPlaying());
    QVERIFY(controller->isTimerActive());
    QTest::keyClick(&window, Qt::Key_Space);
    QVERIFY(!controller->isPlaying());
    QVERIFY(!controller->isTimerActive());

    // Right arrow: exactly one step of dt, which for semi-implicit Euler is
    // v₁ = v₀ + g dt, x₁ = x₀ + v₁ dt.
    const sim::World& world = controller->world();
    const double dt = world.settings().time.dt;
    const double t0 = world.time();
    const std::int64_t n0 = world.stepCount();
    const sim::Vec2 x0 = world.balls().position.col(0), v0 = world.balls().velocity.col(0);
    QTest::keyClick(&window, Qt::Key_Right);
    QCOMPARE(world.stepCount(), n0 + 1);
    QVERIFY(std::abs(world.time() - (t0 + dt)) < 1e-15);
    const sim::Vec2 v1 = v0 + world.settings().gravity.g * dt;
    QVERIFY((world.balls().velocity.col(0) - v1).norm() < 1e-12);
    QVERIFY((world.balls().position.col(0) - (x0 + v1 * dt)).norm() < 1e-12);

    // Period steps too, and pauses a running simulation first.
    controller->play();
    QTest::keyClick(&window, Qt::Key_Period);
    QVERIFY(!controller->isPlaying());
    QVERIFY(std::abs(world.time() - (t0 + 2 * dt)) < 1e-15);

    // R: back to the lesson's start.
    QTest::keyClick(&window, Qt::Key_R);
    QCOMPARE(world.time(), 0.0);
    QCOMPARE(sim::Vec2(world.balls().position.col(0)), lesson.scene.balls[0].position);

    // Hiding the window stops the timer; showing it again resumes play.
    controller->play();
    QVERIFY(controller->isTimerActive());
    window.hide();
    QVERIFY(!controller->isTimerActive());
    QVERIFY(controller->isPlaying());
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(controller->isTimerActive());
    controller->pause();
}

void GuiTest::opensShowcaseAndRemembersLastLesson()
{
    QSettings().clear();
    const QStringList builtIn = LessonLoader::builtInFiles();
    QVERIFY(!builtIn.isEmpty());
    QString gravitySource;
    {
        // Fresh settings: the first built-in lesson, waiting at t = 0 with
        // the "press Space to run" banner.
        MainWindow window;
        QCOMPARE(window.lesson().source, builtIn.first());
        QCOMPARE(window.controller()->world().balls().size(),
                 sim::buildBalls(window.lesson().scene).size());
        QVERIFY(!window.controller()->isPlaying());
        QCOMPARE(window.controller()->world().time(), 0.0);
        QVERIFY(window.canvas()->showsStartHint());

        // Another lesson: the panel shows its values.
        QVERIFY(window.openLesson(QStringLiteral("gravity")));
        gravitySource = window.lesson().source;
        QVERIFY(gravitySource != builtIn.first());
        auto* gy = window.parameterPanel()->findChild<QDoubleSpinBox*>(QStringLiteral("gravityYSpin"));
        QVERIFY(gy);
        // Lesson 07 speaks SI at 100 px = 1 m: its 980 px/s² shows as 9.8 m/s².
        QCOMPARE(window.lesson().scene.settings.gravity.g.y(), 980.0);
        QCOMPARE(gy->value(), 9.8);

        // A file that does not load: the dialog is shown (closed here) and the lesson goes on.
        const double t = window.controller()->world().time();
        QTimer::singleShot(0, [] {
            if (QWidget* dialog = QApplication::activeModalWidget())
                dialog->close();
        });
        QVERIFY(!window.openLesson(QStringLiteral("/nonexistent/lesson.json")));
        QCOMPARE(window.lesson().source, gravitySource);
        QVERIFY(window.controller()->world().time() >= t);
        window.close(); // writes the settings
    }
    // The next start opens the last lesson.
    MainWindow again;
    QCOMPARE(again.lesson().source, gravitySource);
}

// Saved settings are an input path like any other: a damaged settings file
// (hand-edited, another version) must not stop the start. Each value that does
// not fit is replaced by the default and named, with the file, in one line of
// the status bar.
void GuiTest::damagedSettingsAreNamedAndReplaced()
{
    QSettings().clear();
    {
        QSettings s;
        s.setValue(QStringLiteral("mainWindow/geometry"), QStringLiteral("not a geometry"));
        s.setValue(QStringLiteral("mainWindow/layout2"), QByteArray("\x00\x01garbage", 9));
        s.setValue(QStringLiteral("lesson/last"), QStringLiteral("/nonexistent/last-lesson.json"));
        s.setValue(QStringLiteral("lesson/directory"), QStringLiteral("/nonexistent/folder"));
    }
    const QString file = QSettings().fileName();
    const QStringList builtIn = LessonLoader::builtInFiles();
    QVERIFY(!builtIn.isEmpty());
    {
        MainWindow window;
        // It still starts, on the first lesson, waiting at t = 0.
        QCOMPARE(window.lesson().source, builtIn.first());
        QVERIFY(!window.controller()->isPlaying());
        QVERIFY(window.canvas()->showsStartHint());
        QVERIFY(window.width() > 0 && window.height() > 0);
        const QString message = window.statusBar()->currentMessage();
        QVERIFY2(!message.contains(QLatin1Char('\n')), qPrintable(message));
        for (const QString& part : {QStringLiteral("mainWindow/geometry"), QStringLiteral("mainWindow/layout2"),
                                    QStringLiteral("lesson/last"), QStringLiteral("last-lesson.json"),
                                    QStringLiteral("lesson/directory"), QStringLiteral("/nonexistent/folder"),
                                    QDir::toNativeSeparators(file)})
            QVERIFY2(message.contains(part), qPrintable(QStringLiteral("'%1' not in: %2").arg(part, message)));
        window.close(); // writes good settings over the damaged ones
    }
    // Settings this version wrote load without a word.
    MainWindow again;
    QCOMPARE(again.lesson().source, builtIn.first());
    QVERIFY2(!again.statusBar()->currentMessage().contains(QDir::toNativeSeparators(file)),
             qPrintable(again.statusBar()->currentMessage()));
    QSettings().clear();
}

QTEST_MAIN(GuiTest)
#include "test_gui.moc"
