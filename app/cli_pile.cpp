// forcelab-cli pile: the peer scene's pile followed in time
// (sim/studies/pile_study.h), with the solver's knobs as options, so each figure of
// the jitter study in docs/performance.md can be run again.

#include "cli_args.h"
#include "cli_commands.h"

#include "sim/studies/pile_study.h"
#include "sim/world/threads.h"

#include <cmath>
#include <functional>
#include <string>

namespace forcelab::cli {
namespace {

// One numeric option: its name, what it sets (with the unit), its range, and
// whether it must be whole.
struct PileOption {
    const char* name;
    const char* help;
    double min, max;
    bool whole;
    std::function<void(sim::PileStudyOptions&, double)> set;
};

const std::vector<PileOption>& pileOptions()
{
    static const std::vector<PileOption> options = {
        {"balls", "Balls in the peer scene (default 5000).", 1, 1000000, true,
         [](sim::PileStudyOptions& o, double v) { o.balls = static_cast<int>(v); }},
        {"substeps", "Sub-steps per 1/60 s step (default 1).", 1, 64, true,
         [](sim::PileStudyOptions& o, double v) { o.substeps = static_cast<int>(v); }},
        {"seconds", "Simulated time in s (default 10).", 0.1, 600, false,
         [](sim::PileStudyOptions& o, double v) { o.seconds = v; }},
        {"every", "Seconds between two rows (default 0.5).", 1.0 / 60.0, 600, false,
         [](sim::PileStudyOptions& o, double v) { o.every = v; }},
        {"restitution", "Restitution e of balls and walls (default 0.9).", 0, 1, false,
         [](sim::PileStudyOptions& o, double v) { o.restitution = v; }},
        {"velocity-passes", "Most velocity passes per sub-step (default 30).", 1, 10000, true,
         [](sim::PileStudyOptions& o, double v) { o.solver.velocityPasses = static_cast<int>(v); }},
        {"position-passes", "Passes of positional correction per sub-step (default 4).", 1, 1000, true,
         [](sim::PileStudyOptions& o, double v) { o.solver.positionPasses = static_cast<int>(v); }},
        {"correction", "Share of the overlap beyond the slop removed per pass (default 0.8; 0: none).", 0, 1, false,
         [](sim::PileStudyOptions& o, double v) { o.solver.correction = v; }},
        {"slop", "Overlap allowed, as a share of the smaller radius (default 0.005).", 0, 0.5, false,
         [](sim::PileStudyOptions& o, double v) { o.solver.slop = v; }},
        {"resting-factor", "c in v_rest = c |g| h: slower approaches do not bounce (default 2).", 0, 1000, false,
         [](sim::PileStudyOptions& o, double v) { o.solver.restingFactor = v; }},
        {"stages", "Solver stages per sub-step (default 6; 1: one stage with positional correction).", 1, 64, true,
         [](sim::PileStudyOptions& o, double v) { o.solver.stages = static_cast<int>(v); }},
        {"stage-passes", "Velocity passes per stage that push overlaps apart (default 4).", 1, 1000, true,
         [](sim::PileStudyOptions& o, double v) { o.solver.stagePasses = static_cast<int>(v); }},
        {"relax-passes", "Velocity passes per stage after the move, without the push (default 1).", 0, 1000, true,
         [](sim::PileStudyOptions& o, double v) { o.solver.relaxPasses = static_cast<int>(v); }},
        {"bounce-layers", "The passes a bounce adds go to the rows this many balls from it (default 12; 0: every row).",
         0, 254, true, [](sim::PileStudyOptions& o, double v) { o.solver.bounceLayers = static_cast<int>(v); }},
        {"sleep-time", "Seconds a held ball stays still before it sleeps (default 0.5; 0: no sleeping).", 0, 1000,
         false, [](sim::PileStudyOptions& o, double v) { o.solver.sleepTime = v; }},
        {"wake-share", "A pair approaching faster than this share of v_rest wakes the sleepers near it (default 0.5).",
         0, 1000, false, [](sim::PileStudyOptions& o, double v) { o.solver.wakeShare = v; }},
        {"still-share", "A ball slower than this share of v_rest is still (default 0.1).", 0, 1000, false,
         [](sim::PileStudyOptions& o, double v) { o.solver.stillShare = v; }},
        {"stiffness", "A soft contact's spring frequency as a share of the stage rate (default 0.5).", 0.001, 1000,
         false, [](sim::PileStudyOptions& o, double v) { o.solver.contactStiffness = v; }},
        {"damping-ratio", "A soft contact's damping as a share of critical damping (default 1).", 0, 1000, false,
         [](sim::PileStudyOptions& o, double v) { o.solver.dampingRatio = v; }},
        {"threads", "Most threads for the solver's passes (default: every core; same bits for any count).", 1,
         sim::kMostThreads, true, [](sim::PileStudyOptions& o, double v) { o.threads = static_cast<int>(v); }},
    };
    return options;
}

} // namespace

void declarePile(QCommandLineParser& p)
{
    for (const PileOption& o : pileOptions())
        p.addOption({QString::fromLatin1(o.name), QString::fromLatin1(o.help),
                     o.whole ? QStringLiteral("N") : QStringLiteral("X")});
}

int pileCommand(const QCommandLineParser& parser, std::ostream& out, std::ostream& err)
{
    sim::PileStudyOptions study;
    for (const PileOption& o : pileOptions()) {
        if (!parser.isSet(QString::fromLatin1(o.name)))
            continue;
        const std::string text = valueOf(parser, o.name);
        const auto v = parseFiniteNumber(text);
        if (!v || *v < o.min || *v > o.max || (o.whole && std::floor(*v) != *v)) {
            err << "forcelab-cli pile: --" << o.name << ": expected " << (o.whole ? "a whole number" : "a number")
                << " in [" << o.min << ", " << o.max << "], got '" << echo(text) << "'\n";
            return 2;
        }
        o.set(study, *v);
    }
    // The header names the knobs the chosen solve reads.
    const sim::ContactSolverSettings& solver = study.solver;
    out << "Peer scene pile: " << study.balls << " balls (r = 5 px), e = " << study.restitution << ", "
        << study.substeps << " sub-step(s) of 1/60 s, ";
    if (solver.stages > 1) {
        out << solver.stages << " stages of " << solver.stagePasses << " + " << solver.relaxPasses
            << " passes, stiffness " << solver.contactStiffness << ", damping ratio " << solver.dampingRatio
            << ", a bounce's extra passes "
            << (solver.bounceLayers > 0 ? "within " + std::to_string(solver.bounceLayers) + " balls of it"
                                        : std::string("on every row"))
            << ", ";
        if (solver.sleepTime > 0.0)
            out << "balls still for " << solver.sleepTime << " s sleep\n";
        else
            out << "no sleeping\n";
    } else {
        out << "one stage: " << solver.velocityPasses << " velocity passes, " << solver.positionPasses
            << " position passes, correction " << solver.correction << ", slop " << solver.slop << " r\n";
    }
    sim::runPileStudy(study, &out);
    return 0;
}

} // namespace forcelab::cli
