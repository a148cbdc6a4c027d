// The drawing aids a class switches from the View menu: the momenta inset
// adds up to the world's momentum, the centre of mass is where Σ m x / Σ m
// says, force arrows by source add up to the net force arrow, the arrow
// length menu scales arrows by its factor, and the path layer that is
// appended to each frame gives the picture a whole redraw gives.
// Real widgets, offscreen.
#include "ui/canvas/canvas.h"
#include "ui/docks/force_editor_dock.h"
#include "ui/window/main_window.h"
#include "ui/docks/predict_dock.h"
#include "ui/docks/stopwatch_dock.h"
#include "ui/canvas/simulation_controller.h"
#include "ui/window/theme.h"
#include "ui/drawing/world_painter.h"

#include "lessons/colour_names.h"
#include "lessons/lesson_loader.h"
#include "sim/studies/claims.h"
#include "sim/world/names.h"

#include <QDir>
#include <QImageReader>
#include <QScreen>
#include <QTemporaryDir>

#include <QAction>
#include <QLabel>
#include <QMouseEvent>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QRadioButton>
#include <QPainter>
#include <QStandardPaths>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace forcelab;

namespace {

int colorDistance(QRgb a, QRgb b)
{
    return std::max({std::abs(qRed(a) - qRed(b)), std::abs(qGreen(a) - qGreen(b)), std::abs(qBlue(a) - qBlue(b))});
}

QAction* action(MainWindow& window, const char* name)
{
    return window.findChild<QAction*>(QString::fromLatin1(name));
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

} // namespace

class GuiOverlaysTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void momentaInsetAddsUpToTheTotalMomentum();
    void centreOfMassIsTheMassWeightedMean();
    void forcesBySourceAddUpToTheNetForce();
    void arrowLengthMenuScalesTheArrows();
    void autoArrowsKeepOneScaleThroughARun();
    void pathLayerMatchesAWholeRedraw();
    void projectorThemeDrawsOkabeItoBallsWithOutlines();
    void stageViewAlwaysUsesTheProjectorTheme();
    void pictureIsAsLargeAsTheScreenShowsIt();
    void openDialogStartsInTheLessonsFolder();
    void comparePanesRunTheirOwnWallModels();
    void predictionIsMeasuredByItsClaim();
    void slowPredictionCanBeCancelled();
    void choiceQuestionNamesTheRightAnswer();
    void stopwatchTimesBounceToBounce();
    void rulerMeasuresInWorldPixels();
    void rulerSecondLegMeasuresTheAngle();
    void apexMarksAreTheTopsOfTheFlights();
    void forceEditorKeepsTheLastGoodLaw();
};

void GuiOverlaysTest::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
}

// Lesson 31 after the break: the inset's sum arrow is the total momentum
// (to 1e-9 of its size) and ends where the chain of the balls' arrows ends.
void GuiOverlaysTest::momentaInsetAddsUpToTheTotalMomentum()
{
    MainWindow window(QStringLiteral("break-shot"));
    window.resize(1280, 720);
    QAction* momenta = action(window, "showMomenta");
    QVERIFY(momenta && momenta->isChecked()); // lesson 31 names it
    QVERIFY(window.canvas()->overlays().momenta);
    for (int k = 0; k < 40; ++k)
        window.controller()->stepOnce(); // past the break: every ball moves
    window.canvas()->grab();
    const PaintedFrame& f = window.canvas()->painter().lastFrame();
    const sim::World& world = window.controller()->world();
    QCOMPARE(f.momenta.size(), static_cast<std::size_t>(world.balls().size()));
    const sim::Vec2 total = world.momentum();
    QVERIFY(total.norm() > 0.0);
    QVERIFY((f.momentumSum - total).norm() <= 1e-9 * total.norm());
    QVERIFY(f.momentumScale > 0.0);
    const QPointF drawn = (f.momentumSumArrow.p2() - f.momentumSumArrow.p1()) / f.momentumScale;
    QVERIFY(std::abs(drawn.x() - total.x()) <= 1e-9 * total.norm());
    QVERIFY(std::abs(drawn.y() - total.y()) <= 1e-9 * total.norm());
    QVERIFY(QLineF(f.momentumChainTip, f.momentumSumArrow.p2()).length() < 1e-6);
    // A lesson change brings back the lesson's choice: no inset in lesson 19.
    QVERIFY(window.openLesson(QStringLiteral("two-bodies-in-orbit")));
    QVERIFY(!window.canvas()->overlays().momenta && !momenta->isChecked());
}

// Lesson 19 (Earth and Moon): the path's newest point is Σ m x / Σ m, and
// with no outside force the centre of mass moves at the constant velocity
// P / M (total momentum over total mass): after time t it has moved P t / M,
// to 1e-6 px.
void GuiOverlaysTest::centreOfMassIsTheMassWeightedMean()
{
    MainWindow window(QStringLiteral("two-bodies-in-orbit"));
    QVERIFY(action(window, "showCentreOfMass")->isChecked()); // lesson 19 names it
    const sim::World& world = window.controller()->world();
    const double t0 = world.time();
    for (int k = 0; k < 120; ++k)
        window.controller()->stepOnce();
    const std::vector<sim::Vec2>& path = window.canvas()->centreOfMassPath();
    QVERIFY(path.size() >= 2);
    const sim::BallState& balls = world.balls();
    const double total = balls.mass.sum();
    const sim::Vec2 want = (balls.position * balls.mass.matrix()) / total;
    QVERIFY((path.back() - want).norm() < 1e-9);
    const sim::Vec2 moved = world.momentum() * ((world.time() - t0) / total);
    QVERIFY2((path.back() - path.front() - moved).norm() < 1e-6,
             qPrintable(QStringLiteral("moved %1 px, P t / M = %2 px").arg((path.back() - path.front()).norm()).arg(moved.norm())));
}

