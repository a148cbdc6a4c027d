// The stage view for a projector: at 1024×768, 1280×720 and 1920×1080 the
// simulation fills at least 80% of the window, with the lesson's title and
// challenge as a caption and large transport buttons beside or under it;
// Escape leaves it and gives back the docks. In the normal layout the
// readouts never cover the box, and opening a dock does not shrink it.

#include "gui_settle.h"
#include "ui/canvas/canvas.h"
#include "ui/window/language.h"
#include "ui/window/main_window.h"
#include "ui/controls/number_control.h"
#include "ui/stage/stage_sliders.h"
#include "ui/controls/settings_editor.h"
#include "lessons/lesson_controls.h"
#include "ui/canvas/simulation_controller.h"
#include "ui/stage/stage_bar.h"
#include "ui/stage/stage_view.h"
#include "ui/drawing/world_painter.h"

#include "lessons/lesson_loader.h"
#include "lessons/lesson_tools.h"
#include "ui/stage/arrow_legend_view.h"
#include "ui/drawing/display_units.h"
#include "sim/world/parameters.h"

#include <QAction>
#include <QApplication>
#include <QScopeGuard>
#include <QComboBox>
#include <QDockWidget>
#include <QFileInfo>
#include <QFontInfo>
#include <QFontMetrics>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollArea>
#include <QSettings>
#include <QStandardPaths>
#include <QTest>
#include <QToolButton>

#include <algorithm>
#include <vector>

using namespace forcelab;

class GuiStageTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }
    void stageFillsTheScreen_data();
    void stageFillsTheScreen();
    void quittingFromTheStageKeepsTheNormalLayout();
    void showMenuTogglesWhatIsDrawn();
    void autoArrowsAreReadable_data();
    void autoArrowsAreReadable();
    void arrowLegendIsInTheBarOffTheBox_data();
    void arrowLegendIsInTheBarOffTheBox();
    void stageSlidersEditTheWorld();
    void everyListedRowHasAStageControl();
    void stageSwitchesAndChoicesEditTheWorld();
    void stageWallSidesOpenAWall();
    void normalLayoutGivesTheBoxHalfTheWindow_data();
    void normalLayoutGivesTheBoxHalfTheWindow();
    void stageTextIsNeverCut_data();
    void stageTextIsNeverCut();
    void tooLongAChallengeEndsInAnEllipsis();
    void rowReadoutUsesTextColumns();
    void slidersButtonShowsARowBarsSliders();
    void stageAlwaysShowsTheClockAndTheSpeed();
    void stageKeysAreTheNormalLayoutsKeys();
    void textSizeKeysScaleEveryTextAndAreRemembered();
    void everyLessonToolWorksOnTheStage_data();
    void everyLessonToolWorksOnTheStage();
};

namespace {

// Shows the window, turns the stage view on and gives the window `size`,
// whatever the test screen is; false if any of it did not happen.
bool presentAt(MainWindow& window, QSize size)
{
    window.show();
    auto* stage = window.findChild<QAction*>(QStringLiteral("presentationAction"));
    if (!QTest::qWaitForWindowExposed(&window) || !stage)
        return false;
    stage->setChecked(true);
    window.showNormal();
    window.setGeometry(QRect(QPoint(0, 0), size));
    return QTest::qWaitFor([&] { return window.size() == size; });
}

// A projector's sizes: 4:3 and 16:9, and full HD when asked.
/// What a QToolButton's style keeps free beside its text (Fusion: a frame
/// and a margin on each side).
constexpr int kButtonTextMargin = 6;

void addProjectorSizes(bool fullHd)
{
    QTest::addColumn<QSize>("size");
    QTest::newRow("1024x768") << QSize(1024, 768);
    QTest::newRow("1280x720") << QSize(1280, 720);
    if (fullHd)
        QTest::newRow("1920x1080") << QSize(1920, 1080);
}

} // namespace

void GuiStageTest::stageFillsTheScreen_data()
{
    addProjectorSizes(true);
}

void GuiStageTest::stageFillsTheScreen()
{
    QFETCH(QSize, size);
    MainWindow window(QStringLiteral("gravity"));
    QVERIFY(presentAt(window, size));
    QAction* stage = window.findChild<QAction*>(QStringLiteral("presentationAction"));
    QVERIFY(test::waitForSettledLayout(&window));

    const double windowArea = double(size.width()) * size.height();
    Canvas* canvas = window.canvas();
    const QRectF box = canvas->viewTransform().boxRect();
    const double boxShare = box.width() * box.height() / windowArea;
    qInfo("%dx%d: the box takes %.1f%% of the window (%.0f x %.0f px)", size.width(), size.height(), 100 * boxShare,
          box.width(), box.height());
    // The bar takes at most a quarter of the height under the box (what the
    // challenge and the readout need at 2.4% of the height), or a strip
    // beside it: the box keeps three quarters of the height at least.
    QVERIFY2(box.height() >= 0.75 * size.height() - 12, qPrintable(QString::number(box.height())));
    // The area: 71.9% at 1024×768 before the arrow legend moved from a card
    // over the box's corner into the bar (under the buttons); 63% since.
    QVERIFY2(boxShare >= 0.62, qPrintable(QString::number(boxShare)));
    QVERIFY(!window.menuBar()->isVisible());
    for (QDockWidget* dock : window.findChildren<QDockWidget*>())
        QVERIFY2(!dock->isVisible(), qPrintable(dock->objectName()));
    // The caption and the big buttons.
    auto* title = window.findChild<QLabel*>(QStringLiteral("stageTitle"));
    QVERIFY(title && title->isVisible());
    // The lesson's readout moved into the bar, filled in at once (paused at t = 0),
    // and off the canvas.
    auto* readout = window.findChild<QLabel*>(QStringLiteral("stageReadout"));
    QVERIFY(readout && readout->isVisible());
    QVERIFY2(readout->text().contains(QStringLiteral("ball 0")), qPrintable(readout->text()));
    QVERIFY(!window.canvas()->overlays().readout);
    QCOMPARE(title->text(), window.lesson().title);
    // Play, Step, Reset, Slower, Faster, Balls (and Sliders, when the
    // lesson's sliders do not fit the bar).
    auto* slidersAction = window.findChild<QAction*>(QStringLiteral("stageSlidersAction"));
    QList<QToolButton*> buttons;
    for (QToolButton* b : window.findChild<QWidget*>(QStringLiteral("stageBar"))->findChildren<QToolButton*>())
        if (b->defaultAction() != slidersAction)
            buttons << b;
    QCOMPARE(buttons.size(), 6);
    for (QToolButton* b : buttons)
        QVERIFY(b->isVisible() && b->height() >= 56);
    // Run from the stage bar.
    QVERIFY(!window.controller()->isPlaying());
    buttons.first()->click();
    QVERIFY(window.controller()->isPlaying());
    window.controller()->pause();

    // Escape leaves: the docks and menus are back.
    QTest::keyClick(&window, Qt::Key_Escape);
    QVERIFY(!stage->isChecked());
    QVERIFY(window.menuBar()->isVisible());
    QVERIFY(!window.findChild<QWidget*>(QStringLiteral("stageBar"))->isVisible());
}

