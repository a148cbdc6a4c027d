// forcelab-cli validate FILE...: checks lesson files with the loader the
// workbench uses and prints every problem, one line each.

#include "cli_commands.h"

#include "lessons/lesson_loader.h"

namespace forcelab::cli {

int validateCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err)
{
    if (args.empty()) {
        err << "usage: forcelab-cli validate FILE...\n";
        return 2;
    }
    bool allValid = true;
    for (const std::string& arg : args) {
        const QString path = QString::fromLocal8Bit(arg.c_str());
        // Files only: a built-in id is not a file to check.
        const LoadResult r = LessonLoader::loadFile(path);
        if (r.ok()) {
            out << arg << ": ok\n";
            continue;
        }
        allValid = false;
        for (const QString& line : r.errors)
            err << line.toStdString() << "\n";
    }
    return allValid ? 0 : 2;
}

} // namespace forcelab::cli
