// forcelab-cli: ForceLab without a window. Thin: picks the subcommand.

#include "cli_commands.h"

#include <QCoreApplication>
#include <QGuiApplication>

#include <algorithm>
#include <memory>

#include <iostream>
#include <string>
#include <vector>

namespace {

void usage(std::ostream& out)
{
    out << "usage: forcelab-cli COMMAND [ARGS]\n"
           "commands:\n"
           "  run LESSON [--integrator NAME] [--dt S] [--substeps K] [--tolerance T]\n"
           "             [--steps N | --time T] [--seed S] [--set KEY.PATH=VALUE]... [--json]\n"
           "      run a lesson (a file, or a built-in id such as 'gravity') headless\n"
           "  validate FILE...\n"
           "      check lesson files and list every problem (exit 0 when all are valid, 2 otherwise)\n"
           "  bench [--quick] [--csv FILE] [--runs K] [--sizes N,N,...] [--brute-limit N]\n"
           "        [--profile] [--no-peers | --peers-only] [--peer-sizes N,N,...] [--speculative S]\n"
           "      time collision detection and whole steps at several ball counts; --profile adds\n"
           "      the per-stage times of one step at the largest size\n"
           "  sweep [--problem NAME] [--quick] [--csv FILE] [--png FILE]\n"
           "      error against cost of every integrator on problems with known answers\n"
           "  render LESSON --time T --out FILE.png [--size WxH]\n"
           "      draw a lesson at simulated time T as the workbench's canvas shows it\n"
           "  soak [--steps N] [--balls N]\n"
           "      a long run of a box with collisions: energy, NaN and memory over 10^6 steps\n";
}

} // namespace

int main(int argc, char** argv)
{
    std::vector<std::string> args(argv + 1, argv + argc);
    // Drawing text needs a QGuiApplication (fonts); without a display it runs
    // on the offscreen platform. Everything else needs only QtCore.
    const bool draws = !args.empty() && (args[0] == "render" ||
                                         (args[0] == "sweep" && std::find(args.begin(), args.end(), "--png") != args.end()));
    if (draws && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    const std::unique_ptr<QCoreApplication> app =
        draws ? std::make_unique<QGuiApplication>(argc, argv) : std::make_unique<QCoreApplication>(argc, argv);
    if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
        usage(args.empty() ? std::cerr : std::cout);
        return args.empty() ? 2 : 0;
    }
    const std::string command = args[0];
    args.erase(args.begin());
    if (command == "run")
        return forcelab::cli::runCommand(args, std::cout, std::cerr);
    if (command == "validate")
        return forcelab::cli::validateCommand(args, std::cout, std::cerr);
    if (command == "bench")
        return benchCommand(args, std::cout, std::cerr);
    if (command == "sweep")
        return forcelab::cli::sweepCommand(args, std::cout, std::cerr);
    if (command == "render")
        return forcelab::cli::renderCommand(args, std::cout, std::cerr);
    if (command == "soak")
        return forcelab::cli::soakCommand(args, std::cout, std::cerr);
    std::cerr << "forcelab-cli: unknown command '" << command
              << "' (try: run, validate, bench, sweep, render, soak)\n";
    return 2;
}