// Lesson 18 (a spring and drag): with net and per-source force arrows on,
// every ball gets one arrow per model that is on, in the model's colour, and
// the models' forces add up to the net force m a the net arrow shows.
void GuiOverlaysTest::forcesBySourceAddUpToTheNetForce()
{
    MainWindow window(QStringLiteral("elastic-band"));
    window.resize(1280, 720);
    action(window, "showForces")->trigger();
    action(window, "showForceSources")->trigger();
    for (int k = 0; k < 30; ++k)
        window.controller()->stepOnce();
    const sim::World& world = window.controller()->world();
    const sim::Matrix2X a = world.accelerations();
    for (int i = 0; i < world.balls().size(); ++i) {
        sim::Vec2 sum(0, 0);
        int sources = 0;
        for (const sim::World::SourceAcceleration& s : world.accelerationBySource(i)) {
            sum += s.acceleration;
            ++sources;
        }
        QVERIFY(sources >= 2);
        QVERIFY((sum - sim::Vec2(a.col(i))).norm() <= 1e-9 * (1.0 + a.col(i).norm()));
    }
    const QImage shot = window.canvas()->grab().toImage();
    const QRgb gravity = WorldPainter::sourceColor("spring").rgb();
    int pixels = 0;
    for (int y = 0; y < shot.height(); ++y)
        for (int x = 0; x < shot.width(); ++x)
            pixels += colorDistance(shot.pixel(x, y), gravity) < 30;
    QVERIFY2(pixels > 60, qPrintable(QString::number(pixels)));
    QVERIFY(!window.canvas()->painter().lastFrame().forceLengths.empty());
}

// Off auto, ×2 doubles every net force arrow of ×1 (to rounding).
void GuiOverlaysTest::arrowLengthMenuScalesTheArrows()
{
    MainWindow window(QStringLiteral("drag"));
    window.resize(1280, 720);
    action(window, "showForces")->trigger();
    for (int k = 0; k < 10; ++k)
        window.controller()->stepOnce();
    action(window, "arrowFactor1")->trigger();
    QVERIFY(!action(window, "autoArrows")->isChecked());
    window.canvas()->grab();
    const std::vector<double> one = window.canvas()->painter().lastFrame().forceLengths;
    action(window, "arrowFactor2")->trigger();
    window.canvas()->grab();
    const std::vector<double> two = window.canvas()->painter().lastFrame().forceLengths;
    QCOMPARE(one.size(), two.size());
    QVERIFY(!one.empty());
    for (std::size_t k = 0; k < one.size(); ++k)
        QVERIFY2(std::abs(two[k] - 2.0 * one[k]) < 1e-6 * one[k] + 1e-9, qPrintable(QString::number(two[k] / one[k])));
    action(window, "autoArrows")->trigger();
    window.canvas()->grab();
    const double m = median(window.canvas()->painter().lastFrame().forceLengths);
    QVERIFY2(std::abs(m - WorldPainter::kArrowPixels) < 1.0, qPrintable(QString::number(m)));
}

// Lesson 31 (break shot): the auto scale is fixed once per run, so the
// fastest ball's arrow at 8 s over its arrow at 0.8 s is its speed ratio
// (1 %); the legend says what an arrow stands for; the scale survives a
// Reset and doubles with the teacher's ×2.
void GuiOverlaysTest::autoArrowsKeepOneScaleThroughARun()
{
    MainWindow window(QStringLiteral("break-shot"));
    window.resize(1280, 720);
    Canvas* canvas = window.canvas();
    SimulationController* controller = window.controller();
    Overlays o = canvas->overlays();
    o.velocity = true;
    canvas->setOverlays(o);
    QVERIFY(action(window, "autoArrows")->isChecked());
    canvas->grab();
    const sim::BallState& balls = controller->world().balls();
    const auto fastest = [&] {
        int best = 0;
        for (int i = 1; i < balls.size(); ++i)
            if (balls.velocity.col(i).norm() > balls.velocity.col(best).norm())
                best = i;
        return best;
    };
    while (controller->world().time() < 0.8)
        controller->stepOnce();
    canvas->grab();
    const int early = fastest();
    const double earlySpeed = balls.velocity.col(early).norm();
    const double earlyLength = canvas->painter().lastFrame().velocityLengths.at(static_cast<std::size_t>(early));
    QVERIFY(!canvas->painter().lastFrame().arrowLegend.isEmpty());
    QVERIFY(canvas->painter().lastFrame().arrowLegend.first().contains(QStringLiteral("px/s")));
    while (controller->world().time() < 8.0)
        controller->stepOnce();
    canvas->grab();
    const int late = fastest();
    const double lateSpeed = balls.velocity.col(late).norm();
    const double lateLength = canvas->painter().lastFrame().velocityLengths.at(static_cast<std::size_t>(late));
    qInfo("fastest %.1f px/s → %.1f px arrow at 0.8 s, %.1f px/s → %.1f px at 8 s", earlySpeed, earlyLength,
          lateSpeed, lateLength);
    QVERIFY(lateSpeed < 0.5 * earlySpeed);
    const double ratio = (lateLength / earlyLength) / (lateSpeed / earlySpeed);
    QVERIFY2(std::abs(ratio - 1.0) < 0.01, qPrintable(QString::number(ratio)));
    const double fixed = canvas->arrowRun().velocity;
    QVERIFY(fixed > 0.0);
    controller->reset();
    canvas->grab();
    QCOMPARE(canvas->arrowRun().velocity, fixed);
    action(window, "arrowsLonger")->trigger();
    canvas->grab();
    const std::vector<double> lengths = canvas->painter().lastFrame().velocityLengths;
    const ViewTransform view = canvas->viewTransform();
    const int first = fastest();
    const double expected = view.toWidget(2.0 * fixed * balls.velocity.col(first).norm());
    QVERIFY2(std::abs(lengths.at(static_cast<std::size_t>(first)) - expected) < 1e-6 * expected + 1e-9,
             qPrintable(QString::number(lengths.at(static_cast<std::size_t>(first)) / expected)));
}

