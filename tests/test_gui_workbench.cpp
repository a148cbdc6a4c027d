// The workbench around the canvas, driven as a user would: every control of
// the Parameters dock changes the world field it edits, undo and redo put it
// back and again, Reset restores the lesson, lessons switch the docks and the
// controls shown, keyboard shortcuts act, a saved scene opens as the same
// scene, the Lessons tree follows the course, and the Inspector shows the
// selected ball's numbers as the world has them.

#include "ui/canvas/canvas.h"
#include "ui/docks/inspector_dock.h"
#include "ui/docks/lessons_dock.h"
#include "ui/window/main_window.h"
#include "ui/controls/number_control.h"
#include "ui/controls/parameter_panel.h"
#include "ui/controls/settings_editor.h"
#include "ui/canvas/simulation_controller.h"
#include "ui/docks/trajectory_export.h"
#include "ui/drawing/display_units.h"

#include "lessons/lesson_loader.h"
#include "sim/world/names.h"
#include "sim/world/parameters.h"
#include "tests/sim_test_util.h"

#include <QMessageBox>
#include <QTimer>
#include <QApplication>
#include <QScreen>
#include <QDir>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGroupBox>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QSettings>
#include <QScrollBar>
#include <QSignalSpy>
#include <QSlider>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBrowser>
#include <QTreeWidget>
#include <QUndoStack>

#include <cmath>
#include <cstring>
#include <functional>

using namespace forcelab;

namespace {

// A scene in which no model is on, with two listed balls and three random ones.
sim::Scene plainScene()
{
    sim::Scene scene;
    scene.settings.box = {600.0, 400.0};
    scene.balls = {forcelab::test::coloured(sim::ballAt(150, 120, 40, -10, 20), 0xe05050),
                   forcelab::test::coloured(sim::ballAt(420, 260, -25, 30, 12, 3.5), 0x3090d0)};
    scene.spawn.count = 3;
    return scene;
}

// The plain scene in a controller, with an editor and the Parameters panel
// showing every row, and a spy on the controller's errors.
struct PanelBench {
    SimulationController controller;
    bool sceneSet = !controller.setScene(plainScene());
    SettingsEditor editor{&controller};
    ParameterPanel panel{&controller, &editor};
    QSignalSpy errors{&controller, &SimulationController::errorOccurred};
    PanelBench() { panel.setShowAll(true); }
};

// One control of the table: the widget to set, the value to give it, and how
// to read back the field it edits (enums as their index, switches as 0 / 1).
struct ControlCase {
    const char* row;     // ParameterPanel row key (or section key for a model's switch)
    const char* widget;  // objectName
    QVariant value;      // number for spin boxes, text for combos and the seed, bool for switches
    double expected;     // the field's value afterwards, in the world's units
    std::function<double(const SimulationController&)> field;
};

using C = const SimulationController&;
double settingsOf(C c, const std::function<double(const sim::WorldSettings&)>& f)
{
    return f(c.world().settings());
}
#define FIELD(expr) [](C c) { return settingsOf(c, [](const sim::WorldSettings& s) { return double(expr); }); }

template <class Enum>
double indexOf(std::span<const std::string_view> names, const char* name)
{
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == name)
            return double(i);
    return -1.0;
}

const std::vector<ControlCase>& controlCases()
{
    static const std::vector<ControlCase> cases{
        {"gravity", "gravityGroup", true, 1.0, FIELD(s.gravity.enabled)},
        {"gravity_x", "gravityXSpin", -123.5, -123.5, FIELD(s.gravity.g.x())},
        {"gravity_y", "gravityYSpin", 500.0, 500.0, FIELD(s.gravity.g.y())},
        {"wall_sides", "wallLeftCheck", false, 0.0, FIELD(s.walls.left)},
        {"wall_sides", "wallRightCheck", false, 0.0, FIELD(s.walls.right)},
        {"wall_sides", "wallTopCheck", false, 0.0, FIELD(s.walls.top)},
        {"wall_sides", "wallBottomCheck", false, 0.0, FIELD(s.walls.bottom)},
        {"wall_model", "wallModelCombo", "reverse", indexOf<sim::WallModel>(sim::wallModelNames(), "reverse"),
         FIELD(s.walls.model)},
        {"wall_restitution", "wallRestitutionSpin", 0.75, 0.75, FIELD(s.walls.restitution)},
        {"box_width", "boxWidthSpin", 700.0, 700.0, FIELD(s.box.width)},
        {"box_height", "boxHeightSpin", 450.0, 450.0, FIELD(s.box.height)},
        {"middle_wall", "middleWallCheck", true, 1.0, FIELD(s.walls.middle)},
        {"centre_only", "centreOnlyCheck", true, 1.0, FIELD(s.walls.centreOnly)},
        {"drag", "dragGroup", true, 1.0, FIELD(s.drag.enabled)},
        {"drag_law", "dragLawCombo", "quadratic", indexOf<sim::DragLaw>(sim::dragLawNames(), "quadratic"),
         FIELD(s.drag.law)},
        {"drag_k", "dragKSpin", 0.0125, 0.0125, FIELD(s.drag.k)},
        {"drag_scale", "dragScaleCombo", "none", indexOf<sim::ForceScale>(sim::forceScaleNames(), "none"),
         FIELD(s.drag.scale)},
        {"wind_mode", "windModeCombo", "noise", indexOf<sim::WindMode>(sim::windModeNames(), "noise"),
         FIELD(s.wind.mode)},
        {"wind_strength", "windStrengthSpin", 1234.0, 1234.0, FIELD(s.wind.strength)},
        {"wind_scale", "windScaleCombo", "mass", indexOf<sim::ForceScale>(sim::forceScaleNames(), "mass"),
         FIELD(s.wind.scale)},
        {"wind_smoothed_step", "windSmoothedStepSpin", 0.25, 0.25, FIELD(s.wind.smoothedStep)},
        {"wind_frequency", "windFrequencySpin", 2.5, 2.5, FIELD(s.wind.noiseFrequency)},
        {"wind_compare", "windCompareCombo", "smoothed", indexOf<sim::WindMode>(sim::windModeNames(), "smoothed"),
         FIELD(s.wind.compare)},
        {"random_accel", "randomAccelGroup", true, 1.0, FIELD(s.randomAccel.enabled)},
        {"random_fixed", "randomFixedCheck", true, 1.0, FIELD(s.randomAccel.fixed)},
        {"random_strength", "randomStrengthSpin", 250.0, 250.0, FIELD(s.randomAccel.strength)},
        {"random_uncentred", "randomUncentredCheck", true, 1.0, FIELD(s.randomAccel.uncentred)},
        {"point", "pointGroup", true, 1.0, FIELD(s.point.enabled)},
        {"point_kind", "pointKindCombo", "repel", indexOf<sim::PointKind>(sim::pointKindNames(), "repel"),
         FIELD(s.point.kind)},
        {"point_x", "pointXSpin", 111.0, 111.0, FIELD(s.point.position.x())},
        {"point_y", "pointYSpin", 222.0, 222.0, FIELD(s.point.position.y())},
        {"point_strength", "pointStrengthSpin", 2.5e7, 2.5e7, FIELD(s.point.strength)},
        {"point_clamp", "pointClampSpin", 4000.0, 4000.0, FIELD(s.point.maxAccel)},
        {"point_scale", "pointScaleCombo", "radius", indexOf<sim::ForceScale>(sim::forceScaleNames(), "radius"),
         FIELD(s.point.scale)},
        {"point_unnormalised", "pointUnnormalisedCheck", true, 1.0, FIELD(s.point.unnormalised)},
        {"spring", "springGroup", true, 1.0, FIELD(s.spring.enabled)},
        {"spring_k", "springKSpin", 9.0, 9.0, FIELD(s.spring.k)},
        {"spring_x", "springXSpin", 250.0, 250.0, FIELD(s.spring.anchor.x())},
        {"spring_y", "springYSpin", 150.0, 150.0, FIELD(s.spring.anchor.y())},
        {"mutual_gravity", "mutualGravityGroup", true, 1.0, FIELD(s.mutualGravity.enabled)},
        {"mutual_g", "mutualGSpin", -5e4, -5e4, FIELD(s.mutualGravity.G)},
        {"mutual_softening", "mutualSofteningSpin", 3.5, 3.5, FIELD(s.mutualGravity.softening)},
        {"homing", "homingGroup", true, 1.0, FIELD(s.homing.enabled)},
        {"homing_strength", "homingStrengthSpin", 0.5, 0.5, FIELD(s.homing.strength)},
        {"pointer", "pointerGroup", true, 1.0, FIELD(s.pointer.enabled)},
        {"pointer_strength", "pointerStrengthSpin", 5e6, 5e6, FIELD(s.pointer.strength)},
        {"pointer_clamp", "pointerClampSpin", 0.0, 0.0, FIELD(s.pointer.maxAccel)},
        {"magnetic", "magneticGroup", true, 1.0, FIELD(s.magnetic.enabled)},
        {"magnetic_b", "magneticBSpin", 2.5, 2.5, FIELD(s.magnetic.B)},
        {"custom", "customGroup", true, 1.0, FIELD(s.custom.enabled)},
        {"custom_acceleration", "customAccelerationCheck", true, 1.0, FIELD(s.custom.acceleration)},
        {"speed_limit", "speedLimitGroup", true, 1.0, FIELD(s.speedLimit.enabled)},
        {"speed_limit", "speedLimitSpin", 450.0, 450.0, FIELD(s.speedLimit.max)},
        {"detection", "detectionCombo", "grid", indexOf<sim::Detection>(sim::detectionNames(), "grid"),
         FIELD(s.collisions.detection)},
        {"response", "responseCombo", "2d-impulse", indexOf<sim::Response>(sim::responseNames(), "2d-impulse"),
         FIELD(s.collisions.response)},
        {"ball_restitution", "ballRestitutionSpin", 0.5, 0.5, FIELD(s.collisions.restitution)},
        {"continuous", "continuousCheck", true, 1.0, FIELD(s.collisions.continuous)},
        {"resting", "restingCheck", false, 0.0, FIELD(s.collisions.resting)},
        {"integrator", "integratorCombo", "rk45", indexOf<sim::IntegratorKind>(sim::integratorNames(), "rk45"),
         FIELD(s.time.integrator)},
        {"dt", "dtSpin", 5.0, 0.005, FIELD(s.time.dt)},
        {"substeps", "substepsSpin", 4.0, 4.0, FIELD(s.time.substeps)},
        {"tolerance", "toleranceSpin", 1e-6, 1e-6, FIELD(s.time.tolerance)},
        {"per_frame", "perFrameCheck", true, 1.0, FIELD(s.time.perFrame)},
        {"close_passes", "closePassesCheck", true, 1.0, FIELD(s.time.stepPastClosePasses)},
        {"seed", "seedEdit", "12345", 12345.0, FIELD(s.time.seed)},
        {"time_scale", "timeScaleSpin", 0.25, 0.25, [](C c) { return c.timeScale(); }},
        {"ball_count", "ballCountSpin", 12.0, 12.0, [](C c) { return double(c.spawn().count); }},
        {"fully_inside", "fullyInsideCheck", false, 0.0, [](C c) { return double(c.spawn().fullyInside); }},
        {"spawn_min_speed", "spawnMinSpeedSpin", 20.0, 20.0, [](C c) { return c.spawn().minSpeed; }},
        {"spawn_max_speed", "spawnMaxSpeedSpin", 500.0, 500.0, [](C c) { return c.spawn().maxSpeed; }},
    };
    return cases;
}

