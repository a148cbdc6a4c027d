// forcelab-cli: ForceLab without a window. Thin: picks the subcommand, lets
// it declare its options, parses them with QCommandLineParser and runs it.

#include "cli_commands.h"

#include "sim/world/parameter_reference.h"

#include <QCoreApplication>
#include <QGuiApplication>

#include <algorithm>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace forcelab::cli;

void declareNothing(QCommandLineParser&) {}

int paramsCommand(const QCommandLineParser&, std::ostream& out, std::ostream&)
{
    out << forcelab::sim::parameterReference();
    return 0;
}

// One row per subcommand: its name, what it does, its options and its work.
struct Command {
    const char* name;
    const char* summary;
    Declare declare;
    Run run;
};

const Command kCommands[] = {
    {"run", "Run a lesson (a file, or a built-in id such as 'gravity') headless and report the end state.",
     &declareRun, &runCommand},
    {"check", "Run the claims lessons make about their scenes (every built-in lesson when none is named); exit 0 "
              "when all hold, 1 when one does not.",
     &declareCheck, &checkCommand},
    {"validate", "Check lesson files and list every problem (exit 0 when all are valid, 2 otherwise).",
     &declareValidate, &validateCommand},
    {"handbook", "Write the teacher's handbook: every lesson with its goal, answers, misconceptions and checked "
                 "claims.",
     &declareHandbook, &handbookCommand},
    {"bench", "Time collision detection and whole steps at several ball counts.", &declareBench, &benchCommand},
    {"sweep", "Error against cost of every integrator on problems with known answers.", &declareSweep,
     &sweepCommand},
    {"render", "Draw a lesson at simulated time T as the workbench's canvas shows it.", &declareRender,
     &renderCommand},
    {"pile", "Follow the peer scene's pile as it settles: overlaps, jitter and height every half second.",
     &declarePile, &pileCommand},
    {"soak", "A long run of a box with collisions: energy, NaN and memory over 10^6 steps.", &declareSoak,
     &soakCommand},
    {"trace", "Write every step of a lesson (t, ball, x, y, vx, vy, ax, ay, the step's pair tests, contacts, wind "
              "and random draws) as CSV or JSON, with its settings.",
     &declareTrace, &traceCommand},
    {"compare", "Check a student's trace of a lesson against the reference: the first step and ball where it "
                "departs, by how much, and the likely cause; exit 0 when they agree, 1 when not, 2 for a bad file.",
     &declareCompare, &compareCommand},
    {"params", "Print the parameter reference (docs/parameters.md): every setting, its unit, default and range.",
     &declareNothing, &paramsCommand},
};

void usage(std::ostream& out)
{
    out << "usage: forcelab-cli COMMAND [OPTIONS]   (forcelab-cli COMMAND --help lists a command's options)\n"
           "commands:\n";
    for (const Command& c : kCommands)
        out << "  " << c.name << "\n      " << c.summary << "\n";
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
    const auto found = std::find_if(std::begin(kCommands), std::end(kCommands),
                                    [&](const Command& c) { return command == c.name; });
    if (found == std::end(kCommands)) {
        std::cerr << "forcelab-cli: unknown command '" << command << "' (try:";
        for (const Command& c : kCommands)
            std::cerr << " " << c.name;
        std::cerr << ")\n";
        return 2;
    }

    // Parsed before any application object: --help needs no display and
    // prints nothing else.
    QCommandLineParser parser;
    parser.setApplicationDescription(QString::fromUtf8(found->summary));
    const QCommandLineOption help = parser.addHelpOption();
    found->declare(parser);
    QStringList arguments{QStringLiteral("forcelab-cli ") + QString::fromLatin1(found->name)};
    for (std::size_t i = 1; i < args.size(); ++i)
        arguments << QString::fromLocal8Bit(args[i].c_str());
    if (!parser.parse(arguments)) {
        std::cerr << "forcelab-cli " << command << ": " << parser.errorText().toStdString() << " (forcelab-cli "
                  << command << " --help lists the options)\n";
        return 2;
    }
    if (parser.isSet(help)) {
        std::cout << parser.helpText()
                         .replace(QStringLiteral("<executable_name>"), QStringLiteral("forcelab-cli ") +
                                                                            QString::fromLatin1(found->name))
                         .toStdString();
        return 0;
    }
    // Drawing text needs a QGuiApplication (fonts); without a display it runs
    // on the offscreen platform. Everything else needs only QtCore.
    const bool draws = command == "render" || (command == "sweep" && parser.isSet(QStringLiteral("png")));
    if (draws && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    const std::unique_ptr<QCoreApplication> app =
        draws ? std::make_unique<QGuiApplication>(argc, argv) : std::make_unique<QCoreApplication>(argc, argv);
    return found->run(parser, std::cout, std::cerr);
}