// Lesson 09 with its paths: 150 frames appended to the layer without a
// rebuild, and the picture is the one a whole redraw of every path gives.
void GuiOverlaysTest::pathLayerMatchesAWholeRedraw()
{
    MainWindow window(QStringLiteral("bounce-at-the-right-moment"));
    window.resize(1280, 720);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.controller()->setComparePanes({}); // the live run alone fills the canvas
    Canvas* canvas = window.canvas();
    QVERIFY(canvas->overlays().trails);
    int rebuilt = 0;
    for (int frame = 0; frame < 150; ++frame) {
        window.controller()->stepOnce();
        canvas->repaint();
        rebuilt += frame > 0 && canvas->painter().lastFrame().pathLayerRebuilt;
    }
    QCOMPARE(rebuilt, 0); // drawn once, then appended to
    const QImage incremental = canvas->grab().toImage().convertToFormat(QImage::Format_RGB32);
    PaintOptions whole = canvas->paintOptions();
    whole.incrementalPaths = false;
    QImage image(incremental.size(), QImage::Format_ARGB32_Premultiplied);
    image.setDevicePixelRatio(incremental.devicePixelRatio());
    {
        QPainter p(&image);
        WorldPainter painter;
        painter.paint(p, QRectF(canvas->rect()), window.controller()->world(), whole, image.devicePixelRatio());
    }
    image = image.convertToFormat(QImage::Format_RGB32);
    const QRectF box = canvas->viewTransform().boxRect();
    int differ = 0, path = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            differ += colorDistance(image.pixel(x, y), incremental.pixel(x, y)) > 40;
            path += box.contains(x, y) && colorDistance(image.pixel(x, y), canvas_colors::kBackground) > 40;
        }
    QVERIFY(path > 1000); // there are paths to compare
    // Antialiased edges where two appended segments meet may differ a little.
    QVERIFY2(differ <= path / 100, qPrintable(QStringLiteral("%1 of %2 pixels differ").arg(differ).arg(path)));
}

// View > Projector Theme: the box turns white, every ball's centre pixel is
// a listed colour (lessons/colour_names.h), and each ball has a dark outline at its edge.
void GuiOverlaysTest::projectorThemeDrawsOkabeItoBallsWithOutlines()
{
    MainWindow window(QStringLiteral("break-shot"));
    window.resize(1280, 720);
    QAction* theme = action(window, "themeAction");
    QVERIFY(theme && !theme->isChecked());
    Canvas* canvas = window.canvas();
    canvas->setOverlays(Overlays()); // no arrows from the centres
    const QImage plain = canvas->renderImage();
    theme->trigger();
    QVERIFY(canvas->colors().colourBlindSafe);
    const QImage shot = canvas->renderImage();
    QVERIFY(plain != shot);
    const ViewTransform view = canvas->viewTransform();
    const sim::BallState& balls = window.controller()->world().balls();
    const double dpr = shot.devicePixelRatio();
    for (int i = 0; i < balls.size(); ++i) {
        const QPointF c = view.toWidget(sim::Vec2(balls.position.col(i))) * dpr;
        const QRgb centre = shot.pixel(c.toPoint());
        if (std::max({qRed(centre), qGreen(centre), qBlue(centre)}) - std::min({qRed(centre), qGreen(centre), qBlue(centre)}) < 16)
            continue; // the white cue ball stays white
        int nearest = 255;
        for (const lessons::ColourName& k : lessons::colourNames()) // Okabe-Ito, a red and a purple
            nearest = std::min(nearest, colorDistance(centre, k.color | 0xff000000u));
        QVERIFY2(nearest <= 40, qPrintable(QStringLiteral("ball %1 centre #%2").arg(i).arg(centre, 6, 16)));
        // Just inside the edge: the dark outline.
        const QPointF edge = c + QPointF(view.toWidget(balls.radius[i]) * dpr - 1.0, 0.0);
        QVERIFY2(qGray(shot.pixel(edge.toPoint())) < 110,
                 qPrintable(QStringLiteral("ball %1 edge #%2").arg(i).arg(shot.pixel(edge.toPoint()), 6, 16)));
    }
    // Most of the box is its background: white.
    const QRect box = QRectF(view.boxRect().topLeft() * dpr, view.boxRect().size() * dpr).toRect();
    int white = 0;
    for (int y = box.top(); y < box.bottom(); ++y)
        for (int x = box.left(); x < box.right(); ++x)
            white += (shot.pixel(x, y) & 0xffffffu) == 0xffffffu;
    QVERIFY2(white > box.width() * box.height() / 2, qPrintable(QString::number(white)));
    theme->trigger();
    QVERIFY(!canvas->colors().colourBlindSafe);
}