// Sets a widget as a user's finished edit would.
bool setWidget(QWidget* w, const QVariant& value)
{
    if (auto* spin = qobject_cast<QDoubleSpinBox*>(w)) {
        spin->setValue(value.toDouble());
    } else if (auto* combo = qobject_cast<QComboBox*>(w)) {
        const int i = combo->findText(value.toString());
        if (i < 0)
            return false;
        combo->setCurrentIndex(i);
    } else if (auto* check = qobject_cast<QCheckBox*>(w)) {
        check->setChecked(value.toBool());
    } else if (auto* group = qobject_cast<QGroupBox*>(w)) {
        group->setChecked(value.toBool());
    } else if (auto* edit = qobject_cast<QLineEdit*>(w)) {
        edit->setText(value.toString());
        emit edit->editingFinished();
    } else {
        return false;
    }
    return true;
}

bool sameBits(double a, double b)
{
    return std::memcmp(&a, &b, sizeof a) == 0;
}

// Every field of two settings structs, bit for bit; the first difference named.
QString settingsDifference(const sim::WorldSettings& a, const sim::WorldSettings& b)
{
#define SAME(f)                                                                                                        \
    if (!sameBits(double(a.f), double(b.f)))                                                                           \
        return QStringLiteral(#f ": %1 vs %2").arg(double(a.f), 0, 'g', 17).arg(double(b.f), 0, 'g', 17);
    SAME(box.width) SAME(box.height)
    SAME(walls.left) SAME(walls.right) SAME(walls.top) SAME(walls.bottom) SAME(walls.model) SAME(walls.restitution)
    SAME(walls.middle) SAME(walls.centreOnly)
    SAME(time.integrator) SAME(time.dt) SAME(time.substeps) SAME(time.tolerance) SAME(time.perFrame)
    SAME(time.stepPastClosePasses)
    if (a.time.seed != b.time.seed)
        return QStringLiteral("time.seed");
    SAME(gravity.enabled) SAME(gravity.g.x()) SAME(gravity.g.y())
    SAME(drag.enabled) SAME(drag.law) SAME(drag.k)
    SAME(wind.mode) SAME(wind.strength) SAME(wind.scale) SAME(wind.smoothedStep) SAME(wind.noiseFrequency)
    SAME(wind.compare)
    SAME(randomAccel.enabled) SAME(randomAccel.fixed) SAME(randomAccel.strength) SAME(randomAccel.uncentred)
    SAME(point.enabled) SAME(point.kind) SAME(point.position.x()) SAME(point.position.y()) SAME(point.strength)
    SAME(point.maxAccel) SAME(point.scale) SAME(point.unnormalised)
    SAME(spring.enabled) SAME(spring.anchor.x()) SAME(spring.anchor.y()) SAME(spring.k)
    SAME(mutualGravity.enabled) SAME(mutualGravity.G) SAME(mutualGravity.softening) SAME(magnetic.enabled) SAME(magnetic.B)
    SAME(homing.enabled) SAME(homing.strength)
    SAME(pointer.enabled) SAME(pointer.strength) SAME(pointer.maxAccel)
    SAME(speedLimit.enabled) SAME(speedLimit.max)
    SAME(collisions.detection) SAME(collisions.response) SAME(collisions.restitution) SAME(collisions.continuous)
    SAME(collisions.resting)
#undef SAME
    return {};
}

Lesson lessonOf(const sim::Scene& scene, const QStringList& controls = {})
{
    Lesson lesson;
    lesson.id = QStringLiteral("test-scene");
    lesson.title = QStringLiteral("Test scene");
    lesson.scene = scene;
    lesson.controls = controls;
    return lesson;
}

} // namespace

class GuiWorkbenchTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void tableCoversEveryControl();
    void slowestSpawnAboveFastestIsRefused();
    void manyLoadErrorsFitTheScreen();
    void hostileLessonsAreRefusedAndTheLessonStays();
    void eachControlEditsItsFieldAndUndoes_data();
    void eachControlEditsItsFieldAndUndoes();
    void everyRowRoundTripsThroughItsWidget();
    void sliderDragIsOneUndoStep();
    void logSliderSpansDecades();
    void outOfRangeIsReportedNotClamped();
    void resetRestoresTheLessonsValues();
    void lessonControlsComeFirst();
    void switchingLessonsUpdatesTheDocks();
    void shortcutsAct();
    void lessonSpeedIsRestoredAndSlowMotionGlides();
    void transportKeysActWhereverTheFocusIs();
    void lessonChangeGivesTheStageTheKeyboard();
    void saveThenOpenGivesTheSameScene();
    void lessonsTreeFollowsTheCourse();
    void inspectorShowsTheSelectedBall();
    void startSelectionFillsTheInspector();
    void screenshotAndTrajectoryFiles();
    void blowUpPausesAndExplains();
};