// Quitting in the stage view: the next start has its docks, menus and toolbars.
void GuiStageTest::quittingFromTheStageKeepsTheNormalLayout()
{
    {
        MainWindow window(QStringLiteral("gravity"));
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.findChild<QAction*>(QStringLiteral("presentationAction"))->setChecked(true);
        window.close(); // saves the settings
    }
    MainWindow again(QStringLiteral("gravity"));
    again.show();
    QVERIFY(QTest::qWaitForWindowExposed(&again));
    QVERIFY(again.menuBar()->isVisible());
    QVERIFY(again.findChild<QDockWidget*>(QStringLiteral("parametersDock"))->isVisible());
    QVERIFY(again.findChild<QDockWidget*>(QStringLiteral("lessonsDock"))->isVisible());
}

namespace {

// Pixels of the velocity arrows' green in a picture of the canvas.
int velocityPixels(Canvas* canvas)
{
    const QImage image = canvas->renderImage();
    int n = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            n += image.pixel(x, y) == canvas_colors::kVelocity ? 1 : 0;
    return n;
}

} // namespace

// The View menu's Show actions switch what the stage draws; a lesson change
// brings back the lesson's own choice.
void GuiStageTest::showMenuTogglesWhatIsDrawn()
{
    MainWindow window(QStringLiteral("the-line-of-impact")); // lesson 29 draws velocity arrows
    QAction* velocity = window.findChild<QAction*>(QStringLiteral("showVelocity"));
    QVERIFY(velocity && velocity->isChecked());
    window.canvas()->resize(800, 560);
    QVERIFY(velocityPixels(window.canvas()) > 50);
    velocity->setChecked(false);
    QVERIFY(!window.canvas()->overlays().velocity);
    QCOMPARE(velocityPixels(window.canvas()), 0);
    QAction* trails = window.findChild<QAction*>(QStringLiteral("showTrails"));
    trails->setChecked(true);
    QVERIFY(window.canvas()->overlays().trails);
    QVERIFY(window.openLesson(QStringLiteral("gravity")));
    QVERIFY(window.openLesson(QStringLiteral("the-line-of-impact")));
    QVERIFY(velocity->isChecked() && window.canvas()->overlays().velocity);
    QCOMPARE(trails->isChecked(), window.canvas()->overlays().trails);
}

void GuiStageTest::autoArrowsAreReadable_data()
{
    QTest::addColumn<QString>("lesson");
    QTest::newRow("29 line of impact") << "the-line-of-impact";
    QTest::newRow("32 gas") << "gas-in-a-box";
}

// With "arrows of a readable length" (on by default) the median velocity
// arrow is 45 px on screen, within the 30–60 px a class can read; the
// lesson's fixed scale gave 8 px in lesson 29.
void GuiStageTest::autoArrowsAreReadable()
{
    QFETCH(QString, lesson);
    MainWindow window(lesson);
    Canvas* canvas = window.canvas();
    canvas->resize(800, 560);
    const sim::World& world = window.controller()->world();
    const ViewTransform view = canvas->viewTransform();
    std::vector<double> lengths;
    const WorldPainter::ArrowScales scales = WorldPainter::arrowScales(world, view, canvas->paintOptions(), nullptr);
    for (int i = 0; i < world.balls().size(); ++i) {
        const double v = world.balls().velocity.col(i).norm();
        if (v > 0.0)
            lengths.push_back(view.toWidget(scales.velocity * v));
    }
    QVERIFY(!lengths.empty());
    std::nth_element(lengths.begin(), lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2), lengths.end());
    const double median = lengths[lengths.size() / 2];
    qInfo("%s: median velocity arrow %.1f px", qPrintable(lesson), median);
    QVERIFY2(median >= 30.0 && median <= 60.0, qPrintable(QString::number(median)));
}

void GuiStageTest::arrowLegendIsInTheBarOffTheBox_data()
{
    QTest::addColumn<QString>("lesson");
    QTest::addColumn<QSize>("size");
    for (const char* lesson : {"gravity", "elastic-band", "break-shot"}) {
        QTest::newRow(qPrintable(QStringLiteral("%1 1024x768").arg(QLatin1String(lesson))))
            << QString::fromLatin1(lesson) << QSize(1024, 768);
        QTest::newRow(qPrintable(QStringLiteral("%1 1280x720").arg(QLatin1String(lesson))))
            << QString::fromLatin1(lesson) << QSize(1280, 720);
    }
}

// On the stage the arrow legend is in the bar, never on the box: the card
// covered the box's bottom-right corner in the 3:2 lessons at 1024×768. Its
// sample arrow is as long as a velocity arrow of its value on the canvas.
void GuiStageTest::arrowLegendIsInTheBarOffTheBox()
{
    QFETCH(QString, lesson);
    QFETCH(QSize, size);
    MainWindow window(lesson);
    QVERIFY(presentAt(window, size));
    QVERIFY(test::waitForSettledLayout(&window));
    Canvas* canvas = window.canvas();
    QVERIFY(canvas->overlays().velocity);
    QVERIFY(!canvas->paintOptions().arrowLegendCard);
    auto* legend = window.findChild<ArrowLegendView*>(QStringLiteral("stageArrowLegend"));
    QVERIFY(legend);
    QTRY_VERIFY(legend->isVisible() && legend->rows() == canvas->painter().lastFrame().arrowLegendRows);
    QVERIFY(test::waitForSettledLayout(&window));
    const ArrowLegendRow row = legend->rows().first();
    QVERIFY2(row.label.endsWith(QStringLiteral(" (velocity)")), qPrintable(row.label));
    // Widget px per shown unit (px/s, or m/s in SI) of the canvas's
    // velocity arrows, against the legend's: the same to rounding.
    const ViewTransform view = canvas->viewTransform();
    const double perUnit =
        view.toWidget(WorldPainter::arrowScales(window.controller()->world(), view, canvas->paintOptions(), nullptr)
                          .velocity) /
        shownUnit(QStringLiteral("px/s"), displayUnits()).factor();
    bool ok = false;
    const double value = row.label.section(QLatin1Char(' '), 0, 0).toDouble(&ok);
    QVERIFY2(ok && value > 0.0, qPrintable(row.label));
    QVERIFY2(std::abs(row.pixels - value * perUnit) <= 1e-9 * row.pixels,
             qPrintable(QStringLiteral("%1 px for %2, %3 px/unit").arg(row.pixels).arg(row.label).arg(perUnit)));
    // Inside the window, and clear of the box.
    const QRect shown(legend->mapTo(&window, QPoint(0, 0)), legend->size());
    const QRectF box = view.boxRect().translated(canvas->mapTo(&window, QPoint(0, 0)));
    QVERIFY2(QRect(QPoint(0, 0), size).contains(shown), qPrintable(QStringLiteral("legend at %1,%2 %3x%4")
                                                                         .arg(shown.x()).arg(shown.y())
                                                                         .arg(shown.width()).arg(shown.height())));
    QVERIFY(!box.intersects(QRectF(shown)));
    QVERIFY(legend->height() >= legend->sizeHint().height());
    // Back in the normal layout the canvas draws its card again.
    QTest::keyClick(&window, Qt::Key_Escape);
    QVERIFY(canvas->paintOptions().arrowLegendCard);
    QVERIFY(!legend->isVisible());
}

