// forcelab-cli: ForceLab without a window. Thin: picks the subcommand.

#include "cli_commands.h"

#include "sim/parameter_reference.h"

#include <QCoreApplication>
#include <QGuiApplication>

#include <algorithm>
#include <memory>

#include <iostream>
#include <string>
#include <vector>

namespace {

using Run = int (*)(const std::vector<std::string>&, std::ostream&, std::ostream&);

// One row per subcommand: the top-level usage and each `COMMAND --help` are
// written from it, so a subcommand's usage is stated once.
struct Command {
    const char* name;
    const char* synopsis; ///< the arguments, on as many lines as they need
    const char* summary;  ///< what it does
    Run run;
};

int paramsCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err)
{
    if (!args.empty()) {
        err << "forcelab-cli params: takes no arguments\n";
        return 2;
    }
    out << forcelab::sim::parameterReference();
    return 0;
}

const Command kCommands[] = {
    {"run",
     "run LESSON [--integrator NAME] [--dt S] [--substeps K] [--tolerance T]\n"
     "             [--steps N | --time T] [--seed S] [--set KEY.PATH=VALUE]... [--json]",
     "run a lesson (a file, or a built-in id such as 'gravity') headless; --time T ends at T",
     &forcelab::cli::runCommand},
    {"check", "check [LESSON...]",
     "run the claims lessons make about their scenes (every built-in lesson when none is named):\n"
     "      exit 0 when all hold, 1 when one does not",
     &forcelab::cli::checkCommand},
    {"handbook", "handbook --out FILE.html",
     "write the teacher's handbook: every lesson with its goal, answers, misconceptions and checked claims",
     &forcelab::cli::handbookCommand},
    {"validate", "validate FILE...",
     "check lesson files and list every problem (exit 0 when all are valid, 2 otherwise)",
     &forcelab::cli::validateCommand},
    {"bench",
     "bench [--quick] [--csv FILE] [--runs K] [--sizes N,N,...] [--brute-limit N]\n"
     "        [--profile] [--no-peers | --peers-only] [--peer-sizes N,N,...] [--speculative S]",
     "time collision detection and whole steps at several ball counts; --profile adds\n"
     "      the per-stage times of one step at the largest size",
     &benchCommand},
    {"sweep", "sweep [--problem NAME] [--quick] [--csv FILE] [--png FILE]",
     "error against cost of every integrator on problems with known answers", &forcelab::cli::sweepCommand},
    {"render", "render LESSON --time T --out FILE.png [--size WxH]",
     "draw a lesson at simulated time T as the workbench's canvas shows it", &forcelab::cli::renderCommand},
    {"soak", "soak [--steps N] [--balls N]",
     "a long run of a box with collisions: energy, NaN and memory over 10^6 steps", &forcelab::cli::soakCommand},
    {"params", "params",
     "print the parameter reference (docs/parameters.md): every setting, its unit, default and range",
     &paramsCommand},
};

void usage(std::ostream& out)
{
    out << "usage: forcelab-cli COMMAND [ARGS]   (forcelab-cli COMMAND --help for one command)\ncommands:\n";
    for (const Command& c : kCommands)
        out << "  " << c.synopsis << "\n      " << c.summary << "\n";
}

bool asksForHelp(const std::vector<std::string>& args)
{
    return std::find_if(args.begin(), args.end(), [](const std::string& a) { return a == "--help" || a == "-h"; }) !=
           args.end();
}

} // namespace

int main(int argc, char** argv)
{
    std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
        usage(args.empty() ? std::cerr : std::cout);
        return args.empty() ? 2 : 0;
    }
    const std::string command = args[0];
    args.erase(args.begin());
    const auto found = std::find_if(std::begin(kCommands), std::end(kCommands),
                                    [&](const Command& c) { return command == c.name; });
    if (found == std::end(kCommands)) {
        std::cerr << "forcelab-cli: unknown command '" << command << "' (try:";
        for (const Command& c : kCommands)
            std::cerr << " " << c.name;
        std::cerr << ")\n";
        return 2;
    }
    if (asksForHelp(args)) { // before any application object: help needs no display and prints nothing else
        std::cout << "usage: forcelab-cli " << found->synopsis << "\n  " << found->summary << "\n";
        return 0;
    }
    // Drawing text needs a QGuiApplication (fonts); without a display it runs
    // on the offscreen platform. Everything else needs only QtCore.
    const bool draws =
        command == "render" || (command == "sweep" && std::find(args.begin(), args.end(), "--png") != args.end());
    if (draws && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    const std::unique_ptr<QCoreApplication> app =
        draws ? std::make_unique<QGuiApplication>(argc, argv) : std::make_unique<QCoreApplication>(argc, argv);
    return found->run(args, std::cout, std::cerr);
}