void GuiWorkbenchTest::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("ForceLabTest"));
    QCoreApplication::setApplicationName(QStringLiteral("test_gui_workbench"));
    QSettings().clear();
}

// A lesson file with a hundred problems: the dialog shows the first few and
// lists all of them under Show Details, so it never grows past the screen
// and its OK button stays on it.
void GuiWorkbenchTest::manyLoadErrorsFitTheScreen()
{
    QByteArray json = "{\"format\": 1, \"id\": \"t\"";
    for (int k = 0; k < 150; ++k)
        json += ", \"unknown_" + QByteArray::number(k) + "\": 1";
    const LoadResult bad = LessonLoader::loadBytes(json + "}", QStringLiteral("many.json"));
    QVERIFY(bad.errors().size() > 100);
    MainWindow window(QStringLiteral("gravity"));
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    int height = 0, screenHeight = 0;
    QString details;
    bool seen = false;
    QTimer::singleShot(0, &window, [&] {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        if (!box)
            return;
        seen = true;
        height = box->frameGeometry().height();
        screenHeight = box->screen()->availableGeometry().height();
        details = box->detailedText();
        box->accept();
    });
    window.showLoadErrors(bad.errors());
    QVERIFY(seen);
    QVERIFY2(height <= screenHeight, qPrintable(QStringLiteral("%1 > %2").arg(height).arg(screenHeight)));
    for (const QString& line : bad.errors())
        QVERIFY2(details.contains(line), qPrintable(line));
}

// Every file of the hostile-lesson corpus (tests/hostile), opened in the
// workbench: each is refused with the Cannot-open dialog (a hang would be the
// test's time-out) and the lesson that ran before runs on, unchanged. Before,
// the dialog itself rendered the quoted <img src="/dev/zero"> and hung.
void GuiWorkbenchTest::hostileLessonsAreRefusedAndTheLessonStays()
{
    MainWindow window(QStringLiteral("gravity"));
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    const QString before = window.lesson().id;
    const int balls = window.controller()->world().balls().size();
    const QDir dir(QStringLiteral(FORCELAB_HOSTILE_DIR));
    const QStringList files = dir.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name);
    QVERIFY(files.size() >= 25);
    for (const QString& name : files) {
        if (name == QLatin1String("ok.json") || name.startsWith(QLatin1String("runtime-")))
            continue; // these load; they stop when run
        QString shown;
        QTimer poll; // closes the dialog as soon as it is up
        connect(&poll, &QTimer::timeout, &window, [&] {
            if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
                // What the reader sees: the file's quote as characters, never rendered.
                if (auto* label = box->findChild<QLabel*>(QStringLiteral("qt_msgbox_informativelabel")))
                    shown = label->text();
                box->accept();
            }
        });
        poll.start(5);
        QVERIFY2(!window.openLesson(dir.filePath(name)), qPrintable(name));
        poll.stop();
        QVERIFY2(!shown.isEmpty(), qPrintable(name));
        // A quoted tag reaches the label only escaped: the dialog loads no picture.
        QVERIFY2(!shown.contains(QStringLiteral("<img")) && !shown.contains(QStringLiteral("<a ")), qPrintable(shown));
        QCOMPARE(window.lesson().id, before);
        QCOMPARE(window.controller()->world().balls().size(), balls);
    }
}

// Stage 2 asks to change the spawn speed range: a slowest speed typed above
// the fastest is refused with a message naming the field, and the range and
// the balls stay as they were (nothing clamped).
void GuiWorkbenchTest::slowestSpawnAboveFastestIsRefused()
{
    PanelBench bench;
    QVERIFY(bench.sceneSet);
    auto* slowest = bench.panel.findChild<QDoubleSpinBox*>(QStringLiteral("spawnMinSpeedSpin"));
    QVERIFY(slowest);
    const sim::SpawnSettings before = bench.controller.spawn();
    const int steps = bench.editor.undoStack()->count();
    QVERIFY(setWidget(slowest, before.maxSpeed + 100.0));
    QCOMPARE(bench.errors.count(), 1);
    QVERIFY2(bench.errors.first().first().toString().contains(QStringLiteral("spawn.speed")),
             qPrintable(bench.errors.first().first().toString()));
    QCOMPARE(bench.controller.spawn().minSpeed, before.minSpeed);
    QCOMPARE(bench.controller.spawn().maxSpeed, before.maxSpeed);
    QCOMPARE(slowest->value(), before.minSpeed); // the field shows the range that stands
    QCOMPARE(bench.editor.undoStack()->count(), steps);
}

void GuiWorkbenchTest::tableCoversEveryControl()
{
    // "Every parameter": each row of the panel has at least one case below,
    // and every control name a lesson may list shows at least one row.
    SimulationController controller;
    SettingsEditor editor(&controller);
    ParameterPanel panel(&controller, &editor);
    QStringList covered;
    for (const ControlCase& c : controlCases())
        covered.append(QString::fromLatin1(c.row));
    for (const QString& row : panel.rowKeys())
        QVERIFY2(covered.contains(row), qPrintable(row));
    for (const QString& name : LessonLoader::controlNames()) {
        const QStringList rows = ParameterPanel::rowsForControl(name);
        QVERIFY2(!rows.isEmpty(), qPrintable(name));
        for (const QString& row : rows)
            QVERIFY2(panel.rowKeys().contains(row), qPrintable(row));
    }
    // Every row of the parameter table has its control in the panel: a row
    // of its own, a model's tick box (its section), or the wall switches.
    panel.setShowAll(true);
    const QStringList sections = panel.visibleSections();
    for (const sim::Parameter& p : sim::parameters()) {
        const QString key = QString::fromUtf8(p.key.data(), static_cast<qsizetype>(p.key.size()));
        if (key.startsWith(QStringLiteral("world.walls.")))
            QVERIFY(panel.rowKeys().contains(QStringLiteral("wall_sides")));
        else if (key.endsWith(QStringLiteral(".enabled"))) // "models.drag.enabled": the "drag" section's tick box
            QVERIFY2(sections.contains(key.section(QLatin1Char('.'), 1, 1)), qPrintable(key));
        else
            QVERIFY2(panel.rowKeys().contains(QString::fromUtf8(p.control.data(), static_cast<qsizetype>(p.control.size()))),
                     qPrintable(key));        // The widget that edits it, whatever kind it is.
        QVERIFY2(panel.controlWidget(QString::fromUtf8(p.control.data(), static_cast<qsizetype>(p.control.size()))),
                 qPrintable(key));
    }
}

void GuiWorkbenchTest::eachControlEditsItsFieldAndUndoes_data()
{
    QTest::addColumn<int>("index");
    for (std::size_t i = 0; i < controlCases().size(); ++i)
        QTest::newRow(controlCases()[i].widget) << int(i);
}

void GuiWorkbenchTest::eachControlEditsItsFieldAndUndoes()
{
    QFETCH(int, index);
    const ControlCase& c = controlCases()[std::size_t(index)];
    PanelBench bench;
    QVERIFY(bench.sceneSet);
    SimulationController& controller = bench.controller;
    SettingsEditor& editor = bench.editor;
    ParameterPanel& panel = bench.panel;
    QSignalSpy& errors = bench.errors;

    QWidget* w = panel.findChild<QWidget*>(QString::fromLatin1(c.widget));
    QVERIFY2(w, c.widget);
    const double before = c.field(controller);
    QVERIFY2(before != c.expected, "the case must change the field");
    const int steps = editor.undoStack()->count();

    QVERIFY(setWidget(w, c.value));
    QVERIFY2(errors.isEmpty(), errors.isEmpty() ? "" : qPrintable(errors.first().first().toString()));
    QCOMPARE(c.field(controller), c.expected);
    QCOMPARE(editor.undoStack()->count(), steps + 1);

    editor.undoStack()->undo();
    QCOMPARE(c.field(controller), before);
    editor.undoStack()->redo();
    QCOMPARE(c.field(controller), c.expected);
    QCOMPARE(errors.count(), 0);

    if (QString::fromLatin1(c.row) == QStringLiteral("ball_count"))
        QCOMPARE(controller.world().balls().size(), 2 + 12); // the listed two and twelve placed at random
}