// The lesson's number controls are big sliders on the stage (lesson 08:
// restitution and gravity, four rows); moving one changes the world, is
// one undo step, and the stage's label shows the new value.
// Every row of the parameter table a lesson's controls name gets its control
// on the stage from the table alone: a slider for a number with a slider
// range, a button for a switch, a list for a choice.
void GuiStageTest::everyListedRowHasAStageControl()
{
    SimulationController controller;
    SettingsEditor editor(&controller);
    StageSliders sliders(&controller, &editor);
    sliders.setLessonControls(LessonLoader::controlNames());
    // The Parameters panel's own rows (not rows of the parameter table): each
    // is on the stage, or left off it for the reason given.
    const QStringList panelRowsOnTheStage{QStringLiteral("wall_sides"), QStringLiteral("fully_inside")};
    const QHash<QString, QString> panelRowsNotOnTheStage{
        // The stage bar's Slower and Faster buttons change it, and its clock line shows it.
        {QStringLiteral("time_scale"), QStringLiteral("the bar's Slower / Faster buttons")},
        // A 20-digit number to type means nothing to a class; Reset replays the same run.
        {QStringLiteral("seed"), QStringLiteral("a number to type, nothing to see")},
        // A new count places every ball again mid-demonstration, and its range (0 to the
        // ball limit) has no slider range; the lesson's own count is the one it talks about.
        {QStringLiteral("ball_count"), QStringLiteral("respawns the lesson; no slider range")},
        // Typed code: the force editor dock is where it is written and read.
        {QStringLiteral("custom_acceleration"), QStringLiteral("code, in the force editor")},
    };
    int checked = 0;
    for (const QString& name : LessonLoader::controlNames())
        for (const QString& row : lessons::controlRows().value(name)) {
            const sim::Parameter* p = sim::findControl(row.toStdString());
            if (row.startsWith(QStringLiteral("spawn_")) && row.endsWith(QStringLiteral("_speed"))) {
                QVERIFY2(sliders.slider(row), qPrintable(row + QStringLiteral(": no slider on the stage")));
                continue;
            }
            if (panelRowsOnTheStage.contains(row)) {
                const QString side = row == QStringLiteral("wall_sides") ? QStringLiteral("wall_bottom") : row;
                QVERIFY2(sliders.toggle(side), qPrintable(row + QStringLiteral(": no control on the stage")));
                continue;
            }
            if (!p) {
                QVERIFY2(panelRowsNotOnTheStage.contains(row),
                         qPrintable(row + QStringLiteral(": a panel row neither on the stage nor listed here")));
                continue;
            }
            const bool number = p->type == sim::ParameterType::Number || p->type == sim::ParameterType::Integer;
            QWidget* control = number                                    ? static_cast<QWidget*>(sliders.slider(row))
                               : p->type == sim::ParameterType::Boolean ? static_cast<QWidget*>(sliders.toggle(row))
                                                                         : static_cast<QWidget*>(sliders.choice(row));
            if (number && !(p->sliderHi > p->sliderLo))
                QVERIFY2(!control, qPrintable(row)); // no slider range: the panel's box only
            else
                QVERIFY2(control, qPrintable(row + QStringLiteral(": no control on the stage")));
            ++checked;
        }
    QVERIFY(checked > 40);
}

void GuiStageTest::stageSlidersEditTheWorld()
{
    MainWindow window(QStringLiteral("losing-energy"));
    QVERIFY(presentAt(window, QSize(1280, 720))); // a 16:9 screen: the bar is a column beside the box
    auto* sliders = window.findChild<StageSliders*>(QStringLiteral("stageSliders"));
    QVERIFY(sliders);
    QCOMPARE(sliders->count(), 4);
    QVERIFY(sliders->isVisibleTo(&window));
    QVERIFY(sliders->slider(QStringLiteral("gravity_y"))->isVisibleTo(&window));
    NumberControl* e = sliders->slider(QStringLiteral("wall_restitution"));
    QVERIFY(e);
    QCOMPARE(e->value(), 0.8);
    auto* undo = window.findChild<QAction*>(QStringLiteral("undoAction"));
    QVERIFY(undo);
    e->slider()->setValue(e->positionFor(0.5));
    const double now = window.controller()->world().settings().walls.restitution;
    QVERIFY2(std::abs(now - 0.5) < 1e-9, qPrintable(QString::number(now)));
    auto* label = window.findChild<QLabel*>(QStringLiteral("stage_wall_restitutionLabel"));
    QVERIFY(label && label->text().contains(QStringLiteral("<b>0.5</b>")));
    QVERIFY(undo->isEnabled());
    undo->trigger();
    QCOMPARE(window.controller()->world().settings().walls.restitution, 0.8);
    QCOMPARE(e->value(), 0.8);
    // A lesson whose one number has no slider range (the ball count) shows
    // its switch alone.
    QVERIFY(window.openLesson(QStringLiteral("a-wall")));
    QCOMPARE(sliders->count(), 1);
    QVERIFY(!sliders->slider(QStringLiteral("ball_count")));
    QVERIFY(sliders->toggle(QStringLiteral("centre_only")));
    // A lesson without controls shows none, and no area for them.
    QVERIFY(window.openLesson(QStringLiteral("balls-on-a-canvas")));
    QCOMPARE(sliders->count(), 0);
    QVERIFY(!window.findChild<QWidget*>(QStringLiteral("stageSlidersScroll"))->isVisibleTo(&window));
}

