// forcelab-cli sweep: a work-precision study. Every integrator runs the
// reference problems of sim/studies/reference_study.h at a range of time steps (and
// of tolerances for the adaptive ones); each run reports its error against the
// closed form and its cost. This file prints the table, the fitted orders, the
// long-run energy of the symplectic methods next to rk4's drift, and writes the
// CSV; the chart is ui/drawing/sweep_chart.h.

#include "cli_commands.h"

#include "sim/integrators/integrator_info.h"
#include "sim/world/names.h"
#include "sim/studies/reference_study.h"
#include "sim/studies/work_precision.h"
#include "sim/world/world.h"
#include "lessons/atomic_file.h"
#include "ui/drawing/sweep_chart.h"

#include <QString>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>

using namespace forcelab::sim;

namespace forcelab::cli {
namespace {

struct Options {
    bool quick = false;
    std::optional<std::string> problem;
    std::optional<std::string> csv;
    std::optional<std::string> png;
};

std::string sci(double v, int digits = 2)
{
    if (std::isnan(v))
        return "-";
    if (std::isinf(v))
        return "blew up";
    std::ostringstream s;
    s << std::scientific << std::setprecision(digits) << v;
    return s.str();
}

// One table per problem: every run's error and cost. Times are medians of
// `repeats` runs.
void printTable(std::ostream& out, const std::vector<ReferenceProblem>& problems, const std::vector<SweepRun>& rows,
                int repeats)
{
    // The table.
    out << "Work-precision sweep: position error at the end against the closed form, largest relative energy\n"
           "error sampled at every step, cost. Times are medians of "
        << repeats << " runs.\n";
    for (const ReferenceProblem& p : problems) {
        out << "\n" << p.name << ": " << p.what << " (end t = " << p.endTime << " s)\n";
        out << std::left << std::setw(20) << "integrator" << std::right << std::setw(11) << "dt s" << std::setw(9)
            << "tol" << std::setw(11) << "evals" << std::setw(12) << "pos err px" << std::setw(12) << "max|dE/E|"
            << std::setw(11) << "ns/step" << std::setw(10) << "wall ms" << "\n";
        for (const SweepRun& r : rows) {
            if (r.problem != p.name)
                continue;
            out << std::left << std::setw(20) << toString(r.integrator) << std::right << std::setw(11) << sci(r.dt, 1)
                << std::setw(9) << (r.tolerance > 0 ? sci(r.tolerance, 0) : "-") << std::setw(11)
                << (r.blewUp ? "-" : std::to_string(r.evaluations)) << std::setw(12) << sci(r.positionError)
                << std::setw(12) << sci(r.energyError) << std::setw(11)
                << (r.blewUp ? "-" : sci(r.nsPerStepBall)) << std::setw(10) << (r.blewUp ? "-" : sci(r.wallMs))
                << "\n";
        }
    }
}

// Fitted orders: slope of log(error) against log(dt), for every fixed-step
// method with an order to fit.
void printOrders(std::ostream& out, const std::vector<ReferenceProblem>& problems, const std::vector<SweepRun>& rows)
{
    out << "\nFitted order (slope of log error against log dt over the runs with 1e-10 < error / size < 1e-2):\n";
    out << std::left << std::setw(20) << "problem";
    // Every fixed-step method with an order to fit.
    std::vector<IntegratorKind> fixed;
    for (const IntegratorInfo& info : integrators())
        if (!info.adaptive && info.order > 0.0)
            fixed.push_back(info.kind);
    for (IntegratorKind k : fixed)
        out << std::right << std::setw(21) << std::string(toString(k)) + " (" +
                                                   std::to_string(int(theoreticalOrder(k))) + ")";
    out << "\n";
    for (const ReferenceProblem& p : problems) {
        out << std::left << std::setw(20) << p.name << std::right;
        for (IntegratorKind k : fixed) {
            const OrderFit f = fitOrder(rows, p, k);
            std::ostringstream cell;
            if (std::isnan(f.order))
                cell << "- (" << f.points << " pts)";
            else
                cell << std::fixed << std::setprecision(2) << f.order << " (" << f.points << " pts)";
            out << std::setw(21) << cell.str();
        }
        out << "\n";
    }
}

// Long runs: the symplectic methods' energy error stays bounded, rk4's grows
// in proportion to time.
void printLongRuns(std::ostream& out, bool quick)
{
    const ReferenceProblem p = keplerProblem(0.5, 1000);
    const std::vector<int> marks = quick ? std::vector<int>{10, 100} : std::vector<int>{10, 100, 1000};
    const double dt = 1.0 / 256;
    out << "\nEnergy over long runs, Kepler e = 0.5, dt = 1/256 s: largest |dE/E| up to each number of orbits\n";
    out << std::left << std::setw(20) << "integrator" << std::right;
    for (int m : marks)
        out << std::setw(14) << std::to_string(m) + " orbits";
    out << std::setw(12) << "growth" << "\n";
    for (IntegratorKind k : {IntegratorKind::SemiImplicitEuler, IntegratorKind::Verlet, IntegratorKind::Yoshida4,
                             IntegratorKind::Rk4, IntegratorKind::Ias15}) {
        Scene s = p.scene();
        s.settings.time.integrator = k;
        s.settings.time.dt = dt;
        World world;
        world.reset(s);
        double worst = 0.0;
        std::vector<double> at;
        std::int64_t step = 0;
        for (int m : marks) {
            for (; step < std::int64_t(m) * 256; ++step) {
                world.step();
                worst = std::max(worst, p.energyError(world));
            }
            at.push_back(worst);
        }
        out << std::left << std::setw(20) << toString(k) << std::right;
        for (double v : at)
            out << std::setw(14) << sci(v);
        out << std::setw(11) << std::fixed << std::setprecision(1) << at.back() / at.front() << "x"
            << std::defaultfloat << "\n";
    }
}

} // namespace

void declareSweep(QCommandLineParser& p)
{
    p.addOptions({
        {QStringLiteral("problem"), QStringLiteral("Only this reference problem (default: all of them)."),
         QStringLiteral("NAME")},
        {QStringLiteral("quick"), QStringLiteral("Fewer steps, tolerances and repeats.")},
        {QStringLiteral("csv"), QStringLiteral("Also write every run to FILE."), QStringLiteral("FILE")},
        {QStringLiteral("png"), QStringLiteral("Also draw the error-against-cost chart to FILE."), QStringLiteral("FILE")},
    });
}

int sweepCommand(const QCommandLineParser& parser, std::ostream& out, std::ostream& err)
{
    Options o;
    o.quick = parser.isSet(QStringLiteral("quick"));
    if (parser.isSet(QStringLiteral("problem")))
        o.problem = valueOf(parser, "problem");
    if (parser.isSet(QStringLiteral("csv")))
        o.csv = valueOf(parser, "csv");
    if (parser.isSet(QStringLiteral("png")))
        o.png = valueOf(parser, "png");
    if (!parser.positionalArguments().isEmpty()) {
        err << "forcelab-cli sweep: takes no arguments besides its options\n";
        return 2;
    }

    std::vector<ReferenceProblem> problems = referenceProblems(o.quick);
    if (o.problem) {
        std::vector<ReferenceProblem> all = referenceProblems(false);
        std::vector<ReferenceProblem> picked;
        std::string names;
        for (const ReferenceProblem& p : all) {
            names += (names.empty() ? "" : ", ") + p.name;
            if (p.name == *o.problem)
                picked.push_back(p);
        }
        if (picked.empty()) {
            err << "forcelab-cli sweep: --problem: \"" << *o.problem << "\" is not one of " << names << "\n";
            return 2;
        }
        problems = picked;
    }

    // Both files are written all or nothing, and whether they can be written
    // at all is found out now, not after the whole sweep.
    std::optional<lessons::AtomicFile> csvFile;
    if (o.csv) {
        csvFile.emplace(QString::fromStdString(*o.csv));
        if (!csvFile->open()) {
            err << "forcelab-cli sweep: --csv: " << csvFile->error().toStdString() << "\n";
            return 2;
        }
    }
    if (o.png) {
        lessons::AtomicFile probe(QString::fromStdString(*o.png)); // dropped unwritten: the old file stays
        if (!probe.open()) {
            err << "forcelab-cli sweep: --png: " << probe.error().toStdString() << "\n";
            return 2;
        }
    }

    // The sweep: the plan of sim/studies/reference_study.h, each run timed `repeats` times.
    const int repeats = o.quick ? 1 : 5;
    const std::vector<SweepJob> jobs = planSweep(problems, o.quick);
    const auto started = std::chrono::steady_clock::now();
    std::vector<SweepRun> rows;
    for (std::size_t j = 0; j < jobs.size(); ++j) {
        // A progress bar on stderr, redrawn in place.
        const int width = 30, filled = int(width * j / jobs.size());
        err << "\rsweep [" << std::string(filled, '#') << std::string(width - filled, '.') << "] " << j << "/"
            << jobs.size() << " " << jobs[j].problem->name << std::string(12, ' ') << std::flush;
        if (auto row = runReference(*jobs[j].problem, jobs[j].kind, jobs[j].dt, jobs[j].tolerance, repeats))
            rows.push_back(*row);
    }
    err << "\rsweep [" << std::string(30, '#') << "] " << jobs.size() << "/" << jobs.size() << " done in "
        << std::fixed << std::setprecision(1)
        << std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count() << " s"
        << std::string(20, ' ') << "\n"
        << std::defaultfloat;

    printTable(out, problems, rows, repeats);

    printOrders(out, problems, rows);

    printLongRuns(out, o.quick);

    if (csvFile) {
        std::ostringstream f;
        f << "problem,integrator,dt,tolerance,steps,force_evaluations,position_error,energy_error,wall_ms,"
             "ns_per_step_per_ball,blew_up\n";
        f << std::setprecision(6);
        for (const SweepRun& r : rows) {
            f << r.problem << "," << toString(r.integrator) << "," << r.dt << "," << r.tolerance << "," << r.steps
              << "," << r.evaluations << "," << r.positionError << ",";
            if (!std::isnan(r.energyError))
                f << r.energyError;
            f << "," << r.wallMs << "," << r.nsPerStepBall << "," << (r.blewUp ? 1 : 0) << "\n";
        }
        if (!csvFile->write(QByteArray::fromStdString(f.str())) || !csvFile->commit()) {
            err << "forcelab-cli sweep: --csv: " << csvFile->error().toStdString() << "\n";
            return 2;
        }
        out << "\nCSV written to " << *o.csv << "\n";
    }
    if (o.png) {
        QString why;
        if (!writeSweepChart(QString::fromStdString(*o.png), problems, rows, &why)) {
            err << "forcelab-cli sweep: --png: " << why.toStdString() << "\n";
            return 2;
        }
        out << "chart written to " << *o.png << "\n";
    }
    return 0;
}

} // namespace forcelab::cli
