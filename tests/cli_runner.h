#pragma once
// Runs forcelab-cli as a user would: a process, its exit code, its output.
// FORCELAB_CLI_PATH is set by tests/CMakeLists.txt for the tests that use it.

#include <QProcess>
#include <QString>
#include <QStringList>
#include <QtGlobal>

namespace forcelab::test {

struct CliResult {
    int exitCode = -1; ///< -1 when the process crashed
    QString out;       ///< standard output, as UTF-8 text
    QString err;       ///< standard error, as UTF-8 text
};

inline CliResult runCli(const QStringList& args, int timeoutMs = 300000)
{
    QProcess p;
    p.start(QStringLiteral(FORCELAB_CLI_PATH), args);
    if (!p.waitForFinished(timeoutMs))
        qFatal("forcelab-cli did not finish");
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, QString::fromUtf8(p.readAllStandardOutput()),
            QString::fromUtf8(p.readAllStandardError())};
}

} // namespace forcelab::test
