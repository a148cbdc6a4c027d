// forcelab-cli check [LESSON...]: runs the claims of lessons (every built-in
// lesson when none is named) and reports each one.

#include "cli_commands.h"

#include "lessons/lesson_loader.h"

#include <QFileInfo>

namespace forcelab::cli {

void declareCheck(QCommandLineParser& p)
{
    p.addPositionalArgument(QStringLiteral("lessons"), QStringLiteral("Lesson files or built-in ids (default: all built-in)."),
                            QStringLiteral("[LESSON...]"));
}

int checkCommand(const QCommandLineParser& parser, std::ostream& out, std::ostream& err)
{
    QStringList lessons = parser.positionalArguments();
    if (lessons.isEmpty())
        lessons = LessonLoader::builtInFiles();
    int claims = 0, failed = 0, withClaims = 0;
    for (const QString& name : lessons) {
        const LoadResult r = LessonLoader::load(name);
        if (!r.ok()) {
            for (const QString& line : r.errors())
                err << line.toStdString() << "\n";
            return 2;
        }
        const std::string label = QFileInfo(r.lesson->source).completeBaseName().toStdString();
        withClaims += r.lesson->claims.empty() ? 0 : 1;
        for (const sim::Claim& claim : r.lesson->claims) {
            const sim::ClaimResult result = sim::checkClaim(r.lesson->scene, claim);
            ++claims;
            failed += result.holds ? 0 : 1;
            out << label << ": " << sim::describe(claim, result) << "\n";
        }
    }
    out << claims << (claims == 1 ? " claim" : " claims") << " in " << withClaims << " of " << lessons.size()
        << (lessons.size() == 1 ? " lesson" : " lessons") << ": ";
    if (failed == 0)
        out << (claims == 1 ? "it holds" : "all hold") << "\n";
    else
        out << failed << " of them " << (failed == 1 ? "does" : "do") << " not hold\n";
    return failed == 0 ? 0 : 1;
}

} // namespace forcelab::cli