// The third text-free path of every row of the parameter table (the loader
// test walks the file and --set): its widget in the panel, found by the name
// the panel gives it, edited as a user would, lands in the row's field; one
// undo puts the default back. Number fields show a rounded value, so the
// field must equal what the spin box shows, and that must be within half a
// shown digit of the value asked for.
void GuiWorkbenchTest::everyRowRoundTripsThroughItsWidget()
{
    // Every model on, so that no row's widget is greyed out by its model's tick box.
    sim::Scene scene = plainScene();
    for (const sim::Parameter& p : sim::parameters())
        if (p.key.ends_with(".enabled"))
            p.set(scene.settings, 1.0);
    SimulationController controller;
    QVERIFY(!controller.setScene(scene));
    SettingsEditor editor(&controller);
    ParameterPanel panel(&controller, &editor);
    panel.setShowAll(true);
    QSignalSpy errors(&controller, &SimulationController::errorOccurred);
    int checked = 0;
    for (const sim::Parameter& p : sim::parameters()) {
        const QString key = QString::fromUtf8(p.key.data(), static_cast<qsizetype>(p.key.size()));
        if (key.startsWith(QStringLiteral("world.walls.")) || key.endsWith(QStringLiteral(".enabled")))
            continue; // the wall switches and the model tick boxes: see tableCoversEveryControl
        const QString stem = ParameterPanel::objectStem(p.control);
        const double before = p.get(controller.world().settings());
        const double wanted = forcelab::test::anotherValue(p, before);
        const int steps = editor.undoStack()->index();
        if (p.type == sim::ParameterType::Boolean) {
            auto* box = panel.findChild<QCheckBox*>(stem + QStringLiteral("Check"));
            QVERIFY2(box, qPrintable(key));
            box->click();
            QVERIFY2(p.get(controller.world().settings()) == wanted, qPrintable(key));
        } else if (p.type == sim::ParameterType::Choice) {
            auto* combo = panel.findChild<QComboBox*>(stem + QStringLiteral("Combo"));
            QVERIFY2(combo, qPrintable(key));
            combo->setCurrentIndex(static_cast<int>(wanted));
            QVERIFY2(p.get(controller.world().settings()) == wanted, qPrintable(key));
        } else {
            auto* control = panel.findChild<NumberControl*>(stem + QStringLiteral("Control"));
            QVERIFY2(control, qPrintable(key));
            const double toShown = key == QStringLiteral("time.dt") ? 1e3 : 1.0; // dt is shown in ms
            control->spinBox()->setValue(wanted * toShown);
            const double shown = control->spinBox()->value() / toShown;
            QVERIFY2(sameBits(p.get(controller.world().settings()), shown), qPrintable(key));
            const double digit = std::pow(10.0, -control->spinBox()->decimals()) / toShown;
            const double significant = std::abs(wanted) * 5e-4; // four significant figures on log rows
            QVERIFY2(std::abs(shown - wanted) <= std::max(0.5 * digit, significant) * (1 + 1e-12),
                     qPrintable(QStringLiteral("%1: asked %2, shown %3").arg(key).arg(wanted).arg(shown)));
        }
        QVERIFY2(editor.undoStack()->index() == steps + 1, qPrintable(key + QStringLiteral(": not one undo step")));
        editor.undoStack()->undo();
        QVERIFY2(sameBits(p.get(controller.world().settings()), before), qPrintable(key));
        ++checked;
    }
    QVERIFY2(errors.isEmpty(), errors.isEmpty() ? "" : qPrintable(errors.first().first().toString()));
    qInfo("%d rows edited through their widgets", checked);
    QVERIFY(checked >= 40);
}

void GuiWorkbenchTest::sliderDragIsOneUndoStep()
{
    SimulationController controller;
    QVERIFY(!controller.setScene(plainScene()));
    SettingsEditor editor(&controller);
    ParameterPanel panel(&controller, &editor);
    auto* slider = panel.findChild<QSlider*>(QStringLiteral("gravityYSlider"));
    QVERIFY(slider);
    const double g0 = controller.world().settings().gravity.g.y();

    // One drag: three moves, each live in the world, one undo step.
    slider->setSliderDown(true);
    for (int p : {600, 700, 800}) {
        slider->setValue(p);
        const double want = -2000.0 + 4000.0 * p / NumberControl::kSteps;
        QCOMPARE(controller.world().settings().gravity.g.y(), want);
    }
    slider->setSliderDown(false);
    QCOMPARE(editor.undoStack()->count(), 1);
    // A second drag of the same slider is a step of its own.
    slider->setSliderDown(true);
    slider->setValue(900);
    slider->setSliderDown(false);
    QCOMPARE(editor.undoStack()->count(), 2);
    editor.undoStack()->undo();
    QCOMPARE(controller.world().settings().gravity.g.y(), 1200.0);
    editor.undoStack()->undo();
    QCOMPARE(controller.world().settings().gravity.g.y(), g0);
}

void GuiWorkbenchTest::logSliderSpansDecades()
{
    SimulationController controller;
    SettingsEditor editor(&controller);
    ParameterPanel panel(&controller, &editor);
    auto* control = panel.findChild<NumberControl*>(QStringLiteral("mutualGControl"));
    QVERIFY(control);
    // 1 … 1e8 over the slider: each eighth of the travel is a factor of 10.
    QCOMPARE(control->valueAt(0), 1.0);
    QVERIFY(std::abs(control->valueAt(NumberControl::kSteps / 8) / 10.0 - 1.0) < 1e-12);
    QVERIFY(std::abs(control->valueAt(NumberControl::kSteps / 2) / 1e4 - 1.0) < 1e-12);
    QCOMPARE(control->positionFor(1e4), NumberControl::kSteps / 2);
    QCOMPARE(control->positionFor(1e8), NumberControl::kSteps);
    // The spin box still takes values the slider does not reach.
    auto* spin = control->spinBox();
    spin->setValue(-3e9);
    QCOMPARE(controller.world().settings().mutualGravity.G, -3e9);
    QCOMPARE(control->slider()->value(), 0);
}

void GuiWorkbenchTest::outOfRangeIsReportedNotClamped()
{
    MainWindow window(QString(), nullptr);
    QVERIFY(window.setLesson(lessonOf(plainScene())));
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.parameterPanel()->setShowAll(true);
    QSignalSpy errors(window.controller(), &SimulationController::errorOccurred);

    // Typed 1.5 for a restitution in [0, 1]: refused by the world, said in the
    // status bar, the box back at the world's value.
    auto* spin = window.parameterPanel()->findChild<NumberSpinBox*>(QStringLiteral("wallRestitutionSpin"));
    QVERIFY(spin);
    const double before = window.controller()->world().settings().walls.restitution;
    spin->setFocus();
    spin->selectAll();
    QTest::keyClicks(spin, QStringLiteral("1.5"));
    QTest::keyClick(spin, Qt::Key_Return);
    QCOMPARE(errors.count(), 1);
    QVERIFY2(errors.first().first().toString().startsWith(QStringLiteral("world.restitution: 1.5")),
             qPrintable(errors.first().first().toString()));
    QVERIFY(window.statusBar()->currentMessage().contains(QStringLiteral("world.restitution")));
    QCOMPARE(window.controller()->world().settings().walls.restitution, before);
    QCOMPARE(spin->value(), before);
    QCOMPARE(window.parameterPanel()->editor()->undoStack()->count(), 0);

    // dt = 0 ms: the interval (0, 1] s is open at 0.
    auto* dt = window.parameterPanel()->findChild<NumberSpinBox*>(QStringLiteral("dtSpin"));
    QVERIFY(dt);
    dt->setValue(0.0);
    QCOMPARE(errors.count(), 2);
    QVERIFY(errors.last().first().toString().startsWith(QStringLiteral("time.dt")));
    QCOMPARE(window.controller()->world().settings().time.dt, 1.0 / 60.0);
    QCOMPARE(dt->value(), 1000.0 / 60.0);
}