// Lesson 07's challenge "Turn the bottom wall off" is done on the stage: the
// lesson lists "walls", so the stage shows a button per side. A click on
// Bottom opens the floor, the red ball falls through it, and Ctrl+Z closes
// it again.
void GuiStageTest::stageWallSidesOpenAWall()
{
    MainWindow window(QStringLiteral("gravity"));
    QVERIFY(presentAt(window, QSize(1024, 768)));
    auto* controls = window.findChild<StageSliders*>(QStringLiteral("stageSliders"));
    auto* more = window.findChild<QAction*>(QStringLiteral("stageSlidersAction"));
    QVERIFY(controls && more);
    if (more->isVisible())
        more->setChecked(true); // the controls wait for the Sliders button when they do not fit
    QPushButton* bottom = controls->toggle(QStringLiteral("wall_bottom"));
    QVERIFY(bottom);
    for (const char* side : {"wall_left", "wall_right", "wall_top"})
        QVERIFY2(controls->toggle(QLatin1String(side)), side);
    QCOMPARE(bottom->text(), QStringLiteral("Bottom"));
    auto* scroll = window.findChild<QScrollArea*>(QStringLiteral("stageSlidersScroll"));
    QVERIFY(scroll);
    scroll->ensureWidgetVisible(bottom);
    QTRY_VERIFY(bottom->isVisible());
    QVERIFY(bottom->isChecked());
    QVERIFY(window.controller()->world().settings().walls.bottom);

    QTest::mouseClick(bottom, Qt::LeftButton);
    QVERIFY(!window.controller()->world().settings().walls.bottom);
    QVERIFY(window.controller()->world().settings().walls.left); // the others stay
    QVERIFY(!bottom->isChecked());
    auto* label = window.findChild<QLabel*>(QStringLiteral("stage_wall_sidesLabel"));
    QVERIFY(label);
    QVERIFY2(label->text().contains(QStringLiteral("<b>left, right, top</b>")), qPrintable(label->text()));

    // Run: the red ball (ball 0) falls past where the floor was.
    const double height = window.controller()->world().settings().box.height;
    window.controller()->play();
    QTRY_VERIFY_WITH_TIMEOUT(window.controller()->world().balls().position(1, 0) > height + 50.0, 20000);
    window.controller()->pause();

    // Ctrl+Z, from the stage, closes the floor again.
    window.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&window));
    QTest::keyClick(&window, Qt::Key_Z, Qt::ControlModifier);
    QTRY_VERIFY(window.controller()->world().settings().walls.bottom);
    QVERIFY(bottom->isChecked());
    QVERIFY2(label->text().contains(QStringLiteral("<b>left, right, top, bottom</b>")), qPrintable(label->text()));

    // Lesson 04's switch of the Parameters panel's own (not a table row) is
    // on the stage too: a click places the balls fully inside, undo puts
    // back the lesson's partly-outside start.
    QVERIFY(window.openLesson(QStringLiteral("walls-and-radius")));
    if (more->isVisible())
        more->setChecked(true);
    QPushButton* inside = controls->toggle(QStringLiteral("fully_inside"));
    QVERIFY(inside);
    scroll->ensureWidgetVisible(inside);
    QTRY_VERIFY(inside->isVisible());
    QVERIFY(!window.controller()->spawn().fullyInside);
    QVERIFY(!inside->isChecked());
    QTest::mouseClick(inside, Qt::LeftButton);
    QVERIFY(window.controller()->spawn().fullyInside);
    QVERIFY(inside->isChecked());
    QTest::keyClick(&window, Qt::Key_Z, Qt::ControlModifier);
    QTRY_VERIFY(!window.controller()->spawn().fullyInside);
    QVERIFY(!inside->isChecked());

    // Lesson 02's "change the spawn speed range": the fastest random ball's
    // slider, let go at its lowest, places every random ball again at most
    // that fast; undo brings back the lesson's balls.
    QVERIFY(window.openLesson(QStringLiteral("animation")));
    if (more->isVisible())
        more->setChecked(true);
    NumberControl* fastest = controls->slider(QStringLiteral("spawn_max_speed"));
    QVERIFY(fastest && controls->slider(QStringLiteral("spawn_min_speed")));
    scroll->ensureWidgetVisible(fastest);
    QTRY_VERIFY(fastest->isVisible());
    const double lessonFastest = window.controller()->spawn().maxSpeed;
    const double lessonSlowest = window.controller()->spawn().minSpeed;
    QVERIFY(lessonFastest > lessonSlowest);
    fastest->slider()->setSliderDown(true);
    fastest->slider()->setValue(fastest->positionFor(lessonSlowest));
    fastest->slider()->setSliderDown(false); // released: the balls are placed again
    QTRY_COMPARE(window.controller()->spawn().maxSpeed, lessonSlowest);
    const sim::World& world = window.controller()->world();
    const int random = window.controller()->spawn().count; // placed after the lesson's own balls
    QVERIFY(random > 0);
    for (int i = world.balls().size() - random; i < world.balls().size(); ++i)
        QVERIFY2(world.balls().velocity.col(i).norm() <= lessonSlowest + 1e-9, qPrintable(QString::number(i)));
    QTest::keyClick(&window, Qt::Key_Z, Qt::ControlModifier);
    QTRY_COMPARE(window.controller()->spawn().maxSpeed, lessonFastest);
}

// A lesson's switches and choices are on the stage too. Lesson 35's
// challenge says "switch resting contacts off": on a 4:3 projector the
// class sees a big button for it, a click flips the world's setting and the
// label above says so, and one undo puts it back. Lesson 09's wall model is
// a list: a key press picks the next model, and the world runs it.
void GuiStageTest::stageSwitchesAndChoicesEditTheWorld()
{
    MainWindow window(QStringLiteral("stacks-that-stand"));
    QVERIFY(presentAt(window, QSize(1024, 768)));
    auto* controls = window.findChild<StageSliders*>(QStringLiteral("stageSliders"));
    QVERIFY(controls);
    auto* more = window.findChild<QAction*>(QStringLiteral("stageSlidersAction"));
    QVERIFY(more);
    if (more->isVisible())
        more->setChecked(true); // the controls wait for the Sliders button when they do not fit
    QPushButton* resting = controls->toggle(QStringLiteral("resting"));
    QVERIFY(resting);
    QVERIFY(resting->isVisibleTo(&window));
    auto* scroll = window.findChild<QScrollArea*>(QStringLiteral("stageSlidersScroll"));
    QVERIFY(scroll);
    scroll->ensureWidgetVisible(resting);
    QVERIFY(window.controller()->world().settings().collisions.resting);
    QVERIFY(resting->isChecked());
    QCOMPARE(resting->text(), QStringLiteral("Switch off"));
    QTest::mouseClick(resting, Qt::LeftButton);
    QVERIFY(!window.controller()->world().settings().collisions.resting);
    QVERIFY(!resting->isChecked());
    QCOMPARE(resting->text(), QStringLiteral("Switch on"));
    auto* label = window.findChild<QLabel*>(QStringLiteral("stage_restingLabel"));
    QVERIFY(label);
    QVERIFY2(label->text().contains(QStringLiteral("<b>off</b>")), qPrintable(label->text()));
    auto* undo = window.findChild<QAction*>(QStringLiteral("undoAction"));
    QVERIFY(undo && undo->isEnabled());
    undo->trigger();
    QVERIFY(window.controller()->world().settings().collisions.resting);
    QVERIFY(resting->isChecked());
    QVERIFY2(label->text().contains(QStringLiteral("<b>on</b>")), qPrintable(label->text()));

    QVERIFY(window.openLesson(QStringLiteral("bounce-at-the-right-moment")));
    QComboBox* model = controls->choice(QStringLiteral("wall_model"));
    QVERIFY(model);
    const sim::Parameter* row = sim::findControl("wall_model");
    QVERIFY(row);
    QCOMPARE(model->count(), static_cast<int>(row->choices().size()));
    const int before = static_cast<int>(row->get(window.controller()->world().settings()));
    QCOMPARE(model->currentIndex(), before);
    const int next = before + 1 < model->count() ? before + 1 : before - 1;
    QTest::keyClick(model, next > before ? Qt::Key_Down : Qt::Key_Up);
    QCOMPARE(static_cast<int>(row->get(window.controller()->world().settings())), next);
    auto* modelLabel = window.findChild<QLabel*>(QStringLiteral("stage_wall_modelLabel"));
    QVERIFY(modelLabel);
    QVERIFY2(modelLabel->text().contains(QStringLiteral("<b>%1</b>").arg(model->itemText(next))),
             qPrintable(modelLabel->text()));
    undo->trigger();
    QCOMPARE(static_cast<int>(row->get(window.controller()->world().settings())), before);
    QCOMPARE(model->currentIndex(), before);
}

void GuiStageTest::normalLayoutGivesTheBoxHalfTheWindow_data()
{
    QTest::addColumn<QString>("lesson");
    QTest::newRow("07 gravity, readout") << "gravity";
    QTest::newRow("19 orbit, readout") << "two-bodies-in-orbit";
    QTest::newRow("31 break shot, totals and momenta") << "break-shot";
}

