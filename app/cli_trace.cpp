// forcelab-cli trace and compare: a check of a simulation written anywhere.
// trace writes every step of a lesson (state, acceleration, the step's pair
// tests, contacts, wind and random draws) as CSV or JSON; compare reads a
// student's trace of the same lesson, runs the reference, and reports the
// first step and ball where they part, how far, and the known mistake whose
// run the student's numbers follow (sim/studies/trace_compare.h).

#include "cli_commands.h"

#include "cli_args.h"

#include "lessons/lesson_loader.h"
#include "lessons/student_trace.h"
#include "sim/studies/trace.h"
#include "sim/studies/trace_compare.h"
#include "sim/world/names.h"
#include "sim/world/world.h"

#include <QJsonArray>
#include <QJsonDocument>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>

namespace forcelab::cli {
namespace {

constexpr double kDefaultTolerance = 1e-6;

std::optional<QList<Override>> readOverrides(const QCommandLineParser& p, const char* command, std::ostream& err)
{
    QList<Override> overrides;
    for (const QString& text : p.values(QStringLiteral("set"))) {
        QString error;
        const auto override = LessonLoader::parseOverride(text, &error);
        if (!override) {
            err << "forcelab-cli " << command << ": --set " << echo(text.toStdString()) << ": "
                << error.toStdString() << "\n";
            return std::nullopt;
        }
        overrides.append(*override);
    }
    return overrides;
}

std::optional<std::int64_t> wholeOption(const QCommandLineParser& p, const char* name, std::int64_t lo,
                                        std::int64_t hi, const char* command, std::ostream& err)
{
    const std::string v = valueOf(p, name);
    const auto n = parseFiniteNumber(v);
    if (!n || *n < static_cast<double>(lo) || *n > static_cast<double>(hi) || std::floor(*n) != *n) {
        err << "forcelab-cli " << command << ": --" << name << ": expects a whole number from " << lo << " to " << hi
            << ", got '" << echo(v) << "'\n";
        return std::nullopt;
    }
    return static_cast<std::int64_t>(*n);
}

// The settings a trace was made with, for its header.
std::string settingsLine(const Lesson& lesson, const sim::WorldSettings& s, const QList<Override>& overrides,
                         std::int64_t steps, std::int64_t every)
{
    std::ostringstream o;
    o << std::setprecision(17) << "lesson " << lesson.id.toStdString() << "; integrator "
      << sim::toString(s.time.integrator) << "; dt " << s.time.dt << " s; substeps " << s.time.substeps << "; seed "
      << s.time.seed << "; per_frame " << (s.time.perFrame ? "true" : "false") << "; steps " << steps << "; every "
      << every;
    for (const Override& ov : overrides)
        o << "; set " << ov.keyPath.toStdString() << "=" << ov.value.toStdString();
    return o.str();
}

} // namespace

void declareTrace(QCommandLineParser& p)
{
    p.addPositionalArgument(QStringLiteral("lesson"), QStringLiteral("A lesson file, or a built-in id such as gravity."),
                            QStringLiteral("LESSON"));
    p.addOptions({
        {QStringLiteral("steps"), QStringLiteral("Take N steps of dt (at most 1000000)."), QStringLiteral("N")},
        {QStringLiteral("every"), QStringLiteral("Write step 0, every K-th step and the last (default 1)."),
         QStringLiteral("K")},
        {QStringLiteral("set"), QStringLiteral("Change one lesson value, e.g. time.integrator=euler; may be repeated."),
         QStringLiteral("KEY.PATH=VALUE")},
        {QStringLiteral("csv"), QStringLiteral("Write CSV: '#' lines with the settings, a header, one row per ball and step (the default).")},
        {QStringLiteral("json"), QStringLiteral("Write JSON: {\"settings\": …, \"rows\": [{…}, …]}.")},
    });
}

int traceCommand(const QCommandLineParser& p, std::ostream& out, std::ostream& err)
{
    const auto overrides = readOverrides(p, "trace", err);
    if (!overrides)
        return 2;
    const QStringList lessons = p.positionalArguments();
    if (lessons.size() != 1) {
        err << "forcelab-cli trace: needs one lesson (a file or a built-in id)\n";
        return 2;
    }
    if (!p.isSet(QStringLiteral("steps"))) {
        err << "forcelab-cli trace: needs --steps N\n";
        return 2;
    }
    if (p.isSet(QStringLiteral("csv")) && p.isSet(QStringLiteral("json"))) {
        err << "forcelab-cli trace: give --csv or --json, not both\n";
        return 2;
    }
    const auto steps = wholeOption(p, "steps", 0, sim::kMaxTraceSteps, "trace", err);
    if (!steps)
        return 2;
    std::int64_t every = 1;
    if (p.isSet(QStringLiteral("every"))) {
        const auto k = wholeOption(p, "every", 1, sim::kMaxTraceSteps, "trace", err);
        if (!k)
            return 2;
        every = *k;
    }
    sim::World world;
    const std::optional<Lesson> lesson = loadLessonWorld(lessons[0], *overrides, world, err);
    if (!lesson)
        return 2;
    const std::int64_t written = (*steps / every + 1 + (*steps % every != 0 ? 1 : 0)) * world.balls().size();
    if (written > sim::kMaxTraceRows) {
        err << "forcelab-cli trace: " << written << " rows (" << world.balls().size()
            << " balls) is more than the " << sim::kMaxTraceRows << " a trace may have; raise --every or lower --steps\n";
        return 2;
    }
    const bool json = p.isSet(QStringLiteral("json"));
    const std::string settings = settingsLine(*lesson, world.settings(), *overrides, *steps, every);

    std::optional<std::string> halted;
    if (json) {
        // Streamed, not built as a QJsonDocument: two million rows would
        // hold gigabytes. 17 digits read back to the same double.
        out << "{\n  \"settings\": " << QJsonDocument(QJsonArray{QString::fromStdString(settings)})
                                               .toJson(QJsonDocument::Compact)
                                               .mid(1)
                                               .chopped(1)
                                               .toStdString()
            << ",\n  \"rows\": [" << std::setprecision(17);
        bool first = true;
        halted = sim::traceRun(world, *steps, every, [&](const std::vector<sim::TraceRow>& step) {
            for (const sim::TraceRow& r : step) {
                out << (first ? "\n    " : ",\n    ") << "{\"step\": " << r.step << ", \"t\": " << r.t
                    << ", \"ball\": " << r.ball << ", \"x\": " << r.x << ", \"y\": " << r.y << ", \"vx\": " << r.vx
                    << ", \"vy\": " << r.vy << ", \"ax\": " << r.ax << ", \"ay\": " << r.ay
                    << ", \"pair_tests\": " << r.pairTests << ", \"contacts\": " << r.contacts
                    << ", \"wind\": " << r.wind << ", \"random_x\": " << r.randomX << ", \"random_y\": " << r.randomY
                    << "}";
                first = false;
            }
        });
        out << "\n  ]\n}\n";
    } else {
        out << "# forcelab-cli trace: " << settings << "\n";
        const auto& names = sim::traceColumns();
        for (std::size_t k = 0; k < names.size(); ++k)
            out << (k ? "," : "") << names[k];
        out << "\n" << std::setprecision(17);
        halted = sim::traceRun(world, *steps, every, [&](const std::vector<sim::TraceRow>& step) {
            for (const sim::TraceRow& r : step)
                out << r.step << ',' << r.t << ',' << r.ball << ',' << r.x << ',' << r.y << ',' << r.vx << ','
                    << r.vy << ',' << r.ax << ',' << r.ay << ',' << r.pairTests << ',' << r.contacts << ','
                    << r.wind << ',' << r.randomX << ',' << r.randomY << '\n';
        });
    }
    if (halted) {
        err << lesson->source.toStdString() << ": stopped after " << world.stepCount() << " steps: " << *halted
            << "\n";
        return 3;
    }
    return 0;
}

namespace {

std::string unitOf(const std::string& field)
{
    return field[0] == 'v' ? "px/s" : "px";
}

std::string where(const sim::Departure& d, bool json)
{
    return json ? "row " + std::to_string(d.line) : "line " + std::to_string(d.line);
}

} // namespace

void declareCompare(QCommandLineParser& p)
{
    p.addPositionalArgument(QStringLiteral("lesson"), QStringLiteral("A lesson file, or a built-in id such as gravity."),
                            QStringLiteral("LESSON"));
    p.addPositionalArgument(QStringLiteral("student"),
                            QStringLiteral("The student's trace: CSV with a header (step,ball,x,y[,vx,vy]) or JSON "
                                           "(rows of {step, ball, x, y[, vx, vy]}); at most 64 MiB and 2000000 rows."),
                            QStringLiteral("STUDENT.csv|json"));
    p.addOptions({
        {QStringLiteral("set"), QStringLiteral("Change one lesson value for the reference; may be repeated."),
         QStringLiteral("KEY.PATH=VALUE")},
        {QStringLiteral("tolerance"),
         QStringLiteral("A value departs when |student − reference| > T × max(1, |reference|) (default 1e-6)."),
         QStringLiteral("T")},
    });
}

int compareCommand(const QCommandLineParser& p, std::ostream& out, std::ostream& err)
{
    const auto overrides = readOverrides(p, "compare", err);
    if (!overrides)
        return 2;
    const QStringList args = p.positionalArguments();
    if (args.size() != 2) {
        err << "forcelab-cli compare: needs a lesson and a student's trace (forcelab-cli compare LESSON STUDENT.csv)\n";
        return 2;
    }
    double tolerance = kDefaultTolerance;
    if (p.isSet(QStringLiteral("tolerance"))) {
        const std::string v = valueOf(p, "tolerance");
        const auto t = parseFiniteNumber(v);
        if (!t || *t <= 0 || *t > 1) {
            err << "forcelab-cli compare: --tolerance: expects a number in (0, 1], got '" << echo(v) << "'\n";
            return 2;
        }
        tolerance = *t;
    }
    sim::World world;
    const std::optional<Lesson> lesson = loadLessonWorld(args[0], *overrides, world, err);
    if (!lesson)
        return 2;
    const lessons::StudentTrace student = lessons::readStudentTrace(args[1]);
    if (!student.error.empty()) {
        err << student.error << "\n";
        return 2;
    }
    const std::string file = args[1].toStdString();
    const sim::Scene& scene = lesson->scene;
    const sim::TraceMatch match = sim::matchTrace(scene, student.rows, tolerance);
    if (match.problem) {
        err << file << ": " << *match.problem << "\n";
        return 2;
    }
    out << std::setprecision(6);
    if (!match.departure) {
        out << file << " agrees with " << lesson->id.toStdString() << " at every one of " << match.rowsAgreeing
            << " rows (to step " << match.lastStep << "): largest difference " << match.largestAgreeing
            << ", tolerance " << tolerance << " x max(1, |value|)\n";
        return 0;
    }
    const sim::Departure& d = *match.departure;
    out << file << " departs from " << lesson->id.toStdString() << " at step " << d.step << ", ball " << d.ball
        << " (" << where(d, student.json) << "): " << d.field << " is " << std::setprecision(12) << d.student
        << " where the reference has " << d.reference << std::setprecision(6) << ", off by " << d.size << " "
        << unitOf(d.field) << " (tolerance " << tolerance << " x max(1, |value|))\n";
    const auto diagnosis = sim::diagnose(scene, student.rows, tolerance, match);
    if (!diagnosis) {
        out << "cause: no known mistake explains it; " << sim::usualCauses() << "\n";
        return 1;
    }
    const sim::TraceMatch& m = diagnosis->match;
    out << "likely cause: " << diagnosis->variant.cause << ": the numbers follow the reference with --set "
        << diagnosis->variant.setting;
    if (!m.departure)
        out << " to " << m.largestAgreeing << " over all " << m.rowsAgreeing << " rows (to step " << m.lastStep
            << ")";
    else
        out << " for " << m.rowsAgreeing << " rows, to step " << m.departure->step << " (off by "
            << m.departure->size << " " << unitOf(m.departure->field) << " there)";
    out << ": " << diagnosis->variant.meaning << "\n";
    return 1;
}

} // namespace forcelab::cli
