// forcelab-cli handbook --out FILE.html: the teacher's handbook of the
// built-in lessons, one printable HTML page.

#include "cli_commands.h"

#include "lessons/atomic_file.h"
#include "ui/drawing/handbook.h"

#include <QFile>

namespace forcelab::cli {

void declareHandbook(QCommandLineParser& p)
{
    p.addOption({QStringLiteral("out"), QStringLiteral("The HTML file to write."), QStringLiteral("FILE.html")});
}

int handbookCommand(const QCommandLineParser& parser, std::ostream& out, std::ostream& err)
{
    const std::string path = valueOf(parser, "out");
    if (path.empty() || !parser.positionalArguments().isEmpty()) {
        err << "forcelab-cli handbook: give --out FILE.html and nothing else\n";
        return 2;
    }
    QString why;
    if (!lessons::writeFileAtomically(QString::fromStdString(path), builtInHandbookHtml().toUtf8(), &why)) {
        err << "forcelab-cli handbook: " << why.toStdString() << " (an old file there is unchanged)\n";
        return 2;
    }
    out << "wrote " << path << "\n";
    return 0;
}

} // namespace forcelab::cli