// A first start in a 1280x720 window (no saved layout): the lesson goes in a
// tab beside the Parameters, the readouts take two lines above the box, and
// the box gets at least 45% of the window.
void GuiStageTest::normalLayoutGivesTheBoxHalfTheWindow()
{
    QFETCH(QString, lesson);
    QSettings().clear();
    MainWindow window(lesson);
    window.resize(1280, 720);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QTRY_COMPARE(window.size(), QSize(1280, 720));
    QVERIFY(test::waitForSettledLayout(&window));
    const QRectF box = window.canvas()->viewTransform().boxRect();
    const double share = box.width() * box.height() / (1280.0 * 720.0);
    qInfo("%s: the box takes %.1f%% of 1280x720 (%.0f x %.0f px)", qPrintable(lesson), 100 * share, box.width(),
          box.height());
    QVERIFY2(share >= 0.45, qPrintable(QString::number(share)));
    auto* lessons = window.findChild<QDockWidget*>(QStringLiteral("lessonsDock"));
    QVERIFY(lessons && lessons->isVisible()); // raised: the lesson text shows
}

void GuiStageTest::stageTextIsNeverCut_data()
{
    // In every shipped language: a German or Spanish challenge is longer.
    QTest::addColumn<QSize>("size");
    QTest::addColumn<QString>("language");
    for (const Language& language : shippedLanguages())
        for (const QSize size : {QSize(1024, 768), QSize(1280, 720), QSize(1920, 1080)})
            QTest::newRow(qPrintable(QStringLiteral("%1x%2 %3").arg(size.width()).arg(size.height()).arg(language.code)))
                << size << language.code;
}

// Every lesson in the stage view at a projector's 1024x768 and 1280x720:
// the challenge is never cut off (its lines fit the room its label has, in
// the window's text size or larger; a challenge too long even then ends in
// "…" with the whole text as its tooltip), and the readout's lines fit its
// room at 7 pt or more (its floor), and no word of a slider's label is cut.
// Before, lesson 12's challenge lost its first and last lines at 1024x768,
// lesson 07's readout shrank to 7 pt and still lost the speed, and lesson
// 19's slider unit was cut at 1280x720.
void GuiStageTest::stageTextIsNeverCut()
{
    QFETCH(QSize, size);
    QFETCH(QString, language);
    QVERIFY(applyLanguage(language));
    const auto english = qScopeGuard([] { applyLanguage(QStringLiteral("en")); });
    MainWindow window(QStringLiteral("gravity"));
    QVERIFY(presentAt(window, size));
    QWidget* bar = window.findChild<QWidget*>(QStringLiteral("stageBar"));
    auto* challenge = window.findChild<QLabel*>(QStringLiteral("stageChallenge"));
    auto* readout = window.findChild<QLabel*>(QStringLiteral("stageReadout"));
    auto* sliderArea = window.findChild<QScrollArea*>(QStringLiteral("stageSlidersScroll"));
    QVERIFY(bar && challenge && readout && sliderArea);
    QStringList shortened;
    int backRow = 0, challenges = 0; // challenges at 2.4% of the height or more
    int backRowReadouts = 0, readouts = 0;
    QStringList smallReadouts, smallChallenges;
    double smallestChallenge = 1.0; // the smallest challenge's text as a share of the floor
    struct Smallest {
        qreal points = 1000.0;
        QString lesson;
    } smallestInRow, smallestInColumn;
    for (const QString& file : LessonLoader::builtInFiles()) {
        QVERIFY2(window.openLesson(file), qPrintable(file));
        // The bar lays out and fits its text in answer to the events the new
        // lesson posts: read it once they are all served.
        QVERIFY2(test::waitForSettledLayout(&window), qPrintable(file));
        const QString name = QFileInfo(file).baseName();
        if (challenge->isVisible()) {
            const QRect room = challenge->contentsRect();
            const int need = QFontMetrics(challenge->font())
                                 .boundingRect(QRect(0, 0, room.width(), 1 << 20), Qt::TextWordWrap, challenge->text())
                                 .height();
            QVERIFY2(need <= room.height(), qPrintable(QStringLiteral("%1: challenge needs %2 px, has %3")
                                                           .arg(name).arg(need).arg(room.height())));
            QVERIFY2(challenge->font().pointSizeF() >= bar->font().pointSizeF(), qPrintable(name));
            ++challenges;
            const int pixels = QFontInfo(challenge->font()).pixelSize();
            if (pixels >= StageView::kTextFloorShare * size.height() - 0.5)
                ++backRow;
            else
                smallChallenges << QStringLiteral("%1 at %2 px").arg(name).arg(pixels);
            smallestChallenge = std::min(smallestChallenge, pixels / (StageView::kTextFloorShare * size.height()));
            if (challenge->text() != window.lesson().challenges.value(0)) {
                shortened << name;
                QVERIFY2(challenge->text().endsWith(QStringLiteral("…")), qPrintable(name));
                QCOMPARE(challenge->toolTip(), window.lesson().challenges.value(0));
            }
        }
        // Every stage button's word fits under its icon: Qt elides a word too
        // long for the button ("Des…res" was a Spanish "Deslizadores").
        for (QToolButton* button : bar->findChildren<QToolButton*>()) {
            if (!button->isVisible() || button->toolButtonStyle() != Qt::ToolButtonTextUnderIcon)
                continue;
            QString word = button->text();
            word.remove(QLatin1Char('&'));
            const int need = QFontMetrics(button->font()).horizontalAdvance(word);
            QVERIFY2(need <= button->width() - kButtonTextMargin,
                     qPrintable(QStringLiteral("%1: the button word '%2' needs %3 px, the button is %4 px")
                                    .arg(name, word)
                                    .arg(need)
                                    .arg(button->width())));
        }
        // Every word of a stage slider's label fits its width (a label may
        // wrap, but "restitution" must not lose its end).
        for (QLabel* label : bar->findChildren<QLabel*>()) {
            if (!label->isVisible() || !label->objectName().startsWith(QStringLiteral("stage_")))
                continue;
            QString plain = label->text();
            plain.remove(QRegularExpression(QStringLiteral("<[^>]*>")));
            const QFontMetrics fm(label->font());
            const int width = label->contentsRect().width();
            for (const QString& word : plain.split(QLatin1Char(' '), Qt::SkipEmptyParts))
                QVERIFY2(fm.horizontalAdvance(word) <= width,
                         qPrintable(QStringLiteral("%1: '%2' in %3 px").arg(name, word).arg(width)));
            // ... and the label is not under the sliders' scroll bar.
            QWidget* viewport = sliderArea->viewport();
            const int right = label->mapTo(viewport, QPoint(label->width(), 0)).x();
            QVERIFY2(right <= viewport->width(), qPrintable(QStringLiteral("%1: a slider label ends at %2 of %3 px")
                                                                .arg(name)
                                                                .arg(right)
                                                                .arg(viewport->width())));
        }
        if (qEnvironmentVariableIsSet("DBGS")) {
            auto* sliders = window.findChild<StageSliders*>();
            qInfo("SLIDERS %s count %d shown %d", qPrintable(name), sliders ? sliders->count() : -1, int(sliderArea->isVisible()));
        }
        if (readout->isVisible()) {
            const QFontMetrics fm(readout->font());
            const QStringList lines = readout->text().split(QLatin1Char('\n'));
            int widest = 0;
            for (const QString& line : lines)
                widest = std::max(widest, fm.horizontalAdvance(line));
            const QRect room = readout->contentsRect();
            QVERIFY2(widest <= room.width() && lines.size() * fm.lineSpacing() <= room.height(),
                     qPrintable(QStringLiteral("%1: readout %2 x %3 px in %4 x %5 at %6 pt")
                                    .arg(name)
                                    .arg(widest)
                                    .arg(lines.size() * fm.lineSpacing())
                                    .arg(room.width())
                                    .arg(room.height())
                                    .arg(readout->font().pointSizeF())));
            QVERIFY2(readout->font().pointSizeF() >= 7.0,
                     qPrintable(QStringLiteral("%1: readout at %2 pt").arg(name).arg(readout->font().pointSizeF())));
            ++readouts;
            if (QFontInfo(readout->font()).pixelSize() >= StageView::kTextFloorShare * size.height() - 0.5)
                ++backRowReadouts;
            else
                smallReadouts << name;
            auto* stageBar = qobject_cast<StageBar*>(bar);
            Smallest& smallest = stageBar && stageBar->isVertical() ? smallestInColumn : smallestInRow;
            if (readout->font().pointSizeF() < smallest.points)
                smallest = {readout->font().pointSizeF(), name};
        }
    }
    qInfo("%dx%d %s: %lld of %lld challenges shortened (%s)", size.width(), size.height(), qPrintable(language),
          static_cast<long long>(shortened.size()), static_cast<long long>(LessonLoader::builtInFiles().size()),
          qPrintable(shortened.join(QStringLiteral(", "))));
    qInfo("%dx%d: %d of %d challenges at 2.4%% of the height or more (not: %s)", size.width(), size.height(), backRow,
          challenges, qPrintable(smallChallenges.join(QStringLiteral(", "))));
    qInfo("%dx%d: %d of %d readouts at 2.4%% of the height or more (not: %s)", size.width(), size.height(),
          backRowReadouts, readouts, qPrintable(smallReadouts.join(QStringLiteral(", "))));
    // Every English challenge starts at the floor. A translation's is longer
    // (German by about a quarter): one that would not fit at the floor is
    // set a little smaller rather than cut, never under 85% of it. At
    // 1024x768 lesson 33's readout (three balls' energies) is too wide for
    // the column beside its wide box and comes out a little smaller; every
    // other one starts there too.
    if (language == QLatin1String("en"))
        QVERIFY2(backRow == challenges, qPrintable(smallChallenges.join(QStringLiteral(", "))));
    QVERIFY2(smallestChallenge >= 0.85, qPrintable(smallChallenges.join(QStringLiteral(", "))));
    // A translation's longer challenge leaves the readout less room: up to
    // two more readouts under the floor, still at 7 pt or more (above).
    QVERIFY2(backRowReadouts >= readouts - (language == QLatin1String("en") ? 1 : 3),
             qPrintable(smallReadouts.join(QStringLiteral(", "))));
    qInfo("%dx%d: smallest readout %.1f pt in a row (%s), %.1f pt in a column (%s)", size.width(), size.height(),
          smallestInRow.points, qPrintable(smallestInRow.lesson), smallestInColumn.points,
          qPrintable(smallestInColumn.lesson));
}