void GuiOverlaysTest::stageViewAlwaysUsesTheProjectorTheme()
{
    MainWindow window(QStringLiteral("break-shot"));
    QVERIFY(!action(window, "themeAction")->isChecked());
    action(window, "presentationAction")->trigger();
    QVERIFY(window.canvas()->colors().colourBlindSafe && window.canvas()->colors().ringMarked);
    action(window, "presentationAction")->trigger();
    QVERIFY(!window.canvas()->colors().colourBlindSafe);
}

// The picture is the stage laid out as large as the screen would show it, at
// the screen's resolution, and twice that for "double size".
void GuiOverlaysTest::pictureIsAsLargeAsTheScreenShowsIt()
{
    MainWindow window(QStringLiteral("gravity"));
    window.resize(1024, 768);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QTemporaryDir dir;
    const QString one = dir.filePath(QStringLiteral("one.png")), two = dir.filePath(QStringLiteral("two.png"));
    QVERIFY(window.saveScreenshotTo(one, 1.0));
    QVERIFY(window.saveScreenshotTo(two, 2.0));
    const QSize a = QImageReader(one).size(), b = QImageReader(two).size();
    const QSize screen = window.screen()->size() * window.screen()->devicePixelRatio();
    const QSize canvas = window.canvas()->size();
    QVERIFY2(a.width() > canvas.width() || a.height() > canvas.height(),
             qPrintable(QStringLiteral("%1x%2 from a %3x%4 canvas").arg(a.width()).arg(a.height()).arg(canvas.width()).arg(canvas.height())));
    QVERIFY(a.width() == screen.width() || a.height() == screen.height()); // grown until it meets the screen's edge
    QCOMPARE(b, a * 2);
}

void GuiOverlaysTest::openDialogStartsInTheLessonsFolder()
{
    const QDir folder(MainWindow::lessonsFolder());
    QVERIFY(folder.exists(QStringLiteral("07-gravity.json")));
}

// Lesson 09 shows its three wall models side by side: each pane's world is
// bit for bit the lesson run on its own with the pane's wall model, a live
// change (gravity) reaches the panes but not their own setting, and the
// three runs are drawn in three areas that do not overlap.
void GuiOverlaysTest::comparePanesRunTheirOwnWallModels()
{
    MainWindow window(QStringLiteral("bounce-at-the-right-moment"));
    window.resize(1280, 720);
    const auto& panes = window.controller()->comparePanes();
    QCOMPARE(panes.size(), std::size_t{2});
    QCOMPARE(panes[0].label, QStringLiteral("mirror"));
    QCOMPARE(panes[1].label, QStringLiteral("exact"));
    for (int k = 0; k < 120; ++k)
        window.controller()->stepOnce();
    const LoadResult lesson = LessonLoader::load(QStringLiteral("bounce-at-the-right-moment"));
    QVERIFY(lesson.ok());
    for (const char* model : {"mirror", "exact"}) {
        sim::Scene scene = lesson.lesson->scene;
        scene.settings.walls.model = *sim::parseWallModel(model);
        sim::World alone(scene);
        for (int k = 0; k < 120; ++k)
            alone.step();
        const sim::World& pane = *panes[std::string_view(model) == "mirror" ? 0 : 1].world;
        QCOMPARE(pane.time(), alone.time());
        QVERIFY(pane.balls().position == alone.balls().position);
        QVERIFY(pane.balls().velocity == alone.balls().velocity);
    }
    // The live run (clamp) has grouped the balls; exact keeps the row apart.
    QVERIFY(!(window.controller()->world().balls().position == panes[1].world->balls().position));
    sim::WorldSettings s = window.controller()->world().settings();
    s.gravity.g.y() = 500;
    QVERIFY(window.controller()->setSettings(s));
    for (const auto& pane : panes) {
        QCOMPARE(pane.world->settings().gravity.g.y(), 500.0);
        QVERIFY(pane.world->settings().walls.model != sim::WallModel::Clamp);
    }
    const QList<QRectF> areas = window.canvas()->paneAreas(QRectF(window.canvas()->rect()));
    QCOMPARE(areas.size(), 3);
    for (qsizetype a = 0; a < areas.size(); ++a)
        for (qsizetype b = a + 1; b < areas.size(); ++b)
            QVERIFY(!areas[a].intersects(areas[b]));
    QVERIFY(areas[0].contains(window.canvas()->viewTransform().boxRect()));
    // In two rows, the third pane is centred under the first two.
    if (areas[2].top() > areas[0].top())
        QVERIFY(std::abs(areas[2].center().x() - window.canvas()->rect().width() / 2.0) < 1e-9);
    // A ball added by hand is added to every pane: they start again from the edited balls.
    const int before = window.controller()->world().balls().size();
    window.canvas()->addBall();
    QCOMPARE(window.controller()->world().balls().size(), before + 1);
    for (const auto& pane : panes) {
        QCOMPARE(pane.world->balls().size(), before + 1);
        QVERIFY(pane.world->balls().position == window.controller()->world().balls().position);
    }
    // The next lesson has no panes.
    QVERIFY(window.openLesson(QStringLiteral("random-acceleration")));
    QVERIFY(window.controller()->comparePanes().empty());
}