void GuiWorkbenchTest::resetRestoresTheLessonsValues()
{
    MainWindow window;
    QVERIFY(window.openLesson(QStringLiteral("gravity")));
    const sim::WorldSettings lesson = window.lesson().scene.settings;
    ParameterPanel* panel = window.parameterPanel();
    panel->setShowAll(true);
    QVERIFY(setWidget(panel->findChild<QWidget*>(QStringLiteral("gravityYSpin")), 123.0));
    QVERIFY(setWidget(panel->findChild<QWidget*>(QStringLiteral("wallRestitutionSpin")), 0.25));
    QVERIFY(setWidget(panel->findChild<QWidget*>(QStringLiteral("dragGroup")), true));
    QVERIFY(setWidget(panel->findChild<QWidget*>(QStringLiteral("ballCountSpin")), 7.0));
    QVERIFY(!settingsDifference(window.controller()->world().settings(), lesson).isEmpty());

    window.findChild<QAction*>(QStringLiteral("resetAction"))->trigger();
    QCOMPARE(settingsDifference(window.controller()->world().settings(), lesson), QString());
    QCOMPARE(window.controller()->spawn().count, window.lesson().scene.spawn.count);
    QCOMPARE(window.controller()->world().time(), 0.0);
    auto* gy = panel->findChild<QDoubleSpinBox*>(QStringLiteral("gravityYSpin"));
    // In the units the lesson speaks (07: SI, 980 px/s² shown as 9.8 m/s²).
    QCOMPARE(gy->value(), toShown(lesson.gravity.g.y(), QStringLiteral("px/s²")));
    QCOMPARE(panel->editor()->undoStack()->count(), 0);
}

void GuiWorkbenchTest::lessonControlsComeFirst()
{
    SimulationController controller;
    SettingsEditor editor(&controller);
    ParameterPanel panel(&controller, &editor);
    // The lesson's rows in its order, the speed always, nothing else.
    QTest::ignoreMessage(QtWarningMsg, QRegularExpression(QStringLiteral("\"no_such_control\".*ignored")));
    panel.setLessonControls({QStringLiteral("dt"), QStringLiteral("no_such_control"), QStringLiteral("gravity")});
    QCOMPARE(panel.lessonControls(), (QStringList{QStringLiteral("dt"), QStringLiteral("gravity")}));
    QCOMPARE(panel.visibleSections(), (QStringList{QStringLiteral("time"), QStringLiteral("gravity")}));
    QCOMPARE(panel.visibleRows(), (QStringList{QStringLiteral("time_scale"), QStringLiteral("dt"),
                                               QStringLiteral("gravity_x"), QStringLiteral("gravity_y")}));
    // Show all: the same first, then everything else.
    panel.findChild<QCheckBox*>(QStringLiteral("showAllCheck"))->setChecked(true);
    QVERIFY(panel.showAll());
    const QStringList all = panel.visibleRows();
    QCOMPARE(all.size(), panel.rowKeys().size());
    QCOMPARE(all.mid(0, 2), (QStringList{QStringLiteral("time_scale"), QStringLiteral("integrator")}));
    QCOMPARE(panel.visibleSections().mid(0, 2), (QStringList{QStringLiteral("time"), QStringLiteral("gravity")}));
}

void GuiWorkbenchTest::switchingLessonsUpdatesTheDocks()
{
    MainWindow window;
    for (const QString& id : {QStringLiteral("gravity"), QStringLiteral("drag"), QStringLiteral("showcase")}) {
        QVERIFY(window.openLesson(id));
        const Lesson& lesson = window.lesson();
        // Lessons dock: the lesson selected, its text and challenges shown.
        LessonsDock* lessons = window.lessonsDock();
        QCOMPARE(lessons->currentSource(), lesson.source);
        QTreeWidgetItem* current = lessons->tree()->currentItem();
        QVERIFY(current);
        QVERIFY(current->text(0).contains(lesson.title));
        const QString text = lessons->textBrowser()->toPlainText();
        QVERIFY(text.contains(lesson.title));
        for (const QString& challenge : lesson.challenges)
            QVERIFY(text.contains(challenge.left(30)));
        // Parameters: the lesson's controls, and their rows first.
        ParameterPanel* panel = window.parameterPanel();
        QCOMPARE(panel->lessonControls(), lesson.controls);
        QStringList expected{QStringLiteral("time_scale")}; // always shown
        for (const QString& control : lesson.controls)
            for (const QString& row : ParameterPanel::rowsForControl(control))
                if (!expected.contains(row))
                    expected.append(row);
        const QStringList shown = panel->visibleRows();
        QCOMPARE(shown.size(), expected.size());
        for (const QString& row : expected)
            QVERIFY2(shown.contains(row), qPrintable(row));
        // The first visible row belongs to the lesson's first control (or is the
        // speed when that control's section is Time).
        const QString firstRow = shown.first();
        QVERIFY2(ParameterPanel::rowsForControl(lesson.controls.first()).contains(firstRow) ||
                     firstRow == QStringLiteral("time_scale"),
                 qPrintable(firstRow));
        // The values are the lesson's.
        auto* gy = panel->findChild<QDoubleSpinBox*>(QStringLiteral("gravityYSpin"));
        QCOMPARE(gy->value(), toShown(lesson.scene.settings.gravity.g.y(), QStringLiteral("px/s²"))); // SI in 07
        QCOMPARE(window.windowTitle(), QStringLiteral("%1 — ForceLab").arg(lesson.title));
    }
}

// With the keyboard in the Speed field, a lesson change hands it to the
// canvas, so Space pauses instead of being typed into the field.
void GuiWorkbenchTest::lessonChangeGivesTheStageTheKeyboard()
{
    MainWindow window;
    QVERIFY(window.setLesson(lessonOf(plainScene())));
    window.show();
    QVERIFY(QTest::qWaitForWindowActive(&window));
    auto* speed = window.parameterPanel()->findChild<QDoubleSpinBox*>(QStringLiteral("timeScaleSpin"));
    QVERIFY(speed);
    speed->setFocus();
    QTRY_VERIFY(speed->hasFocus());
    QVERIFY(window.openLesson(QStringLiteral("gravity")));
    QTRY_VERIFY(window.canvas()->hasFocus());
    SimulationController* controller = window.controller();
    QVERIFY(!controller->isPlaying()); // a lesson waits at t = 0
    QVERIFY(window.canvas()->showsStartHint());
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Space);
    QVERIFY(controller->isPlaying());
    QCOMPARE(controller->timeScale(), 1.0); // the Speed field was not typed into
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Space);
    QVERIFY(!controller->isPlaying());
}

// Reset and a lesson change bring the lesson's own speed (1×) back; in slow
// motion the canvas draws the balls between the last two steps, a share α of
// the way, instead of jumping once every few frames.
void GuiWorkbenchTest::lessonSpeedIsRestoredAndSlowMotionGlides()
{
    MainWindow window;
    QVERIFY(window.setLesson(lessonOf(plainScene())));
    SimulationController* controller = window.controller();
    controller->setTimeScale(1.0 / 16);
    window.findChild<QAction*>(QStringLiteral("resetAction"))->trigger();
    QCOMPARE(controller->timeScale(), 1.0);
    controller->setTimeScale(0.25);
    QVERIFY(window.openLesson(QStringLiteral("gravity")));
    QCOMPARE(controller->timeScale(), 1.0);

    SimulationController slow;
    QVERIFY(!slow.setScene(plainScene()));
    const double dt = slow.world().settings().time.dt;
    slow.setTimeScale(0.25);
    slow.play();
    QSignalSpy frames(&slow, &SimulationController::framePassed);
    QCOMPARE(slow.advance(dt), 0); // a quarter step of simulated time: no step yet
    QCOMPARE(frames.count(), 1);
    QVERIFY(!slow.interpolatedPositions()); // nothing to blend with before the first step
    QCOMPARE(slow.advance(3 * dt), 1);      // the quarter steps add up to one step
    const sim::Matrix2X before = slow.world().balls().position; // after the step
    QCOMPARE(slow.advance(dt), 0);          // α = 1/4 into the next step
    const sim::Matrix2X* drawn = slow.interpolatedPositions();
    QVERIFY(drawn);
    // The drawn ball is a quarter of the way from the last step's start to its end.
    const sim::Vec2 v = slow.world().balls().velocity.col(0);
    const sim::Vec2 start = before.col(0) - v * dt; // free flight: the step moved it by v dt
    QVERIFY2((drawn->col(0) - (start + 0.25 * (before.col(0) - start))).norm() < 1e-9,
             qPrintable(QStringLiteral("drawn at (%1, %2)").arg(drawn->coeff(0, 0)).arg(drawn->coeff(1, 0))));
    slow.pause();
    QVERIFY(!slow.interpolatedPositions()); // paused: the true positions
}

