// forcelab: the workbench. `forcelab [LESSON]` opens a lesson file or a
// built-in lesson id; without one it opens the last lesson or the showcase.

#include "lessons/lesson_loader.h"
#include "ui/canvas/canvas.h"
#include "ui/window/main_window.h"
#include "ui/window/window_host.h"
#include "ui/window/language.h"
#include "ui/drawing/png_file.h"
#include "ui/drawing/render_bench.h"
#include "ui/canvas/simulation_controller.h"

#include <QApplication>
#include <QCoreApplication>
#include <QCommandLineParser>
#include <QScreen>
#include <QTimer>

#include <cstdio>
#include <optional>

namespace {

// The options beside the lesson, declared once.
struct Options {
    QCommandLineOption help;
    QCommandLineOption version;
    QCommandLineOption screenshot;
    QCommandLineOption after;
    QCommandLineOption time;
    QCommandLineOption size;
    QCommandLineOption present;
    QCommandLineOption benchRender;
    QCommandLineOption select;
    QCommandLineOption ballTable;
    QCommandLineOption zoom;
    QCommandLineOption follow;
    QCommandLineOption fitBalls;
    QCommandLineOption language;
};

// The names QSettings files the remembered choices under.
void setApplicationNames()
{
    QCoreApplication::setOrganizationName(QStringLiteral("ForceLab"));
    QCoreApplication::setApplicationName(QStringLiteral("ForceLab"));
    QCoreApplication::setApplicationVersion(QStringLiteral("0.1"));
}

Options declareOptions(QCommandLineParser& parser)
{
    parser.setApplicationDescription(QCoreApplication::translate("CommandLine", "A workbench for forces and collisions of 2D balls."));
    const QCommandLineOption help = parser.addHelpOption();
    const QCommandLineOption version = parser.addVersionOption();
    parser.addPositionalArgument(QStringLiteral("lesson"), QCoreApplication::translate("CommandLine", "Lesson file or built-in lesson id."),
                                 QStringLiteral("[lesson]"));
    const QCommandLineOption screenshot(QStringLiteral("screenshot"),
                                        QCoreApplication::translate("CommandLine", "Save a picture of the window to FILE and quit."),
                                        QStringLiteral("FILE"));
    const QCommandLineOption after(QStringLiteral("after"),
                                   QCoreApplication::translate("CommandLine", "Seconds to run in real time before --screenshot (default 3)."),
                                   QStringLiteral("SECONDS"), QStringLiteral("3"));
    const QCommandLineOption time(QStringLiteral("time"),
                                  QCoreApplication::translate("CommandLine", "For --screenshot: step the lesson to simulated time T (seconds) "
                                                 "and take the picture there, paused, instead of --after."),
                                  QStringLiteral("T"));
    const QCommandLineOption size(QStringLiteral("size"),
                                  QCoreApplication::translate("CommandLine", "For --screenshot: the window's size in pixels (default: the screen)."),
                                  QStringLiteral("WxH"));
    const QCommandLineOption present(QStringLiteral("present"),
                                     QCoreApplication::translate("CommandLine", "Open in the stage view for a projector (F11; Escape leaves)."));
    const QCommandLineOption benchRender(QStringLiteral("bench-render"),
                                         QCoreApplication::translate("CommandLine", "Time drawing 1k, 10k and 50k balls offscreen and quit."));
    const QCommandLineOption select(QStringLiteral("select"),
                                    QCoreApplication::translate("CommandLine", "Select ball N at the start (the Inspector shows its numbers)."),
                                    QStringLiteral("N"));
    const QCommandLineOption ballTable(QStringLiteral("ball-table"),
                                       QCoreApplication::translate("CommandLine", "Show the table of the balls (the Balls dock, or under the box "
                                                      "with --present), with the selected ball."));
    const QCommandLineOption zoom(QStringLiteral("zoom"),
                                  QCoreApplication::translate("CommandLine", "Zoom in Z times on the selected ball (or the box's middle)."),
                                  QStringLiteral("Z"));
    const QCommandLineOption follow(QStringLiteral("follow"),
                                    QCoreApplication::translate("CommandLine", "Follow the selected ball (with --select)."));
    const QCommandLineOption fitBalls(QStringLiteral("fit-balls"),
                                      QCoreApplication::translate("CommandLine", "Zoom so every ball is seen (with --time: where they are then)."));
    const QCommandLineOption language(QStringLiteral("language"),
                                      QCoreApplication::translate("CommandLine", "Show the program in language CODE (en, de or es) this time, "
                                                     "without changing the remembered one (View > Language)."),
                                      QStringLiteral("CODE"));
    parser.addOptions({screenshot, after, time, size, present, select, ballTable, zoom, follow, fitBalls, language,
                       benchRender});
    return {help, version, screenshot, after, time, size, present, benchRender, select, ballTable, zoom, follow,
            fitBalls, language};
}

// Reads the arguments before any window system is needed: --help and
// --version work without a display, and a picture or a benchmark is drawn
// offscreen when there is none. The exit code when the program ends here.
std::optional<int> readArguments(QCommandLineParser& parser, const Options& o, int argc, char* argv[])
{
    QStringList arguments;
    for (int i = 0; i < argc; ++i)
        arguments << QString::fromLocal8Bit(argv[i]);
    if (!parser.parse(arguments)) {
        std::fprintf(stderr, "forcelab: %s (forcelab --help lists the options)\n", qPrintable(parser.errorText()));
        return 2;
    }
    if (parser.isSet(o.help)) {
        // The help in the program's language (--language, else the one
        // View → Language remembers): a core application holds the
        // translators, and the options are declared again under them.
        int coreArgc = 1;
        char name[] = "forcelab"; // the usage line says "forcelab", wherever it was started from
        char* coreArgv[] = {name, nullptr};
        QCoreApplication core(coreArgc, coreArgv);
        setApplicationNames();
        forcelab::applyLanguage(parser.isSet(o.language) ? parser.value(o.language) : forcelab::rememberedLanguage());
        QCommandLineParser translated;
        declareOptions(translated);
        std::fputs(qPrintable(translated.helpText().replace(QStringLiteral("<executable_name>"), QStringLiteral("forcelab"))),
                   stdout);
        return 0;
    }
    if (parser.isSet(o.version)) {
        std::printf("ForceLab 0.1\n");
        return 0;
    }
    const bool display = !qEnvironmentVariableIsEmpty("DISPLAY") || !qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY") ||
                         !qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM");
    if (!display) {
        if (!parser.isSet(o.screenshot) && !parser.isSet(o.benchRender)) {
            std::fprintf(stderr, "forcelab: there is no display to open the window on (DISPLAY is not set); start it "
                                 "on a desktop, or draw a picture offscreen with --screenshot FILE.png\n");
            return 2;
        }
        qputenv("QT_QPA_PLATFORM", "offscreen");
    }
    return std::nullopt;
}

// For a picture: the window at the size asked for (`requested`), or the
// whole screen's worth of workbench. False when --size is not a size.
bool sizeForPicture(forcelab::MainWindow& window, const QCommandLineParser& parser, const Options& o,
                    std::optional<QSize>& requested)
{
    if (parser.isSet(o.screenshot)) {
        // The picture shows the whole screen's worth of workbench, or the size asked for.
        if (parser.isSet(o.size)) {
            const QStringList wh = parser.value(o.size).split(QLatin1Char('x'));
            const int w = wh.value(0).toInt(), h = wh.value(1).toInt();
            if (wh.size() != 2 || w < 320 || h < 240 || w > 7680 || h > 4320) {
                std::fprintf(stderr, "forcelab: --size: \"%s\" is not WxH between 320x240 and 7680x4320\n",
                             qPrintable(parser.value(o.size)));
                return false;
            }
            window.resize(w, h);
            requested = QSize(w, h);
        } else if (const QScreen* screen = window.screen()) {
            window.setGeometry(screen->availableGeometry());
        }
    }
    return true;
}

// Steps to --time (or runs for --after) and then saves the picture and
// quits. False when one of those values is not a number in range.
bool scheduleScreenshot(forcelab::MainWindow& window, const QCommandLineParser& parser, const Options& o)
{
    bool ok = false;
    const double seconds = parser.value(o.after).toDouble(&ok);
    if (!ok || !(seconds >= 0.0 && seconds <= 600.0)) {
        std::fprintf(stderr, "forcelab: --after: \"%s\" is not a number of seconds from 0 to 600\n",
                     qPrintable(parser.value(o.after)));
        return false;
    }
    const QString file = parser.value(o.screenshot);
    int wait = static_cast<int>(seconds * 1000.0);
    if (parser.isSet(o.time)) {
        const double t = parser.value(o.time).toDouble(&ok);
        if (!ok || !(t >= 0.0 && t <= 3600.0)) {
            std::fprintf(stderr, "forcelab: --time: \"%s\" is not a number of seconds from 0 to 3600\n",
                         qPrintable(parser.value(o.time)));
            return false;
        }
        forcelab::SimulationController* controller = window.controller();
        const double dt = controller->world().settings().time.dt;
        while (controller->world().time() < t - 0.5 * dt && !controller->world().halted())
            controller->stepOnce();
        wait = 200; // let the window lay itself out and paint
    } else {
        window.controller()->play(); // a lesson opens paused; --after shows it running
    }
    QTimer::singleShot(wait, &window, [&window, file] {
        QString why;
        if (!forcelab::writePngAtomically(file, window.grab().toImage(), &why)) {
            std::fprintf(stderr, "forcelab: --screenshot: %s\n", qPrintable(why));
            QApplication::exit(2);
            return;
        }
        QApplication::quit();
    });
    return true;
}

// --zoom, --follow and --fit-balls, on the balls where they are now (after
// --time's steps). False when --zoom is not a zoom in range.
bool setCamera(forcelab::MainWindow& window, const QCommandLineParser& parser, const Options& o)
{
    forcelab::Canvas* canvas = window.canvas();
    if (parser.isSet(o.zoom)) {
        bool ok = false;
        const double zoom = parser.value(o.zoom).toDouble(&ok);
        if (!ok || !(zoom >= forcelab::Camera::kMinZoom && zoom <= forcelab::Camera::kMaxZoom)) {
            std::fprintf(stderr, "forcelab: --zoom: \"%s\" is not a zoom from %g to %g\n",
                         qPrintable(parser.value(o.zoom)), forcelab::Camera::kMinZoom, forcelab::Camera::kMaxZoom);
            return false;
        }
        forcelab::Camera camera;
        camera.zoom = zoom;
        const int ball = canvas->selectedBall();
        if (ball >= 0)
            camera.centre = forcelab::sim::Vec2(window.controller()->world().balls().position.col(ball));
        canvas->setCamera(camera);
    }
    // Fitting needs the canvas's size: once the window has laid itself out.
    const bool fit = parser.isSet(o.fitBalls), follow = parser.isSet(o.follow);
    QTimer::singleShot(0, canvas, [canvas, fit, follow] {
        if (fit)
            canvas->fitAllBalls();
        if (follow)
            canvas->setFollowing(true);
    });
    return true;
}

} // namespace