// Lesson 08 asks how high the red ball rises after its first bounce: the
// student types 200, the lesson runs, and at the claim's time the dock shows
// the claim's own measurement (bit for bit sim::checkClaim's).
void GuiOverlaysTest::predictionIsMeasuredByItsClaim()
{
    MainWindow window(QStringLiteral("losing-energy"));
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    auto* dock = window.findChild<PredictDock*>(QStringLiteral("predictDock"));
    QVERIFY(dock && dock->hasQuestions());
    auto* number = dock->findChild<QLineEdit*>(QStringLiteral("predictNumber"));
    QVERIFY(number && number->isEnabled());
    QTest::keyClicks(number, QStringLiteral("200"));
    QTest::mouseClick(dock->findChild<QPushButton*>(QStringLiteral("predictRun")), Qt::LeftButton);
    // The answer is measured on a worker; the lesson runs when it is known.
    QTRY_VERIFY(window.controller()->isPlaying());
    QCOMPARE(dock->predicted().value_or(-1), 200.0);
    QVERIFY(!dock->revealed());
    window.controller()->pause();
    const LoadResult lesson = LessonLoader::load(QStringLiteral("losing-energy"));
    const sim::ClaimResult want = sim::checkClaim(lesson.lesson->scene, lesson.lesson->claims[0]);
    QCOMPARE(dock->measured().value_or(-1), want.measured);
    while (window.controller()->world().time() < lesson.lesson->claims[0].at - 1e-9)
        window.controller()->stepOnce();
    QVERIFY(dock->revealed());
    const QString shown = dock->findChild<QLabel*>(QStringLiteral("predictResult"))->text();
    QVERIFY2(shown.contains(QStringLiteral("You said <b>200 px</b>")), qPrintable(shown));
    QVERIFY2(shown.contains(QString::number(want.measured, 'g', 5)), qPrintable(shown));
    // In a student's words: the lesson's sentence, not the measurement
    // table's rule ("the ball's height … at its n-th highest point").
    QVERIFY2(shown.contains(QString::fromStdString(lesson.lesson->claims[0].text).toHtmlEscaped()), qPrintable(shown));
    QVERIFY2(!shown.contains(QStringLiteral("n-th")) && !shown.contains(QLatin1Char('`')) &&
                 !shown.contains(QStringLiteral("claim")),
             qPrintable(shown));
    // A reset asks again.
    window.controller()->reset();
    QVERIFY(!dock->predicted() && number->isEnabled());
}

// A question whose claim takes long (a million sub-steps) is measured on a
// worker thread: the window keeps answering, the progress bar moves, and
// Cancel asks the question again without running the lesson.
void GuiOverlaysTest::slowPredictionCanBeCancelled()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("slow.json"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({"format": 1, "id": "slow", "time": {"dt": 0.00001}, "spawn": {"count": 40},
        "models": {"collisions": {"response": "flag", "detection": "brute"}},
        "claims": [{"says": "s", "measure": "speed", "at": 10, "below": 1e9}],
        "predict": [{"ask": "How fast?", "claim": 0}]})");
    file.close();
    MainWindow window(path);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    auto* dock = window.findChild<PredictDock*>(QStringLiteral("predictDock"));
    QVERIFY(dock && dock->hasQuestions());
    auto* number = dock->findChild<QLineEdit*>(QStringLiteral("predictNumber"));
    auto* progress = dock->findChild<QProgressBar*>(QStringLiteral("predictProgress"));
    auto* cancel = dock->findChild<QPushButton*>(QStringLiteral("predictCancel"));
    QVERIFY(number && progress && cancel && !progress->isVisible());
    QTest::keyClicks(number, QStringLiteral("5"));
    QTest::mouseClick(dock->findChild<QPushButton*>(QStringLiteral("predictRun")), Qt::LeftButton);
    QVERIFY(dock->measuring() && progress->isVisible() && cancel->isVisible() && !number->isEnabled());
    QTRY_VERIFY(progress->value() > 0); // the event loop runs while the worker measures
    QTest::mouseClick(cancel, Qt::LeftButton);
    QTRY_VERIFY(!dock->measuring());
    QTRY_VERIFY(!progress->isVisible());
    QVERIFY(!dock->predicted() && !dock->measured() && number->isEnabled());
    QVERIFY(!window.controller()->isPlaying());
    QVERIFY(dock->findChild<QLabel*>(QStringLiteral("predictResult"))->text().startsWith(QStringLiteral("Cancelled")));
}