// A row bar 600 px wide and 100 px tall with a challenge of 120 words: the
// font goes down to the window's text size, the text stops after the last
// whole word that fits with "…", and the tooltip holds all of it. Given
// room again, the whole challenge comes back at its own size.
void GuiStageTest::tooLongAChallengeEndsInAnEllipsis()
{
    QAction play(QStringLiteral("Play"));
    StageBar bar({&play});
    bar.setVertical(false);
    bar.setFixedSize(600, 100);
    bar.show();
    QVERIFY(QTest::qWaitForWindowExposed(&bar));
    QStringList words;
    for (int i = 0; i < 120; ++i)
        words << QStringLiteral("word%1").arg(i);
    const QString challenge = words.join(QLatin1Char(' '));
    bar.setCaption(QStringLiteral("Title"), challenge);
    auto* label = bar.findChild<QLabel*>(QStringLiteral("stageChallenge"));
    QVERIFY(label);
    QTRY_VERIFY(label->text().endsWith(QStringLiteral(" …")));
    QCOMPARE(label->toolTip(), challenge);
    QVERIFY(challenge.startsWith(label->text().chopped(2)));
    QCOMPARE(label->font().pointSizeF(), bar.font().pointSizeF());
    const QRect room = label->contentsRect();
    QVERIFY(QFontMetrics(label->font())
                .boundingRect(QRect(0, 0, room.width(), 1 << 20), Qt::TextWordWrap, label->text())
                .height() <= room.height());
    bar.setFixedSize(1600, 400);
    QTRY_COMPARE(label->text(), challenge);
    QVERIFY(label->toolTip().isEmpty());
    QVERIFY(label->font().pointSizeF() > bar.font().pointSizeF());
}

// Lesson 26 at 1280x720 puts its ten lines of readout (a ball, then the
// totals) in a row bar about 120 px tall: in one text column they fit only at
// 7 pt, too small for the back of a classroom. Set in two text columns they
// are at 10 pt or more, every line is still there, and no group is split
// ("kinetic", "potential" and "total" stay under "energy").
void GuiStageTest::rowReadoutUsesTextColumns()
{
    MainWindow window(QStringLiteral("gravity"));
    QVERIFY(presentAt(window, QSize(1280, 720)));
    QVERIFY(window.openLesson(QStringLiteral("26-bouncing-in-1d-naively")));
    auto* readout = window.findChild<QLabel*>(QStringLiteral("stageReadout"));
    QVERIFY(readout);
    QTRY_VERIFY(readout->isVisible() && readout->text().contains(QStringLiteral("momentum")));
    QVERIFY(test::waitForSettledLayout(&window)); // the bar fits its text once the grid has laid out
    auto* bar = window.findChild<StageBar*>(QStringLiteral("stageBar"));
    QVERIFY(bar && !bar->isVertical());
    const QStringList shown = readout->text().split(QLatin1Char('\n'));
    qInfo("lesson 26 at 1280x720: %lld lines in the label, at %.1f pt", static_cast<long long>(shown.size()),
          readout->font().pointSizeF());
    QVERIFY2(readout->font().pointSizeF() >= 10.0, qPrintable(QString::number(readout->font().pointSizeF())));
    QVERIFY(shown.size() <= 6);
    int energy = -1, column = -1;
    for (qsizetype row = 0; row < shown.size(); ++row) {
        const int at = static_cast<int>(shown[row].indexOf(QStringLiteral("energy (")));
        if (at >= 0) {
            energy = static_cast<int>(row);
            column = at;
        }
    }
    QVERIFY(energy >= 0 && energy + 3 < shown.size());
    QCOMPARE(shown[energy + 1].indexOf(QStringLiteral("kinetic")), column + 2);
    QCOMPARE(shown[energy + 2].indexOf(QStringLiteral("potential")), column + 2);
    QCOMPARE(shown[energy + 3].indexOf(QStringLiteral("total")), column + 2);
    for (const QString& line : {QStringLiteral("ball 0"), QStringLiteral("speed"), QStringLiteral("momentum")})
        QVERIFY2(readout->text().contains(line), qPrintable(line));
}

