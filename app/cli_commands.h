#pragma once
// The subcommands of forcelab-cli. Each declares its options on a
// QCommandLineParser (so `forcelab-cli COMMAND --help` lists them), and runs
// on the parsed options: results to `out`, one-line errors to `err`, and the
// exit code it returns (0 success, 1 a check failed, 2 bad input, 3 the
// simulation stopped because it blew up).

#include <QCommandLineParser>

#include <ostream>
#include <string>

namespace forcelab::cli {

using Declare = void (*)(QCommandLineParser& parser);
using Run = int (*)(const QCommandLineParser& parser, std::ostream& out, std::ostream& err);

/// The value of option `name` as a std::string (empty when not given).
inline std::string valueOf(const QCommandLineParser& parser, const char* name)
{
    return parser.value(QString::fromLatin1(name)).toStdString();
}

/// A value the user typed, for a message: whole when short, else its start
/// and its length (lessons/message_text.h), so a 100 KB argument is not
/// echoed whole.
std::string echo(const std::string& value);

void declareRun(QCommandLineParser& parser);
int runCommand(const QCommandLineParser& parser, std::ostream& out, std::ostream& err);

void declareValidate(QCommandLineParser& parser);
int validateCommand(const QCommandLineParser& parser, std::ostream& out, std::ostream& err);

void declareCheck(QCommandLineParser& parser);
int checkCommand(const QCommandLineParser& parser, std::ostream& out, std::ostream& err);

void declareHandbook(QCommandLineParser& parser);
int handbookCommand(const QCommandLineParser& parser, std::ostream& out, std::ostream& err);

void declareBench(QCommandLineParser& parser);
int benchCommand(const QCommandLineParser& parser, std::ostream& out, std::ostream& err);

void declareSweep(QCommandLineParser& parser);
int sweepCommand(const QCommandLineParser& parser, std::ostream& out, std::ostream& err);

void declareRender(QCommandLineParser& parser);
int renderCommand(const QCommandLineParser& parser, std::ostream& out, std::ostream& err);

void declarePile(QCommandLineParser& parser);
int pileCommand(const QCommandLineParser& parser, std::ostream& out, std::ostream& err);

void declareSoak(QCommandLineParser& parser);
int soakCommand(const QCommandLineParser& parser, std::ostream& out, std::ostream& err);

void declareTrace(QCommandLineParser& parser);
int traceCommand(const QCommandLineParser& parser, std::ostream& out, std::ostream& err);

void declareCompare(QCommandLineParser& parser);
int compareCommand(const QCommandLineParser& parser, std::ostream& out, std::ostream& err);

} // namespace forcelab::cli
