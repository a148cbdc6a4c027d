// forcelab-cli run: loads a lesson, applies the overrides, steps it headless
// and reports the final state.

#include "cli_commands.h"

#include "cli_args.h"

#include "lessons/lesson_loader.h"
#include "lessons/message_text.h"
#include "sim/world/names.h"
#include "sim/world/step_plan.h"
#include "sim/world/world.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <optional>

namespace forcelab::cli {
namespace {

struct RunOptions {
    QString lesson;
    QList<Override> overrides;
    std::optional<std::int64_t> steps;
    std::optional<double> time;
    bool json = false;
};

constexpr std::int64_t kMaxSteps = 1'000'000'000;

// The options that change a lesson value, and the key path each overrides:
// they become overrides, so they are checked by the same code as the file.
constexpr std::pair<const char*, const char*> kTimeOptions[] = {
    {"integrator", "time.integrator"}, {"dt", "time.dt"},     {"substeps", "time.substeps"},
    {"tolerance", "time.tolerance"},   {"seed", "time.seed"},
};

std::optional<RunOptions> readOptions(const QCommandLineParser& p, std::ostream& err)
{
    RunOptions o;
    auto fail = [&](const std::string& what) {
        err << "forcelab-cli run: " << what << "\n";
        return std::nullopt;
    };
    o.json = p.isSet(QStringLiteral("json"));
    for (const auto& [name, key] : kTimeOptions) {
        if (!p.isSet(QString::fromLatin1(name)))
            continue;
        const std::string v = valueOf(p, name);
        const std::string flag = std::string("--") + name;
        // Checked here so the message names the option the user typed; the
        // range checks are the lesson's own, through the override.
        const bool isName = std::string_view(name) == "integrator";
        const std::string shown = lessons::cutForMessage(QString::fromStdString(v)).toStdString();
        if (isName && !sim::parseIntegrator(v))
            return fail(flag + ": \"" + shown + "\" is not one of " + sim::joinNames(sim::integratorNames()));
        if (!isName && !parseFiniteNumber(v))
            return fail(flag + ": expects a number, got '" + shown + "'");
        o.overrides.append(Override{QString::fromLatin1(key),
                                    isName ? QString::fromStdString("\"" + v + "\"") : QString::fromStdString(v)});
    }
    for (const QString& text : p.values(QStringLiteral("set"))) {
        QString error;
        const auto override = LessonLoader::parseOverride(text, &error);
        if (!override)
            return fail("--set " + lessons::cutForMessage(text).toStdString() + ": " + error.toStdString());
        o.overrides.append(*override);
    }
    if (p.isSet(QStringLiteral("steps"))) {
        const std::string v = valueOf(p, "steps");
        const auto n = parseFiniteNumber(v);
        if (!n || *n < 0 || *n > kMaxSteps || std::floor(*n) != *n)
            return fail("--steps: expects a whole number from 0 to 1000000000, got '" + echo(v) + "'");
        o.steps = static_cast<std::int64_t>(*n);
    }
    if (p.isSet(QStringLiteral("time"))) {
        const std::string v = valueOf(p, "time");
        const auto t = parseFiniteNumber(v);
        if (!t || !std::isfinite(*t) || *t < 0)
            return fail("--time: expects a number of seconds >= 0, got '" + echo(v) + "'");
        o.time = *t;
    }
    const QStringList lessons = p.positionalArguments();
    if (lessons.isEmpty())
        return fail("needs a lesson (a file or a built-in id)");
    if (lessons.size() > 1)
        return fail("more than one lesson given ('" + lessons[0].toStdString() + "' and '" + lessons[1].toStdString() +
                    "')");
    o.lesson = lessons[0];
    if (o.steps && o.time)
        return fail("give --steps or --time, not both");
    return o;
}

QJsonObject report(const Lesson& lesson, const sim::World& world, double wallMs)
{
    const sim::BallState& b = world.balls();
    QJsonArray balls;
    for (int i = 0; i < b.size(); ++i) {
        balls.append(QJsonObject{{"x", b.position(0, i)},
                                 {"y", b.position(1, i)},
                                 {"vx", b.velocity(0, i)},
                                 {"vy", b.velocity(1, i)},
                                 {"r", b.radius[i]},
                                 {"mass", b.mass[i]}});
    }
    const sim::Energy e = world.energy();
    const sim::Vec2 p = world.momentum();
    const sim::StepStats& t = world.totals();
    const sim::WorldSettings& s = world.settings();
    return QJsonObject{
        {"lesson", lesson.id},
        {"integrator", QString::fromLatin1(sim::toString(s.time.integrator).data(),
                                           static_cast<qsizetype>(sim::toString(s.time.integrator).size()))},
        {"dt", s.time.dt},
        {"steps", static_cast<double>(world.stepCount())},
        {"time", world.time()},
        {"balls", balls},
        {"energy", QJsonObject{{"kinetic", e.kinetic}, {"potential", e.potential}, {"total", e.total()}}},
        {"momentum", QJsonArray{p.x(), p.y()}},
        {"angular_momentum", world.angularMomentum()},
        {"force_evaluations", static_cast<double>(t.forceEvaluations)},
        {"wall_hits", static_cast<double>(t.wallHits)},
        {"contacts", static_cast<double>(t.contacts)},
        {"tolerance_floor", t.toleranceFloor},
        {"wall_ms", wallMs},
    };
}

} // namespace

void declareRun(QCommandLineParser& p)
{
    p.addPositionalArgument(QStringLiteral("lesson"), QStringLiteral("A lesson file, or a built-in id such as gravity."),
                            QStringLiteral("LESSON"));
    p.addOptions({
        {QStringLiteral("integrator"),
         QStringLiteral("Integrator: ") + QString::fromStdString(sim::joinNames(sim::integratorNames())) + u'.',
         QStringLiteral("NAME")},
        {QStringLiteral("dt"), QStringLiteral("Time step in s (time.dt)."), QStringLiteral("S")},
        {QStringLiteral("substeps"), QStringLiteral("Sub-steps per step (time.substeps)."), QStringLiteral("K")},
        {QStringLiteral("tolerance"), QStringLiteral("Tolerance of rk45 and ias15 (time.tolerance)."),
         QStringLiteral("T")},
        {QStringLiteral("seed"), QStringLiteral("Random seed (time.seed)."), QStringLiteral("S")},
        {QStringLiteral("set"), QStringLiteral("Change one lesson value, e.g. models.gravity.y=0; may be repeated."),
         QStringLiteral("KEY.PATH=VALUE")},
        {QStringLiteral("steps"), QStringLiteral("Take N steps of dt."), QStringLiteral("N")},
        {QStringLiteral("time"), QStringLiteral("Run to simulated time T s exactly (default 10)."), QStringLiteral("T")},
        {QStringLiteral("json"), QStringLiteral("Print the end state as one line of JSON.")},
    });
}

int runCommand(const QCommandLineParser& parser, std::ostream& out, std::ostream& err)
{
    const auto options = readOptions(parser, err);
    if (!options)
        return 2;
    sim::World world;
    const std::optional<Lesson> loaded = loadLessonWorld(options->lesson, options->overrides, world, err);
    if (!loaded)
        return 2;
    const Lesson& lesson = *loaded;
    const double dt = world.settings().time.dt;
    // --time T ends at T: whole steps of dt, then one shorter step if dt does
    // not divide T. --steps N takes N steps of dt. Neither: 10 s.
    sim::StepPlan plan;
    if (options->steps) {
        plan.whole = *options->steps;
    } else {
        std::string why;
        const auto planned = sim::planSteps(options->time.value_or(10.0), dt, kMaxSteps, &why);
        if (!planned) {
            err << "forcelab-cli run: --time: " << why << "\n";
            return 2;
        }
        plan = *planned;
    }

    const auto started = std::chrono::steady_clock::now();
    sim::runPlan(world, plan);
    const double wallMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
    // The world stopped itself: the motion blows up. Exit 3 with its reason.
    if (world.halted()) {
        err << lesson.source.toStdString() << ": stopped after " << world.stepCount() << " steps: " << *world.halted()
            << "\n";
        return 3;
    }

    // ias15 could not meet a tolerance below what rounding allows: say what it held instead.
    if (world.totals().toleranceFloor > 0.0)
        err << "note: time.tolerance " << world.settings().time.tolerance
            << " is below what rounding allows here; ias15 held its error estimate to "
            << world.totals().toleranceFloor << " instead\n";

    if (options->json) {
        out << QJsonDocument(report(lesson, world, wallMs)).toJson(QJsonDocument::Compact).toStdString() << "\n";
        return 0;
    }
    const sim::Energy e = world.energy();
    const sim::StepStats& t = world.totals();
    out << std::setprecision(10) << lesson.title.toStdString() << " (" << lesson.id.toStdString() << "): "
        << plan.whole << " steps of " << dt << " s";
    if (plan.last > 0.0) // dt does not divide --time: one shorter step ends the run at the time asked
        out << ", then one of " << plan.last << " s";
    out << " with "
        << sim::toString(world.settings().time.integrator) << ", t = " << world.time() << " s\n"
        << "  balls " << world.balls().size() << ", energy kinetic " << e.kinetic << " potential " << e.potential
        << " total " << e.total() << "\n"
        << "  force evaluations " << t.forceEvaluations << ", wall hits " << t.wallHits << ", contacts "
        << t.contacts << ", stepping took " << wallMs << " ms\n";
    return 0;
}

} // namespace forcelab::cli