int main(int argc, char* argv[])
{
    QCommandLineParser parser;
    const Options o = declareOptions(parser);
    if (const std::optional<int> exit = readArguments(parser, o, argc, argv))
        return *exit;

    QApplication app(argc, argv);
    setApplicationNames();

    if (parser.isSet(o.benchRender)) {
        const forcelab::RenderBenchOptions options;
        std::fputs(qPrintable(forcelab::formatRenderBench(forcelab::runRenderBench(options), options)), stdout);
        return 0;
    }

    const QStringList lessons = parser.positionalArguments();
    // A picture is taken with nobody at the screen: a lesson that does not
    // load is a line on stderr and exit code 2, not a dialog that waits for
    // a click for ever.
    if (parser.isSet(o.screenshot) && !lessons.isEmpty()) {
        const forcelab::LoadResult check = forcelab::LessonLoader::load(lessons.first());
        if (!check.ok()) {
            for (const QString& error : check.errors())
                std::fprintf(stderr, "forcelab: %s\n", qPrintable(error));
            return 2;
        }
    }
    // The host owns the window, in the remembered language, and rebuilds it when View → Language changes it.
    const QString language = parser.value(o.language);
    if (parser.isSet(o.language) && !forcelab::applyLanguage(language)) {
        QStringList codes;
        for (const forcelab::Language& l : forcelab::shippedLanguages())
            codes << l.code;
        std::fprintf(stderr, "forcelab: --language: \"%s\" is not one of %s\n", qPrintable(language.left(40)),
                     qPrintable(codes.join(QStringLiteral(", "))));
        return 2;
    }
    forcelab::WindowHost host(lessons.isEmpty() ? QString() : lessons.first(), parser.isSet(o.language));
    forcelab::MainWindow& window = *host.window();
    std::optional<QSize> requested; // --size
    if (parser.isSet(o.screenshot) && !sizeForPicture(window, parser, o, requested))
        return 2;
    window.show();
    if (parser.isSet(o.present)) {
        window.findChild<QAction*>(QStringLiteral("presentationAction"))->setChecked(true);
        if (requested) { // a picture of the stage at the size asked for, whatever the screen
            window.showNormal();
            window.setGeometry(QRect(QPoint(0, 0), *requested));
        }
    }
    if (parser.isSet(o.select)) {
        bool ok = false;
        const int ball = parser.value(o.select).toInt(&ok);
        const int count = window.controller()->world().balls().size();
        if (!ok || ball < 0 || ball >= count) {
            std::fprintf(stderr, "forcelab: --select: \"%s\" is not a ball number from 0 to %d\n",
                         qPrintable(parser.value(o.select)), count - 1);
            return 2;
        }
        window.canvas()->setSelectedBall(ball);
    }
    if (parser.isSet(o.ballTable))
        window.editBall(window.canvas()->selectedBall());

    if (parser.isSet(o.screenshot) && !scheduleScreenshot(window, parser, o))
        return 2;
    if (!setCamera(window, parser, o))
        return 2;
    return QApplication::exec();
}