// On a 4:3 projector the bar under the box has no room for a lesson's
// sliders (37 of the 39 lessons with sliders had none in the stage view at
// 1024x768). The Sliders button shows them: the bar grows, every slider is
// in view without scrolling and edits the world, and the box keeps over 60%
// of its size; pressed again, the box gets its room back. Where the
// sliders fit (a column on a 16:9 screen) there is no such button.
void GuiStageTest::slidersButtonShowsARowBarsSliders()
{
    MainWindow window(QStringLiteral("losing-energy"));
    QVERIFY(presentAt(window, QSize(1024, 768)));
    auto* action = window.findChild<QAction*>(QStringLiteral("stageSlidersAction"));
    auto* area = window.findChild<QScrollArea*>(QStringLiteral("stageSlidersScroll"));
    auto* sliders = window.findChild<StageSliders*>(QStringLiteral("stageSliders"));
    QVERIFY(action && area && sliders);
    QCOMPARE(sliders->count(), 4);
    QToolButton* button = nullptr;
    for (QToolButton* b : window.findChildren<QToolButton*>())
        if (b->defaultAction() == action)
            button = b;
    QVERIFY(button);
    QTRY_VERIFY(button->isVisible());
    QVERIFY(!area->isVisible());
    QVERIFY(test::waitForSettledLayout(&window));
    const double windowArea = 1024.0 * 768.0;
    auto boxShare = [&] {
        const QRectF box = window.canvas()->viewTransform().boxRect();
        return box.width() * box.height() / windowArea;
    };
    const double hiddenShare = boxShare();

    QTest::mouseClick(button, Qt::LeftButton);
    QTRY_VERIFY(area->isVisible());
    QVERIFY(test::waitForSettledLayout(&window));
    QVERIFY(action->isChecked());
    QVERIFY2(area->widget()->height() <= area->viewport()->height(),
             qPrintable(QStringLiteral("%1 of %2").arg(area->widget()->height()).arg(area->viewport()->height())));
    const double shownShare = boxShare();
    qInfo("the box takes %.1f%% of 1024x768 with the sliders hidden, %.1f%% with them shown", 100 * hiddenShare,
          100 * shownShare);
    QVERIFY(shownShare < hiddenShare);
    QVERIFY2(shownShare >= 0.6 * hiddenShare, qPrintable(QString::number(shownShare)));
    if (qEnvironmentVariableIsSet("SHOTS"))
        window.grab().save(QStringLiteral("/tmp/sliders_shown.png"));
    NumberControl* e = sliders->slider(QStringLiteral("wall_restitution"));
    QVERIFY(e && e->isVisibleTo(&window));
    e->slider()->setValue(e->positionFor(0.5));
    QVERIFY(std::abs(window.controller()->world().settings().walls.restitution - 0.5) < 1e-9);

    QTest::mouseClick(button, Qt::LeftButton);
    QTRY_VERIFY(!area->isVisible());
    QTRY_VERIFY(std::abs(boxShare() - hiddenShare) < 1e-9);

    // A 16:9 screen: the bar is a column beside the box, with the sliders.
    window.setGeometry(QRect(QPoint(0, 0), QSize(1280, 720)));
    QTRY_VERIFY(area->isVisible());
    QVERIFY(!button->isVisible());
}

QTEST_MAIN(GuiStageTest)
// Lesson 09 has no readout, and a teacher slowed lesson 07 to a quarter
// with no sign of it: the stage always shows the time and the speed, and
// they follow the Slower button and the run.
void GuiStageTest::stageAlwaysShowsTheClockAndTheSpeed()
{
    MainWindow window(QStringLiteral("bounce-at-the-right-moment"));
    QVERIFY(presentAt(window, QSize(1024, 768)));
    QVERIFY(!window.lesson().overlays.contains(QStringLiteral("readout")));
    auto* readout = window.findChild<QLabel*>(QStringLiteral("stageReadout"));
    QVERIFY(readout);
    QTRY_VERIFY(readout->isVisible() && readout->text().contains(QStringLiteral("t = 0.00 s")));
    QVERIFY2(readout->text().contains(QStringLiteral("t = 0.00 s   1× speed")), qPrintable(readout->text()));
    auto* slower = window.findChild<QAction*>(QStringLiteral("slowerAction"));
    QVERIFY(slower);
    slower->trigger();
    slower->trigger();
    QCOMPARE(window.controller()->timeScale(), 0.25);
    QTRY_VERIFY2(readout->text().contains(QStringLiteral("¼× speed")), qPrintable(readout->text()));
    window.controller()->setPlaying(true);
    QTRY_VERIFY(window.controller()->world().time() > 0.1);
    // The shown time is the world's, to the hundredth.
    window.controller()->setPlaying(false);
    QTRY_VERIFY(readout->text().contains(
        QStringLiteral("t = %1 s").arg(window.controller()->world().time(), 0, 'f', 2)));
    QCOMPARE(StageView::clockText(12.345, 0.125), QStringLiteral("t = 12.35 s   1/8× speed"));
    QCOMPARE(StageView::clockText(0.0, 4.0), QStringLiteral("t = 0.00 s   4× speed"));
}