// Lesson 09's question is a choice: clamp with e = 1 lifts the red ball
// above its 330 px drop, and the dock names "higher" as the answer.
void GuiOverlaysTest::choiceQuestionNamesTheRightAnswer()
{
    MainWindow window(QStringLiteral("bounce-at-the-right-moment"));
    auto* dock = window.findChild<PredictDock*>(QStringLiteral("predictDock"));
    QVERIFY(dock && dock->hasQuestions());
    auto* exactly = dock->findChild<QRadioButton*>(QStringLiteral("predictChoice1"));
    QVERIFY(exactly);
    exactly->setChecked(true);
    dock->lockIn();
    QTRY_VERIFY(dock->measured().has_value());
    window.controller()->pause();
    dock->reveal();
    const QString shown = dock->findChild<QLabel*>(QStringLiteral("predictResult"))->text();
    QVERIFY2(shown.contains(QStringLiteral("the answer is <b>higher than 330 px</b>")), qPrintable(shown));
    QVERIFY(dock->measured().value_or(0) > 330.0);
}

// Lesson 07 with exact walls and e = 1: the stopwatch armed on ball 0's
// bounce and stopped at the next one reads 2 v0 / g, v0 = √(2 g h), to a step.
void GuiOverlaysTest::stopwatchTimesBounceToBounce()
{
    MainWindow window(QStringLiteral("gravity"));
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    SimulationController* controller = window.controller();
    controller->pause();
    sim::WorldSettings s = controller->world().settings();
    s.walls.model = sim::WallModel::Exact;
    s.walls.restitution = 1.0;
    QVERIFY(controller->setSettings(s));
    auto* watch = window.findChild<StopwatchDock*>(QStringLiteral("stopwatchDock"));
    QVERIFY(watch);
    watch->setStartOn(StopwatchDock::StartOn::Event);
    watch->setStopOn(StopwatchDock::StopOn::Events, 1);
    watch->setEvent(sim::EventKind::Bounce, 0);
    watch->show();
    watch->raise();
    QTest::mouseClick(watch->findChild<QPushButton*>(QStringLiteral("stopwatchStartStop")), Qt::LeftButton);
    QCOMPARE(watch->state(), StopwatchDock::State::Armed);
    const sim::BallState& b = controller->world().balls();
    const double g = s.gravity.g.y(), h = (s.box.height - b.radius[0]) - b.position(1, 0);
    const double want = 2.0 * std::sqrt(2.0 * g * h) / g;
    for (int k = 0; k < 2000 && watch->state() != StopwatchDock::State::Stopped; ++k)
        controller->stepOnce();
    QCOMPARE(watch->state(), StopwatchDock::State::Stopped);
    qInfo("bounce to bounce: %.4f s, 2 v0 / g = %.4f s", watch->elapsed(), want);
    QVERIFY(std::abs(watch->elapsed() - want) <= s.time.dt);
    QVERIFY(watch->findChild<QLabel*>(QStringLiteral("stopwatchTime"))->text().startsWith(QString::number(watch->elapsed(), 'f', 3)));

    // Lesson 19's challenge, done as it says: the Moon crossing y = 250,
    // started on the event and stopped after 2 more, is one orbit: 6.21 s.
    QVERIFY(window.openLesson(QStringLiteral("two-bodies-in-orbit")));
    controller->pause();
    watch->setStartOn(StopwatchDock::StartOn::Event);
    watch->setStopOn(StopwatchDock::StopOn::Events, 2);
    watch->setEvent(sim::EventKind::CrossY, 1, 250.0);
    watch->startOrStop();
    for (int k = 0; k < 5000 && watch->state() != StopwatchDock::State::Stopped; ++k)
        controller->stepOnce();
    QCOMPARE(watch->state(), StopwatchDock::State::Stopped);
    qInfo("lesson 19, one orbit: %.3f s", watch->elapsed());
    QVERIFY(std::abs(watch->elapsed() - 6.21) < 0.01 * 6.21);
}

// Shift + drag: the ruler's length is the world distance between the two
// points, measuring leaves every ball as it was, and Reset clears it.
void GuiOverlaysTest::rulerMeasuresInWorldPixels()
{
    MainWindow window(QStringLiteral("gravity"));
    window.resize(1280, 720);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    Canvas* canvas = window.canvas();
    const sim::Matrix2X before = window.controller()->world().balls().position;
    const QPoint a = canvas->worldToWidget(sim::Vec2(100, 350)).toPoint();
    const QPoint b = canvas->worldToWidget(sim::Vec2(400, 150)).toPoint();
    QTest::mousePress(canvas, Qt::LeftButton, Qt::ShiftModifier, a);
    QMouseEvent move(QEvent::MouseMove, QPointF(b), canvas->mapToGlobal(QPointF(b)), Qt::NoButton, Qt::LeftButton,
                     Qt::ShiftModifier);
    QCoreApplication::sendEvent(canvas, &move);
    QTest::mouseRelease(canvas, Qt::LeftButton, Qt::ShiftModifier, b);
    const Canvas::Ruler& r = canvas->ruler();
    QVERIFY(r.shown);
    const double want = (canvas->widgetToWorld(QPointF(b)) - canvas->widgetToWorld(QPointF(a))).norm();
    QVERIFY(std::abs(r.length() - want) < 1e-9);
    QVERIFY(std::abs(r.length() - 360.555) < 2.0); // 300 by 200 px, to the widget's pixel
    QVERIFY(std::abs(r.angle() - 33.69) < 1.0);
    QVERIFY(window.controller()->world().balls().position == before);
    QTest::mouseClick(canvas, Qt::LeftButton, Qt::NoModifier, canvas->worldToWidget(sim::Vec2(580, 20)).toPoint());
    QVERIFY(!canvas->ruler().shown);
    // Reset takes the ruler away with the scene it measured.
    QTest::mousePress(canvas, Qt::LeftButton, Qt::ShiftModifier, a);
    QCoreApplication::sendEvent(canvas, &move);
    QTest::mouseRelease(canvas, Qt::LeftButton, Qt::ShiftModifier, b);
    QVERIFY(canvas->ruler().shown);
    window.controller()->reset();
    QVERIFY(!canvas->ruler().shown);
}

