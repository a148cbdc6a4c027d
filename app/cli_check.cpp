// forcelab-cli check [LESSON...]: runs the claims of lessons (every built-in
// lesson when none is named) and reports each one.

#include "cli_commands.h"

#include "lessons/lesson_loader.h"

#include <QFileInfo>

namespace forcelab::cli {

namespace {

// A table cell: one line, no column breaks.
std::string cell(std::string text)
{
    for (char& c : text)
        if (c == '\n')
            c = ' ';
    std::string out;
    for (char c : text) {
        if (c == '|')
            out += '\\';
        out += c;
    }
    return out;
}

} // namespace

void declareCheck(QCommandLineParser& p)
{
    p.addOption(QCommandLineOption(QStringLiteral("markdown"),
                                   QStringLiteral("Print the claims as Markdown tables, one per lesson (docs/lessons.md "
                                                  "holds this list; a test compares the two).")));
    p.addPositionalArgument(QStringLiteral("lessons"), QStringLiteral("Lesson files or built-in ids (default: all built-in)."),
                            QStringLiteral("[LESSON...]"));
}

int checkCommand(const QCommandLineParser& parser, std::ostream& out, std::ostream& err)
{
    QStringList lessons = parser.positionalArguments();
    if (lessons.isEmpty())
        lessons = LessonLoader::builtInFiles();
    const bool markdown = parser.isSet(QStringLiteral("markdown"));
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
        if (markdown && !r.lesson->claims.empty())
            out << "\n### " << label << ": " << r.lesson->title.toStdString() << "\n\n"
                << "| the lesson says | measurement | result |\n|---|---|---|\n";
        for (const sim::Claim& claim : r.lesson->claims) {
            const sim::ClaimResult result = sim::checkClaim(r.lesson->scene, claim);
            ++claims;
            failed += result.holds ? 0 : 1;
            if (!markdown) {
                out << label << ": " << sim::describe(claim, result) << "\n";
                continue;
            }
            std::string what = claim.measure + (claim.set.empty() ? "" : " (with its own settings)");
            out << "| " << cell(claim.text) << " | " << cell(what) << " | " << (result.holds ? "holds: " : "FAILS: ")
                << cell(result.explanation) << " |\n";
        }
    }
    if (markdown)
        out << "\n";
    out << claims << (claims == 1 ? " claim" : " claims") << " in " << withClaims << " of " << lessons.size()
        << (lessons.size() == 1 ? " lesson" : " lessons") << ": ";
    if (failed == 0)
        out << (claims == 1 ? "it holds" : "all hold") << "\n";
    else
        out << failed << " of them " << (failed == 1 ? "does" : "do") << " not hold\n";
    return failed == 0 ? 0 : 1;
}

} // namespace forcelab::cli