// Space runs and pauses, R resets, whatever control has the keyboard (a
// check box, a slider, a combo box), except a text field being edited; on a
// slider the arrows move the slider, as sliders do.
void GuiWorkbenchTest::transportKeysActWhereverTheFocusIs()
{
    sim::Scene scene = plainScene();
    scene.settings.gravity.enabled = true;
    MainWindow window;
    QVERIFY(window.setLesson(lessonOf(scene, {QStringLiteral("gravity"), QStringLiteral("integrator")})));
    window.show();
    QVERIFY(QTest::qWaitForWindowActive(&window));
    SimulationController* controller = window.controller();
    window.parameterPanel()->setShowAll(true);
    const QStringList focusables{QStringLiteral("gravityYSlider"), QStringLiteral("integratorCombo"),
                                 QStringLiteral("showAllCheck")};
    for (const QString& name : focusables) {
        QWidget* w = window.findChild<QWidget*>(name);
        QVERIFY2(w, qPrintable(name));
        w->setFocus();
        QTRY_VERIFY2(w->hasFocus(), qPrintable(name));
        const bool playing = controller->isPlaying();
        QTest::keyClick(w, Qt::Key_Space);
        QVERIFY2(controller->isPlaying() != playing, qPrintable(name + ": Space did not run or pause"));
        controller->pause();
        controller->stepOnce();
        QVERIFY(controller->world().time() > 0.0);
        QTest::keyClick(w, Qt::Key_R);
        QVERIFY2(controller->world().time() == 0.0, qPrintable(name + ": R did not reset"));
    }
    // On a slider the arrows, Page Up / Down and Home / End belong to the
    // slider: an arrow moves a hundredth of the travel, Shift + arrow a
    // thousandth, Page Up a twentieth; the world does not step.
    auto* slider = window.findChild<QSlider*>(QStringLiteral("gravityYSlider"));
    slider->setFocus();
    QTRY_VERIFY(slider->hasFocus());
    int at = slider->value();
    QTest::keyClick(slider, Qt::Key_Right);
    QCOMPARE(slider->value(), at + NumberControl::kSteps / 100);
    at = slider->value();
    QTest::keyClick(slider, Qt::Key_Left, Qt::ShiftModifier);
    QCOMPARE(slider->value(), at - 1);
    at = slider->value();
    QTest::keyClick(slider, Qt::Key_PageUp);
    QCOMPARE(slider->value(), at + NumberControl::kSteps / 20);
    QTest::keyClick(slider, Qt::Key_End);
    QCOMPARE(slider->value(), NumberControl::kSteps);
    QTest::keyClick(slider, Qt::Key_Home);
    QCOMPARE(slider->value(), 0);
    QCOMPARE(controller->world().time(), 0.0);
    // Away from a slider, → steps the world.
    window.canvas()->setFocus();
    QTest::keyClick(window.canvas(), Qt::Key_Right);
    QVERIFY(controller->world().time() > 0.0);
    // Every control a keyboard can reach has an accessible name.
    QStringList unnamed;
    for (QWidget* w : window.findChildren<QWidget*>()) {
        if (w->focusPolicy() == Qt::NoFocus || !w->isVisible() || qobject_cast<QScrollBar*>(w) ||
            w->inherits("QLineEdit") || w->inherits("QTabBar") || w->inherits("QDockWidget") ||
            w->inherits("QAbstractScrollArea") || w->inherits("QChartView") || w->inherits("QMainWindow") ||
            (w->parentWidget() && w->parentWidget()->inherits("QChartView"))) // a chart's viewport: the chart is named
            continue;
        QString name = w->accessibleName();
        for (const char* shown : {"text", "title", "currentText"}) // what Qt's accessibility reads when no name is set
            if (name.isEmpty())
                name = w->property(shown).toString();
        if (name.isEmpty())
            unnamed << QStringLiteral("%1 (%2 in %3)")
                           .arg(w->objectName(), QString::fromLatin1(w->metaObject()->className()),
                                w->parentWidget() ? QString::fromLatin1(w->parentWidget()->metaObject()->className())
                                                  : QString());
    }
    QVERIFY2(unnamed.isEmpty(), qPrintable(QStringLiteral("no accessible name: ") + unnamed.join(", ")));
    // In a text field Space is typed.
    auto* spin = window.findChild<QDoubleSpinBox*>(QStringLiteral("gravityYSpin"));
    spin->setFocus();
    QTRY_VERIFY(spin->hasFocus());
    const bool playing = controller->isPlaying();
    QTest::keyClick(spin, Qt::Key_Space);
    QCOMPARE(controller->isPlaying(), playing);
}