// The ruler's second leg (issue #36): closed forms for the lengths and the
// angle between the legs, then the gesture: Shift + drag from an end of the
// line draws the second leg from that exact end, and one from elsewhere
// starts a fresh ruler.
void GuiOverlaysTest::rulerSecondLegMeasuresTheAngle()
{
    const auto ruler = [](sim::Vec2 from, sim::Vec2 to, bool fromStart, sim::Vec2 end) {
        Canvas::Ruler r;
        r.shown = r.hasSecond = true;
        r.from = from;
        r.to = to;
        r.secondFromStart = fromStart;
        r.end = end;
        return r;
    };
    // Right angle: 300 px along x, 400 px up, from the shared start.
    Canvas::Ruler r = ruler({0, 0}, {300, 0}, true, {0, -400});
    QVERIFY(std::abs(r.length() - 300.0) < 1e-9);
    QVERIFY(std::abs(r.secondLength() - 400.0) < 1e-9);
    QVERIFY(std::abs(r.between() - 90.0) < 1e-9);
    // 3-4-5 from the far end: the hypotenuse back to the start is 500 px, and
    // the angle at the shared end is atan(300 / 400).
    r = ruler({0, 0}, {400, 0}, false, {0, 300});
    QVERIFY(std::abs(r.secondLength() - 500.0) < 1e-9);
    QVERIFY(std::abs(r.between() - std::atan(300.0 / 400.0) * 180.0 / std::numbers::pi) < 1e-9);
    QVERIFY(std::abs(r.between() - 36.86989764584402) < 1e-9);
    // 60°: two legs of 200 px, an equilateral triangle's corner.
    r = ruler({0, 0}, {200, 0}, true, {100, -100 * std::sqrt(3.0)});
    QVERIFY(std::abs(r.secondLength() - 200.0) < 1e-9);
    QVERIFY(std::abs(r.between() - 60.0) < 1e-9);
    // Straight on and straight back.
    QVERIFY(std::abs(ruler({0, 0}, {100, 0}, false, {250, 0}).between() - 180.0) < 1e-9);
    QVERIFY(std::abs(ruler({0, 0}, {100, 0}, false, {0, 0}).between()) < 1e-9);

    MainWindow window(QStringLiteral("gravity"));
    window.resize(1280, 720);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    Canvas* canvas = window.canvas();
    const auto shiftDrag = [&](QPoint from, QPoint to) {
        QTest::mousePress(canvas, Qt::LeftButton, Qt::ShiftModifier, from);
        QMouseEvent move(QEvent::MouseMove, QPointF(to), canvas->mapToGlobal(QPointF(to)), Qt::NoButton,
                         Qt::LeftButton, Qt::ShiftModifier);
        QCoreApplication::sendEvent(canvas, &move);
        QTest::mouseRelease(canvas, Qt::LeftButton, Qt::ShiftModifier, to);
    };
    const QPoint a = canvas->worldToWidget(sim::Vec2(100, 350)).toPoint();
    const QPoint b = canvas->worldToWidget(sim::Vec2(400, 350)).toPoint();
    const QPoint c = canvas->worldToWidget(sim::Vec2(100, 50)).toPoint();
    shiftDrag(a, b);
    QVERIFY(canvas->ruler().shown && !canvas->ruler().hasSecond);
    const QImage one = canvas->grab().toImage();
    // From a few pixels off the first leg's start: the second leg starts at
    // that start exactly.
    shiftDrag(a + QPoint(4, -3), c);
    const Canvas::Ruler& two = canvas->ruler();
    QVERIFY(two.hasSecond && two.secondFromStart);
    QCOMPARE(two.pivot(), canvas->widgetToWorld(QPointF(a)));
    const sim::Vec2 u = canvas->widgetToWorld(QPointF(b)) - two.pivot();
    const sim::Vec2 v = canvas->widgetToWorld(QPointF(c)) - two.pivot();
    QVERIFY(std::abs(two.secondLength() - v.norm()) < 1e-9);
    QVERIFY(std::abs(two.between() - std::acos(u.dot(v) / (u.norm() * v.norm())) * 180.0 / std::numbers::pi) < 1e-9);
    QVERIFY2(std::abs(two.between() - 90.0) < 1.0, qPrintable(QString::number(two.between()))); // to the pixel
    QVERIFY(canvas->grab().toImage() != one); // the second leg, its arc and its numbers are drawn
    if (qEnvironmentVariableIsSet("SHOTS"))
        canvas->grab().save(QStringLiteral("/tmp/ruler_two_legs.png"));
    // A Shift + drag elsewhere starts a fresh ruler.
    shiftDrag(canvas->worldToWidget(sim::Vec2(300, 200)).toPoint(), c);
    QVERIFY(canvas->ruler().shown && !canvas->ruler().hasSecond);
    // Reset takes both legs away.
    shiftDrag(c + QPoint(2, 2), b);
    QVERIFY(canvas->ruler().hasSecond && !canvas->ruler().secondFromStart);
    window.controller()->reset();
    QVERIFY(!canvas->ruler().shown && !canvas->ruler().hasSecond);
}

