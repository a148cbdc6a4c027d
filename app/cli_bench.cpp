// forcelab-cli bench: the options of the collision benchmark
// (sim/studies/collision_bench.h), which does the measuring and prints the tables.

#include "cli_commands.h"

#include "lessons/atomic_file.h"
#include "sim/studies/collision_bench.h"
#include "sim/world/threads.h"

#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace {

std::optional<std::vector<int>> parseSizes(const std::string& text)
{
    std::vector<int> out;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) {
        char* end = nullptr;
        const long v = std::strtol(item.c_str(), &end, 10);
        if (item.empty() || *end != '\0' || v < 0 || v > 10000000)
            return std::nullopt;
        out.push_back(static_cast<int>(v));
    }
    if (out.empty())
        return std::nullopt;
    return out;
}

} // namespace

namespace forcelab::cli {

void declareBench(QCommandLineParser& p)
{
    p.addOptions({
        {QStringLiteral("quick"), QStringLiteral("Fewer sizes and runs (1000, 4000, 10000 balls; 3 runs).")},
        {QStringLiteral("csv"), QStringLiteral("Also write every row to FILE."), QStringLiteral("FILE")},
        {QStringLiteral("runs"), QStringLiteral("Runs per measurement; the median is reported."), QStringLiteral("K")},
        {QStringLiteral("sizes"), QStringLiteral("Ball counts of the main table."), QStringLiteral("N,N,...")},
        {QStringLiteral("peer-sizes"), QStringLiteral("Ball counts of the comparison with other engines' methods."),
         QStringLiteral("N,N,...")},
        {QStringLiteral("brute-limit"), QStringLiteral("Largest count for the all-pairs detector."), QStringLiteral("N")},
        {QStringLiteral("profile"), QStringLiteral("Add the per-stage times of one step at the largest size.")},
        {QStringLiteral("speculative"), QStringLiteral("Speculative-contact growth of the solver, in radii, in [0, 8]."),
         QStringLiteral("S")},
        {QStringLiteral("threads"),
         QStringLiteral("Most threads for the solver's passes (default: every core); the results are the same "
                        "bits for any count, only the wall-clock times change."),
         QStringLiteral("T")},
        {QStringLiteral("no-peers"), QStringLiteral("Leave out the comparison table.")},
        {QStringLiteral("peers-only"), QStringLiteral("Only the comparison table.")},
        {QStringLiteral("spawn"),
         QStringLiteral("Add the spawn scene: N balls spawned in a 3500 px box, the solver against one pass over its "
                        "first 20 and 200 steps."),
         QStringLiteral("N")},
        {QStringLiteral("spawn-only"), QStringLiteral("Only the spawn scene (with --spawn).")},
    });
}

int benchCommand(const QCommandLineParser& parser, std::ostream& out, std::ostream& err)
{
    sim::CollisionBenchOptions o;
    std::string csvFile;
    auto has = [&](const char* name) { return parser.isSet(QString::fromLatin1(name)); };
    if (has("quick")) {
        o.quick = true;
        o.runs = 3;
        o.sizes = {1000, 4000, 10000};
        o.peerSizes = {1000, 5000};
        o.peerSteps = 120;
    }
    if (has("csv"))
        csvFile = valueOf(parser, "csv");
    if (has("runs")) {
        const auto n = parseSizes(valueOf(parser, "runs"));
        if (!n || n->size() != 1 || (*n)[0] < 1) {
            err << "forcelab-cli bench: --runs: expected a positive integer, got '" << echo(valueOf(parser, "runs")) << "'\n";
            return 2;
        }
        o.runs = (*n)[0];
    }
    for (const char* name : {"sizes", "peer-sizes"}) {
        if (!has(name))
            continue;
        const auto n = parseSizes(valueOf(parser, name));
        if (!n) {
            err << "forcelab-cli bench: --" << name << ": expected a list like 1000,4000, got '" << echo(valueOf(parser, name))
                << "'\n";
            return 2;
        }
        (std::string_view(name) == "sizes" ? o.sizes : o.peerSizes) = *n;
    }
    if (has("brute-limit")) {
        const auto n = parseSizes(valueOf(parser, "brute-limit"));
        if (!n || n->size() != 1) {
            err << "forcelab-cli bench: --brute-limit: expected an integer, got '" << echo(valueOf(parser, "brute-limit"))
                << "'\n";
            return 2;
        }
        o.bruteLimit = (*n)[0];
    }
    o.profile = has("profile");
    if (has("speculative")) {
        const std::string v = valueOf(parser, "speculative");
        char* end = nullptr;
        o.speculative = std::strtod(v.c_str(), &end);
        if (v.empty() || *end != '\0' || !(o.speculative >= 0.0 && o.speculative <= 8.0)) {
            err << "forcelab-cli bench: --speculative: expected a number in [0, 8], got '" << echo(v) << "'\n";
            return 2;
        }
    }
    if (has("no-peers"))
        o.peers = false;
    if (has("peers-only")) {
        o.main = false;
        o.bandwidth = false;
    }
    if (has("spawn")) {
        const auto n = parseSizes(valueOf(parser, "spawn"));
        if (!n || n->size() != 1 || (*n)[0] < 1) {
            err << "forcelab-cli bench: --spawn: expected a positive integer, got '" << echo(valueOf(parser, "spawn"))
                << "'\n";
            return 2;
        }
        o.spawnSize = (*n)[0];
    }
    if (has("spawn-only")) {
        if (o.spawnSize == 0) {
            err << "forcelab-cli bench: --spawn-only needs --spawn N\n";
            return 2;
        }
        o.main = o.peers = o.bandwidth = false;
    }
    std::unique_ptr<sim::ThreadLimit> limit;
    if (has("threads")) {
        const auto t = parseSizes(valueOf(parser, "threads"));
        if (!t || t->size() != 1 || (*t)[0] < 1 || (*t)[0] > sim::kMostThreads) {
            err << "forcelab-cli bench: --threads: expected an integer in [1, " << sim::kMostThreads << "], got '"
                << echo(valueOf(parser, "threads")) << "'\n";
            return 2;
        }
        limit = std::make_unique<sim::ThreadLimit>((*t)[0]);
    }
    out << "Threads for the solver's passes: " << sim::availableThreads()
        << " (step ms is wall-clock time; cpu columns are the calling thread's CPU time)\n";
    // The CSV is written all or nothing, and whether it can be written at
    // all is found out before the bench runs.
    std::optional<lessons::AtomicFile> csvOut;
    std::ostringstream csv;
    if (!csvFile.empty()) {
        csvOut.emplace(QString::fromStdString(csvFile));
        if (!csvOut->open()) {
            err << "forcelab-cli bench: --csv: " << csvOut->error().toStdString() << "\n";
            return 2;
        }
    }
    sim::runCollisionBench(o, out, csvOut ? &csv : nullptr);
    if (csvOut) {
        if (!csvOut->write(QByteArray::fromStdString(csv.str())) || !csvOut->commit()) {
            err << "forcelab-cli bench: --csv: " << csvOut->error().toStdString() << "\n";
            return 2;
        }
        out << "\nCSV written to " << csvFile << "\n";
    }
    return 0;
}

} // namespace forcelab::cli
