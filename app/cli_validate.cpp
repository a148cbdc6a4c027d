// forcelab-cli validate FILE...: checks lesson files with the loader the
// workbench uses and prints every problem, one line each.

#include "cli_commands.h"

#include "lessons/lesson_loader.h"

namespace forcelab::cli {

void declareValidate(QCommandLineParser& p)
{
    p.addPositionalArgument(QStringLiteral("files"), QStringLiteral("Lesson files to check."), QStringLiteral("FILE..."));
}

int validateCommand(const QCommandLineParser& parser, std::ostream& out, std::ostream& err)
{
    const QStringList files = parser.positionalArguments();
    if (files.isEmpty()) {
        err << "forcelab-cli validate: give one or more lesson files\n";
        return 2;
    }
    bool allValid = true;
    for (const QString& path : files) {
        const std::string arg = path.toStdString();
        // Files only: a built-in id is not a file to check.
        const LoadResult r = LessonLoader::loadFile(path);
        if (r.ok()) {
            out << arg << ": ok\n";
            continue;
        }
        allValid = false;
        for (const QString& line : r.errors())
            err << line.toStdString() << "\n";
    }
    return allValid ? 0 : 2;
}

} // namespace forcelab::cli
