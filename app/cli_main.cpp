// forcelab-cli: ForceLab without a window. Thin: picks the subcommand.

#include "cli_commands.h"

#include <QCoreApplication>

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
           "  bench [--quick] [--csv FILE]\n"
           "      time collision detection and whole steps at several ball counts\n";
}

} // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv); // resources and QtCore's file access
    std::vector<std::string> args(argv + 1, argv + argc);
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
    std::cerr << "forcelab-cli: unknown command '" << command << "' (try: run, validate, bench)\n";
    return 2;
}