// The stage view hides the menus and toolbars, not their keys: B adds a
// ball and Ctrl+Z takes it back, Ctrl+Shift+Z puts it back, Alt+→ and Alt+←
// change the lesson, and F11 (the View menu says so) leaves the stage view,
// under any window system.
void GuiStageTest::stageKeysAreTheNormalLayoutsKeys()
{
    MainWindow window(QStringLiteral("gravity"));
    QVERIFY(presentAt(window, QSize(1024, 768)));
    QVERIFY(!window.menuBar()->isVisible());
    window.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&window));
    window.canvas()->setFocus();
    const int balls = window.controller()->world().balls().size();
    QTest::keyClick(window.canvas(), Qt::Key_B);
    QTRY_COMPARE(window.controller()->world().balls().size(), balls + 1);
    QTest::keyClick(window.canvas(), Qt::Key_Z, Qt::ControlModifier);
    QTRY_COMPARE(window.controller()->world().balls().size(), balls);
    QTest::keyClick(window.canvas(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QTRY_COMPARE(window.controller()->world().balls().size(), balls + 1);

    const QString first = window.lesson().id;
    QTest::keyClick(window.canvas(), Qt::Key_Right, Qt::AltModifier);
    QTRY_VERIFY(window.lesson().id != first);
    QTest::keyClick(window.canvas(), Qt::Key_Left, Qt::AltModifier);
    QTRY_COMPARE(window.lesson().id, first);

    auto* stage = window.findChild<QAction*>(QStringLiteral("presentationAction"));
    QVERIFY(stage && stage->isChecked());
    QCOMPARE(stage->shortcut(), QKeySequence(Qt::Key_F11));
    // The View menu lists the action with its key.
    bool listed = false;
    for (QAction* menu : window.menuBar()->actions())
        if (menu->menu())
            for (QAction* a : menu->menu()->actions())
                listed = listed || (a == stage && !a->shortcut().isEmpty());
    QVERIFY(listed);
    QTest::keyClick(window.canvas(), Qt::Key_F11);
    QTRY_VERIFY(!stage->isChecked());
    QTRY_VERIFY(window.menuBar()->isVisible());
}

// Ctrl+= makes the text larger on the stage (title, challenge, readout),
// in every panel (the application's font) and on the canvas (its panels'
// scale); a new window opens at the same size; Ctrl+0 brings the usual
// size back. The setting lives in this test's own settings file, removed
// whatever happens, so the other tests open at the usual size.
void GuiStageTest::textSizeKeysScaleEveryTextAndAreRemembered()
{
    const QString key = QStringLiteral("view/textScale");
    QSettings().remove(key);
    const auto forget = qScopeGuard([&] { QSettings().remove(key); });
    double title = 0.0, app = 0.0, lines = 0.0;
    {
        MainWindow window(QStringLiteral("two-bodies-in-orbit"));
        QVERIFY(presentAt(window, QSize(1280, 720)));
        QVERIFY(test::waitForSettledLayout(&window));
        auto* titleLabel = window.findChild<QLabel*>(QStringLiteral("stageTitle"));
        QVERIFY(titleLabel);
        title = titleLabel->font().pointSizeF();
        app = QApplication::font().pointSizeF();
        lines = window.canvas()->paintOptions().lineScale;
        window.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&window));
        QTest::keyClick(window.canvas(), Qt::Key_Equal, Qt::ControlModifier);
        QTest::keyClick(window.canvas(), Qt::Key_Equal, Qt::ControlModifier);
        QTRY_COMPARE(window.textScale(), 1.44);
        QTRY_VERIFY(std::abs(titleLabel->font().pointSizeF() - 1.44 * title) < 0.05 * title);
        QVERIFY(std::abs(QApplication::font().pointSizeF() - 1.44 * app) < 0.05 * app);
        QVERIFY(std::abs(window.canvas()->paintOptions().lineScale - 1.44 * lines) < 1e-9);
        QVERIFY(test::waitForSettledLayout(&window));
        // Still nothing cut: the challenge shows whole or ends in "…" with
        // the whole of it as its tooltip.
        auto* challenge = window.findChild<QLabel*>(QStringLiteral("stageChallenge"));
        QVERIFY(challenge);
        QVERIFY(challenge->text() == challenge->toolTip() || challenge->toolTip().isEmpty() ||
                challenge->text().endsWith(QStringLiteral(" …")));
    }
    QCOMPARE(QSettings().value(key).toDouble(), 1.44);
    MainWindow again(QStringLiteral("two-bodies-in-orbit"));
    QCOMPARE(again.textScale(), 1.44);
    QVERIFY(std::abs(QApplication::font().pointSizeF() - 1.44 * app) < 0.05 * app);
    QVERIFY(presentAt(again, QSize(1280, 720)));
    again.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&again));
    QTest::keyClick(again.canvas(), Qt::Key_0, Qt::ControlModifier);
    QTRY_COMPARE(again.textScale(), 1.0);
    QTRY_VERIFY(std::abs(QApplication::font().pointSizeF() - app) < 1e-9);
    QCOMPARE(QSettings().value(key).toDouble(), 1.0);
}

void GuiStageTest::everyLessonToolWorksOnTheStage_data()
{
    addProjectorSizes(false);
}

// Every shipped lesson that sends its class to a panel (the Stopwatch in
// lesson 19, the Inspector in 02, Predict where it asks) offers it on the
// stage: the start banner lists its key, the key opens the panel floating over the
// stage and inside the screen, ready to use, the key again closes it, and
// the right-click menu has the same tools and the Show menu.
void GuiStageTest::everyLessonToolWorksOnTheStage()
{
    QFETCH(QSize, size);
    MainWindow window(QStringLiteral("gravity"));
    QVERIFY(presentAt(window, size));
    window.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&window));
    int used = 0;
    for (const QString& file : LessonLoader::builtInFiles()) {
        QVERIFY(window.openLesson(file));
        const QStringList tools = lessons::stageTools(window.lesson());
        for (qsizetype k = 0; k < tools.size(); ++k) {
            const QString what = file + QStringLiteral(": ") + tools[k];
            const lessons::ToolInfo* tool = lessons::findTool(tools[k]);
            QVERIFY2(tool, qPrintable(what));
            const QString key = QStringLiteral("%1 %2").arg(k + 1).arg(tool->title);
            QVERIFY2(window.canvas()->toolKeys().contains(key), qPrintable(what));
            auto* action = window.findChild<QAction*>(QStringLiteral("toolAction_") + tools[k]);
            QVERIFY2(action && action->shortcut() == QKeySequence(Qt::Key_1 + static_cast<int>(k)), qPrintable(what));
            QTest::keyClick(window.canvas(), static_cast<Qt::Key>(Qt::Key_1 + k));
            QDockWidget* dock = nullptr;
            QTRY_VERIFY2((dock = [&]() -> QDockWidget* {
                             for (QDockWidget* d : window.findChildren<QDockWidget*>())
                                 if (d->isVisible() && d->isFloating())
                                     return d;
                             return nullptr;
                         }()) != nullptr,
                         qPrintable(what));
            QVERIFY2(dock->widget() && dock->widget()->isEnabled(), qPrintable(what));
            const QRect screen(window.mapToGlobal(QPoint(0, 0)), window.size());
            QVERIFY2(screen.contains(dock->frameGeometry()),
                     qPrintable(what + QStringLiteral(" at %1,%2 %3x%4")
                                           .arg(dock->frameGeometry().x())
                                           .arg(dock->frameGeometry().y())
                                           .arg(dock->frameGeometry().width())
                                           .arg(dock->frameGeometry().height())));
            // Its own title bar, to move and close it by without a window manager.
            QWidget* bar = dock->titleBarWidget();
            QVERIFY2(bar && bar->objectName() == QStringLiteral("stageToolTitle") && bar->isVisible(),
                     qPrintable(what));
            if (used % 2 == 0) { // closed by its key, or by the bar's close button
                window.canvas()->setFocus();
                QTest::keyClick(window.canvas(), static_cast<Qt::Key>(Qt::Key_1 + k));
            } else {
                bar->findChild<QToolButton*>(QStringLiteral("stageToolClose"))->click();
            }
            QTRY_VERIFY2(!dock->isVisible(), qPrintable(what));
            ++used;
        }
    }
    QVERIFY2(used >= 20, qPrintable(QString::number(used))); // Predict in most lessons, and the listed tools
    // Back in the normal layout the panels have their usual titles again.
    QTest::keyClick(&window, Qt::Key_Escape);
    for (QDockWidget* d : window.findChildren<QDockWidget*>())
        QVERIFY2(!d->titleBarWidget(), qPrintable(d->objectName()));
    window.findChild<QAction*>(QStringLiteral("presentationAction"))->setChecked(true);
    // The right-click menu ends with the Tools and Show menus.
    QVERIFY(window.openLesson(QStringLiteral("two-bodies-in-orbit")));
    QMenu menu;
    window.canvas()->fillContextMenu(menu, QPointF(5, 5));
    QStringList titles;
    for (QAction* a : menu.actions())
        if (a->menu())
            titles << a->menu()->title().remove(QLatin1Char('&'));
    QVERIFY2(titles.contains(QStringLiteral("Tools")) && titles.size() == 2, qPrintable(titles.join(u',')));
}

#include "test_gui_stage.moc"