void GuiWorkbenchTest::shortcutsAct()
{
    MainWindow window;
    QVERIFY(window.setLesson(lessonOf(plainScene())));
    window.show();
    QVERIFY(QTest::qWaitForWindowActive(&window));
    window.canvas()->setFocus();
    SimulationController* controller = window.controller();
    controller->pause();

    // [ and ]: down and up the ladder 1/16, 1/8, 1/4, 1/2, 1, 2, 4, 8, 16.
    QCOMPARE(controller->timeScale(), 1.0);
    QTest::keyClick(&window, Qt::Key_BracketLeft);
    QCOMPARE(controller->timeScale(), 0.5);
    QTest::keyClick(&window, Qt::Key_BracketRight);
    QTest::keyClick(&window, Qt::Key_BracketRight);
    QCOMPARE(controller->timeScale(), 2.0);
    for (int k = 0; k < 6; ++k)
        QTest::keyClick(&window, Qt::Key_BracketRight);
    QCOMPARE(controller->timeScale(), 16.0);
    for (int k = 0; k < 12; ++k)
        QTest::keyClick(&window, Qt::Key_BracketLeft);
    QCOMPARE(controller->timeScale(), 1.0 / 16);
    // From a speed typed between rungs (0.05×), Faster goes to the next rung
    // and on through 1× (before: 0.1, 0.2, 0.4, 0.8, 1.6, never 1).
    controller->setTimeScale(0.05);
    const double ladder[] = {1.0 / 16, 1.0 / 8, 0.25, 0.5, 1.0};
    for (const double rung : ladder) {
        QTest::keyClick(&window, Qt::Key_BracketRight);
        QCOMPARE(controller->timeScale(), rung);
    }

    // Ctrl+Z / Ctrl+Shift+Z: undo and redo a parameter edit.
    auto* gy = window.parameterPanel()->findChild<QDoubleSpinBox*>(QStringLiteral("gravityYSpin"));
    window.parameterPanel()->setShowAll(true);
    const double g0 = controller->world().settings().gravity.g.y();
    gy->setValue(321.0);
    QCOMPARE(controller->world().settings().gravity.g.y(), 321.0);
    window.canvas()->setFocus();
    QTest::keyClick(&window, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(controller->world().settings().gravity.g.y(), g0);
    QCOMPARE(gy->value(), g0);
    QTest::keyClick(&window, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(controller->world().settings().gravity.g.y(), 321.0);
    // The speed changes were undo steps too: undo the last one.
    QTest::keyClick(&window, Qt::Key_Z, Qt::ControlModifier); // gravity
    QTest::keyClick(&window, Qt::Key_Z, Qt::ControlModifier); // the last "]": 0.5 → 1
    QCOMPARE(controller->timeScale(), 0.5);

    // Space plays, → steps, R resets (the lesson's own values).
    QTest::keyClick(&window, Qt::Key_Space);
    QVERIFY(controller->isPlaying());
    QTest::keyClick(&window, Qt::Key_Right);
    QVERIFY(!controller->isPlaying());
    QVERIFY(controller->world().stepCount() >= 1);
    gy->setValue(777.0);
    window.canvas()->setFocus();
    QTest::keyClick(&window, Qt::Key_R);
    QCOMPARE(controller->world().time(), 0.0);
    QCOMPARE(controller->world().settings().gravity.g.y(), g0);

    // Every shortcut belongs to one action, shown in a menu.
    for (const char* name : {"playAction", "stepAction", "resetAction", "slowerAction", "fasterAction", "undoAction",
                             "redoAction", "openAction", "saveAction", "screenshotAction", "exportAction",
                             "presentationAction", "previousLessonAction", "nextLessonAction"}) {
        auto* action = window.findChild<QAction*>(QString::fromLatin1(name));
        QVERIFY2(action, name);
        QVERIFY2(!action->shortcut().isEmpty(), name);
        QVERIFY2(!action->associatedObjects().isEmpty(), name);
    }
    QCOMPARE(window.findChild<QAction*>(QStringLiteral("openAction"))->shortcut(), QKeySequence(QKeySequence::Open));
    QCOMPARE(window.findChild<QAction*>(QStringLiteral("saveAction"))->shortcut(), QKeySequence(QKeySequence::Save));
    QCOMPARE(window.findChild<QAction*>(QStringLiteral("presentationAction"))->shortcut(), QKeySequence(Qt::Key_F11));
    controller->pause();
}

void GuiWorkbenchTest::saveThenOpenGivesTheSameScene()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    MainWindow window;
    QVERIFY(window.openLesson(QStringLiteral("showcase")));
    SimulationController* controller = window.controller();
    controller->pause();
    // Change a few settings live and let the balls move, so the saved scene
    // differs from the lesson's start in both settings and balls.
    window.parameterPanel()->setShowAll(true);
    QVERIFY(setWidget(window.parameterPanel()->findChild<QWidget*>(QStringLiteral("gravityGroup")), true));
    QVERIFY(setWidget(window.parameterPanel()->findChild<QWidget*>(QStringLiteral("gravityYSpin")), 321.5));
    QVERIFY(setWidget(window.parameterPanel()->findChild<QWidget*>(QStringLiteral("integratorCombo")), "rk4"));
    for (int k = 0; k < 37; ++k)
        controller->stepOnce();
    const sim::WorldSettings settings = controller->world().settings();
    const sim::BallState balls = controller->world().balls();
    QVERIFY(balls.size() > 100);

    const QString path = dir.filePath(QStringLiteral("my-scene.json"));
    QVERIFY(window.saveLessonTo(path));
    QVERIFY(window.openLesson(path));
    QCOMPARE(window.lesson().source, path);
    QCOMPARE(window.lesson().id, QStringLiteral("my-scene"));
    QCOMPARE(window.lesson().scene.spawn.count, 0);
    QCOMPARE(window.lesson().controls, LessonLoader::load(QStringLiteral("showcase")).lesson->controls);

    const sim::World& world = controller->world();
    QCOMPARE(settingsDifference(world.settings(), settings), QString());
    QCOMPARE(world.balls().size(), balls.size());
    for (int i = 0; i < balls.size(); ++i) {
        const sim::Ball a = balls.ball(i), b = world.balls().ball(i);
        QVERIFY2(sameBits(a.position.x(), b.position.x()) && sameBits(a.position.y(), b.position.y()) &&
                     sameBits(a.velocity.x(), b.velocity.x()) && sameBits(a.velocity.y(), b.velocity.y()) &&
                     sameBits(a.radius, b.radius) && sameBits(a.mass, b.mass) && a.color == b.color &&
                     sameBits(a.home.x(), b.home.x()) && sameBits(a.home.y(), b.home.y()),
                 qPrintable(QStringLiteral("ball %1").arg(i)));
    }
    // Saving the reopened scene with the same title and text writes the same
    // file, but for the id: a saved lesson never takes the id of the one it
    // was made from.
    const QString again = dir.filePath(QStringLiteral("my-scene-again.json"));
    QFile first(path);
    QVERIFY(first.open(QIODevice::ReadOnly));
    QByteArray bytes = first.readAll();
    first.close();
    bytes.replace("\"id\": \"my-scene\"", "\"id\": \"my-scene-again\"");
    const Lesson showcase = *LessonLoader::load(QStringLiteral("showcase")).lesson;
    QVERIFY(window.saveLessonTo(again, lessons::defaultDeriveChoices(showcase)));
    QFile second(again);
    QVERIFY(second.open(QIODevice::ReadOnly));
    QCOMPARE(second.readAll(), bytes);
}

void GuiWorkbenchTest::lessonsTreeFollowsTheCourse()
{
    MainWindow window;
    LessonsDock* dock = window.lessonsDock();
    const QStringList order = dock->order();
    const QStringList files = LessonLoader::builtInFiles();
    QCOMPARE(order.size(), files.size());

    // The showcase first; then parts A, B, C and beyond, stages rising.
    QTreeWidget* tree = dock->tree();
    QVERIFY(tree->topLevelItemCount() >= 2);
    QCOMPARE(tree->topLevelItem(0)->childCount(), 0);
    int lastStage = -1;
    int lastPart = 0;
    for (const QString& source : order) {
        const LoadResult r = LessonLoader::load(source);
        QVERIFY2(r.ok(), qPrintable(source));
        QVERIFY2(r.lesson->stage >= lastStage, qPrintable(source));
        QVERIFY(LessonsDock::partOf(r.lesson->stage) >= lastPart);
        lastStage = r.lesson->stage;
        lastPart = LessonsDock::partOf(r.lesson->stage);
    }
    QCOMPARE(LessonLoader::load(order.first()).lesson->stage, 0);
    for (int i = 1; i < tree->topLevelItemCount(); ++i) {
        QTreeWidgetItem* part = tree->topLevelItem(i);
        const QString name = part->text(0);
        for (int j = 0; j < part->childCount(); ++j) {
            const int stage = LessonLoader::load(part->child(j)->data(0, Qt::UserRole).toString()).lesson->stage;
            if (name.startsWith(QStringLiteral("Part A")))
                QVERIFY(stage >= 1 && stage <= 9);
            else if (name.startsWith(QStringLiteral("Part B")))
                QVERIFY(stage >= 10 && stage <= 22);
            else if (name.startsWith(QStringLiteral("Part C")))
                QVERIFY(stage >= 23 && stage <= 29);
            else
                QVERIFY(stage >= 30);
        }
    }

    // Next and Previous walk the same order; the ends switch the buttons off.
    QVERIFY(window.openLesson(order.first()));
    auto* next = window.findChild<QAction*>(QStringLiteral("nextLessonAction"));
    auto* previous = window.findChild<QAction*>(QStringLiteral("previousLessonAction"));
    QVERIFY(!previous->isEnabled());
    const int walk = std::min<int>(5, int(order.size()) - 1);
    for (int i = 1; i <= walk; ++i) {
        next->trigger();
        QCOMPARE(window.lesson().source, order.at(i));
        QCOMPARE(dock->tree()->currentItem()->data(0, Qt::UserRole).toString(), order.at(i));
    }
    previous->trigger();
    QCOMPARE(window.lesson().source, order.at(walk - 1));
    QVERIFY(window.openLesson(order.last()));
    QVERIFY(!next->isEnabled());
    QVERIFY(previous->isEnabled());

    // Clicking an entry opens it.
    QTreeWidgetItem* item = tree->topLevelItem(0);
    emit tree->itemActivated(item, 0);
    QCOMPARE(window.lesson().source, order.first());
}

void GuiWorkbenchTest::inspectorShowsTheSelectedBall()
{
    sim::Scene scene = plainScene();
    scene.spawn.count = 0;
    scene.settings.gravity.enabled = true;
    scene.settings.gravity.g = {30.0, 700.0};
    scene.settings.drag.enabled = true;
    scene.settings.drag.k = 0.5;
    scene.settings.drag.scale = sim::ForceScale::None; // a = -k v for this ball of mass 3.5: F = -m k v
    scene.settings.spring.enabled = true;
    scene.settings.spring.k = 2.0;
    scene.settings.spring.anchor = {300.0, 200.0};
    MainWindow window;
    QVERIFY(window.setLesson(lessonOf(scene)));
    window.resize(1400, 900);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    SimulationController* controller = window.controller();
    controller->pause();
    controller->stepOnce();

    // Click ball 1 on the canvas.
    Canvas* canvas = window.canvas();
    const sim::World& world = controller->world();
    const QPointF at = canvas->worldToWidget(world.balls().position.col(1));
    QTest::mouseClick(canvas, Qt::LeftButton, {}, at.toPoint());
    QCOMPARE(canvas->selectedBall(), 1);
    InspectorDock* inspector = window.inspectorDock();
    QCOMPARE(inspector->selectedBall(), 1);
    controller->stepOnce(); // and it follows every step

    const InspectorDock::Readout& r = inspector->readout();
    const sim::Matrix2X a = world.accelerations();
    QCOMPARE(r.position, sim::Vec2(world.balls().position.col(1)));
    QCOMPARE(r.velocity, sim::Vec2(world.balls().velocity.col(1)));
    QCOMPARE(r.acceleration, sim::Vec2(a.col(1)));
    QCOMPARE(r.mass, 3.5);
    QCOMPARE(r.radius, 12.0);
    // Forces per model from their closed forms: m g, -m k v, -m k_s (x - anchor).
    QCOMPARE(int(r.forces.size()), 3);
    const double m = 3.5;
    const sim::Vec2 x = r.position, v = r.velocity;
    const sim::Vec2 expected[] = {m * sim::Vec2(30.0, 700.0), -m * 0.5 * v, -m * 2.0 * (x - sim::Vec2(300.0, 200.0))};
    const char* names[] = {"gravity", "drag", "spring"};
    sim::Vec2 sum(0.0, 0.0);
    for (int k = 0; k < 3; ++k) {
        QCOMPARE(r.forces[std::size_t(k)].model, QString::fromLatin1(names[k]));
        QVERIFY2((r.forces[std::size_t(k)].force - expected[k]).norm() < 1e-9 * (1.0 + expected[k].norm()), names[k]);
        sum += r.forces[std::size_t(k)].force;
    }
    QVERIFY((sum - m * r.acceleration).norm() < 1e-9 * (1.0 + sum.norm()));
    QCOMPARE(r.totalForce, m * r.acceleration);
    // The labels show the same numbers.
    auto* position = inspector->findChild<QLabel*>(QStringLiteral("inspectorPosition"));
    QVERIFY(position->text().contains(QString::number(x.x(), 'f', 1)));
    QVERIFY(position->text().contains(QString::number(x.y(), 'f', 1)));
    auto* forces = inspector->findChild<QLabel*>(QStringLiteral("inspectorForces"));
    QVERIFY(forces->text().contains(QStringLiteral("spring")));

    // The trail switch: a trail behind the selected ball only.
    auto* trail = inspector->findChild<QCheckBox*>(QStringLiteral("trailCheck"));
    QVERIFY(!canvas->trailsEnabled());
    trail->setChecked(true);
    QVERIFY(canvas->trailsEnabled());
    QCOMPARE(canvas->trailScope(), TrailRecorder::Scope::Selected);
    trail->setChecked(false);
    QVERIFY(!canvas->trailsEnabled());

    // Clicking empty space clears the selection.
    QTest::mouseClick(canvas, Qt::LeftButton, {}, canvas->worldToWidget(sim::Vec2(580.0, 20.0)).toPoint());
    QCOMPARE(inspector->selectedBall(), -1);
}

// Issue #36: a lesson whose readout talks about ball 0 rings ball 0 at the
// start; that ring is a real selection, so the Inspector shows ball 0 from
// the start, and a click on it, or on another ball, fills the Inspector
// also after a reset.
void GuiWorkbenchTest::startSelectionFillsTheInspector()
{
    MainWindow window(QStringLiteral("gravity")); // overlays: readout, velocity
    window.resize(1400, 900);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    Canvas* canvas = window.canvas();
    InspectorDock* inspector = window.inspectorDock();
    inspector->show();
    inspector->raise();
    SimulationController* controller = window.controller();
    const sim::World& world = controller->world();
    QCOMPARE(canvas->selectedBall(), 0);
    QCOMPARE(inspector->selectedBall(), 0);
    controller->stepOnce();
    QCOMPARE(inspector->readout().position, sim::Vec2(world.balls().position.col(0)));

    // A click on ball 1, then on ball 0, moves the Inspector with it.
    const auto clickBall = [&](int i) {
        QTest::mouseClick(canvas, Qt::LeftButton, {}, canvas->worldToWidget(world.balls().position.col(i)).toPoint());
    };
    clickBall(1);
    QCOMPARE(inspector->selectedBall(), 1);
    clickBall(0);
    QCOMPARE(inspector->selectedBall(), 0);
    // A reset keeps the ring's ball and the Inspector's together.
    controller->reset();
    QCOMPARE(canvas->selectedBall(), 0);
    QCOMPARE(inspector->selectedBall(), 0);
    clickBall(0);
    QCOMPARE(inspector->selectedBall(), 0);
    controller->stepOnce();
    QCOMPARE(inspector->readout().position, sim::Vec2(world.balls().position.col(0)));
    // Empty space clears both; the ball clicked again is selected again.
    QTest::mouseClick(canvas, Qt::LeftButton, {}, canvas->worldToWidget(sim::Vec2(580.0, 20.0)).toPoint());
    QCOMPARE(inspector->selectedBall(), -1);
    clickBall(0);
    QCOMPARE(inspector->selectedBall(), 0);

    // A lesson without the readout starts with nothing selected.
    QVERIFY(window.openLesson(QStringLiteral("newtons-cradle")));
    QCOMPARE(canvas->selectedBall(), -1);
    QCOMPARE(inspector->selectedBall(), -1);
}

void GuiWorkbenchTest::screenshotAndTrajectoryFiles()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    MainWindow window;
    QVERIFY(window.setLesson(lessonOf(plainScene())));
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    SimulationController* controller = window.controller();
    controller->pause();

    // The picture is the canvas grown to what the screen would show.
    const QString png = dir.filePath(QStringLiteral("shot.png"));
    QVERIFY(window.saveScreenshotTo(png));
    const QImage image(png);
    QVERIFY(!image.isNull());
    QCOMPARE(image.size(), window.pictureSize() * window.canvas()->devicePixelRatio());

    // Record: the selected ball's rows, one per step, as the world has them.
    window.canvas()->setSelectedBall(1);
    auto* record = window.findChild<QAction*>(QStringLiteral("recordAction"));
    record->setChecked(true);
    for (int k = 0; k < 5; ++k)
        controller->stepOnce();
    record->setChecked(false);
    const auto* exporter = window.findChild<TrajectoryExport*>();
    QVERIFY(exporter);
    QCOMPARE(int(exporter->rows().size()), 6); // the start and five steps
    const TrajectoryExport::Row& last = exporter->rows().back();
    QCOMPARE(last.ball, 1);
    QCOMPARE(last.t, controller->world().time());
    QCOMPARE(last.x, controller->world().balls().position(0, 1));
    QCOMPARE(last.vy, controller->world().balls().velocity(1, 1));
}