// Lesson 08 marks the top of each flight: the red ball's first mark is the
// highest point it reached after its first bounce, to the step's resolution.
void GuiOverlaysTest::apexMarksAreTheTopsOfTheFlights()
{
    MainWindow window(QStringLiteral("losing-energy"));
    QVERIFY(window.canvas()->overlays().apexes);
    SimulationController* controller = window.controller();
    double lowestY = 1e9;
    bool bounced = false;
    double previousVy = 0.0;
    while (controller->world().time() < 2.0) {
        controller->stepOnce();
        const double y = controller->world().balls().position(1, 0), vy = controller->world().balls().velocity(1, 0);
        if (previousVy > 0.0 && vy < 0.0)
            bounced = true;
        if (bounced && window.canvas()->apexes().empty())
            lowestY = std::min(lowestY, y);
        previousVy = vy;
    }
    QVERIFY(!window.canvas()->apexes().empty());
    const ApexMark first = window.canvas()->apexes().front();
    QVERIFY2(std::abs(first.centre.y() - lowestY) < 1.0,
             qPrintable(QStringLiteral("%1 vs %2").arg(first.centre.y()).arg(lowestY)));
    // The label is the height the text talks about: 330 px of fall, about
    // 211 px of rise (the claim's own measurement, to a step's resolution).
    const double rise = (400.0 - first.radius) - first.centre.y();
    QVERIFY2(std::abs(rise - 211.2) < 0.05 * 211.2, qPrintable(QString::number(rise)));
}

// Lesson 41's Force editor: a formula with an unknown name is refused with
// its column under the field and the world keeps its law; a good one runs,
// and Undo brings the old one back.
void GuiOverlaysTest::forceEditorKeepsTheLastGoodLaw()
{
    MainWindow window(QStringLiteral("write-your-own-force"));
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    auto* editor = window.findChild<ForceEditorDock*>(QStringLiteral("forceEditorDock"));
    QVERIFY(editor);
    editor->show();
    editor->raise();
    auto* fx = editor->findChild<QLineEdit*>(QStringLiteral("customFx"));
    QVERIFY(fx);
    const std::string law = window.controller()->world().settings().custom.fx;
    QCOMPARE(QString::fromStdString(law), fx->text());
    fx->setFocus();
    fx->selectAll();
    QTest::keyClicks(fx, QStringLiteral("-kk*x"));
    QTest::keyClick(fx, Qt::Key_Return);
    QVERIFY2(editor->problem(QStringLiteral("fx")).startsWith(QStringLiteral("column 2: unknown name \"kk\"")),
             qPrintable(editor->problem(QStringLiteral("fx"))));
    QCOMPARE(window.controller()->world().settings().custom.fx, law);
    // A new law with the old potential is refused at U: −∇U no longer fits F.
    fx->selectAll();
    QTest::keyClicks(fx, QStringLiteral("-k*m*(x - 250)"));
    QTest::keyClick(fx, Qt::Key_Return);
    QVERIFY(editor->problem(QStringLiteral("fx")).isEmpty());
    QVERIFY(editor->problem(QStringLiteral("potential")).contains(QStringLiteral("not the potential")));
    QCOMPARE(window.controller()->world().settings().custom.fx, law);
    auto* u = editor->findChild<QLineEdit*>(QStringLiteral("customPotential"));
    u->setFocus();
    u->selectAll();
    QTest::keyClicks(u, QStringLiteral("0.5*k*m*((x - 250)^2 + (y - 200)^2)"));
    QTest::keyClick(u, Qt::Key_Return);
    QVERIFY(editor->problem(QStringLiteral("potential")).isEmpty());
    QCOMPARE(window.controller()->world().settings().custom.fx, std::string("-k*m*(x - 250)"));
    // The anchor moved to x = 250: the red ball at x = 450 is pulled 4 × 200 px/s² to the left.
    const sim::Matrix2X a = window.controller()->world().accelerations();
    QVERIFY(std::abs(a(0, 0) + 800.0) < 1e-9);
    window.findChild<QAction*>(QStringLiteral("undoAction"))->trigger(); // one step: both fields
    QCOMPARE(window.controller()->world().settings().custom.fx, law);
    QCOMPARE(fx->text(), QString::fromStdString(law));
}

QTEST_MAIN(GuiOverlaysTest)
#include "test_gui_overlays.moc"
