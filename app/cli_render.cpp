// forcelab-cli render: steps a lesson headless to a time and draws it into a
// PNG with the canvas's own painter (WorldPainter) and the lesson's overlays,
// so pictures in the docs and in tests are what the workbench shows.

#include "cli_commands.h"

#include "cli_args.h"

#include "lessons/lesson_loader.h"
#include "sim/world/step_plan.h"
#include "ui/drawing/png_file.h"
#include "ui/drawing/world_painter.h"

#include <QImage>
#include <QPainter>

#include <cmath>
#include <optional>

namespace forcelab::cli {
namespace {

struct RenderOptions {
    QString lesson;
    double time = 0.0;
    QString out;
    int width = 800;
    int height = 600;
};

constexpr int kMaxSide = 8192;
constexpr std::int64_t kMaxSteps = 100'000'000;

std::optional<RenderOptions> readOptions(const QCommandLineParser& p, std::ostream& err)
{
    RenderOptions o;
    auto fail = [&](const std::string& what) {
        err << "forcelab-cli render: " << what << "\n";
        return std::nullopt;
    };
    if (!p.isSet(QStringLiteral("time")))
        return fail("needs --time T (seconds of simulated time)");
    const std::string time = valueOf(p, "time");
    const auto t = parseFiniteNumber(time);
    if (!t || *t < 0)
        return fail("--time: expects a number of seconds >= 0, got '" + echo(time) + "'");
    o.time = *t;
    o.out = p.value(QStringLiteral("out"));
    if (o.out.isEmpty())
        return fail("needs --out FILE.png");
    if (p.isSet(QStringLiteral("size"))) {
        const std::string v = valueOf(p, "size");
        const auto x = v.find('x');
        const auto w = x == std::string::npos ? std::nullopt : parseFiniteNumber(v.substr(0, x));
        const auto h = x == std::string::npos ? std::nullopt : parseFiniteNumber(v.substr(x + 1));
        if (!w || !h || *w < 1 || *h < 1 || *w > kMaxSide || *h > kMaxSide || std::floor(*w) != *w ||
            std::floor(*h) != *h)
            return fail("--size: expects WIDTHxHEIGHT in pixels (1 to 8192 each), got '" + echo(v) + "'");
        o.width = int(*w);
        o.height = int(*h);
    }
    const QStringList lessons = p.positionalArguments();
    if (lessons.isEmpty())
        return fail("needs a lesson (a file or a built-in id)");
    if (lessons.size() > 1)
        return fail("more than one lesson given");
    o.lesson = lessons[0];
    return o;
}

} // namespace

void declareRender(QCommandLineParser& p)
{
    p.addPositionalArgument(QStringLiteral("lesson"), QStringLiteral("A lesson file, or a built-in id."),
                            QStringLiteral("LESSON"));
    p.addOptions({{QStringLiteral("time"), QStringLiteral("Simulated time to draw, s."), QStringLiteral("T")},
                  {QStringLiteral("out"), QStringLiteral("The PNG file to write."), QStringLiteral("FILE.png")},
                  {QStringLiteral("size"), QStringLiteral("Picture size in pixels (default 800x600)."),
                   QStringLiteral("WxH")}});
}

int renderCommand(const QCommandLineParser& parser, std::ostream& out, std::ostream& err)
{
    const auto options = readOptions(parser, err);
    if (!options)
        return 2;
    sim::World world;
    const std::optional<Lesson> loaded = loadLessonWorld(options->lesson, {}, world, err);
    if (!loaded)
        return 2;
    const Lesson& lesson = *loaded;
    // Ends at T, as `run --time` does.
    std::string why;
    const auto plan = sim::planSteps(options->time, world.settings().time.dt, kMaxSteps, &why);
    if (!plan) {
        err << "forcelab-cli render: --time: " << why << "\n";
        return 2;
    }
    sim::runPlan(world, *plan);
    if (world.halted()) {
        err << lesson.source.toStdString() << ": stopped after " << world.stepCount() << " steps: " << *world.halted()
            << "\n";
        return 3;
    }

    QImage image(options->width, options->height, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    {
        QPainter painter(&image);
        PaintOptions paint;
        paint.overlays = Overlays::fromNames(lesson.overlays);
        WorldPainter painterOfWorld;
        painterOfWorld.paint(painter, QRectF(0, 0, options->width, options->height), world, paint, 1.0);
    }
    QString unwritten;
    if (!writePngAtomically(options->out, image, &unwritten)) {
        err << "forcelab-cli render: --out: " << unwritten.toStdString() << " (an old file there is unchanged)\n";
        return 2;
    }
    out << lesson.id.toStdString() << " at t = " << world.time() << " s (" << world.stepCount() << " steps) drawn to "
        << options->out.toStdString() << " (" << options->width << "x" << options->height << ")\n";
    return 0;
}

} // namespace forcelab::cli