// A stiff spring at a large dt: the world refuses to step, the controller
// pauses and the banner above the canvas says why with the fix; a safe dt
// takes the banner away and lets it run again.
void GuiWorkbenchTest::blowUpPausesAndExplains()
{
    MainWindow window;
    QVERIFY(window.openLesson(QStringLiteral("gravity")));
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    SimulationController* controller = window.controller();
    auto* banner = window.findChild<QLabel*>(QStringLiteral("haltBanner"));
    QVERIFY(banner);
    QVERIFY(!banner->isVisible());
    controller->play();
    sim::WorldSettings s = controller->world().settings();
    s.spring = sim::SpringSettings{true, sim::Vec2(300, 200), 90000.0}; // ω = 300 rad/s
    s.time.integrator = sim::IntegratorKind::Verlet;
    s.time.dt = 0.02;                                                   // ω dt = 6 > 2
    QVERIFY(controller->setSettings(s));
    QVERIFY(banner->isVisible());
    QVERIFY2(banner->text().contains(QStringLiteral("verlet is unstable for this spring")), qPrintable(banner->text()));
    QVERIFY(!controller->isPlaying());
    const std::int64_t steps = controller->world().stepCount();
    controller->advance(0.5);
    QCOMPARE(controller->world().stepCount(), steps); // nothing moves while halted
    s.time.dt = 0.005;                                 // ω dt = 1.5: stable
    QVERIFY(controller->setSettings(s));
    QVERIFY(!banner->isVisible());
    controller->advance(0.05);
    QVERIFY(controller->world().stepCount() > steps);
}

QTEST_MAIN(GuiWorkbenchTest)
#include "test_gui_workbench.moc"
