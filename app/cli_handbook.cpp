// forcelab-cli handbook --out FILE.html: the teacher's handbook of the
// built-in lessons, one printable HTML page.

#include "cli_commands.h"

#include "ui/handbook.h"

#include <QFile>

namespace forcelab::cli {

int handbookCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err)
{
    if (args.size() != 2 || args[0] != "--out") {
        err << "usage: forcelab-cli handbook --out FILE.html\n";
        return 2;
    }
    QFile file(QString::fromLocal8Bit(args[1].c_str()));
    if (!file.open(QIODevice::WriteOnly) || file.write(builtInHandbookHtml().toUtf8()) < 0) {
        err << args[1] << ": cannot write: " << file.errorString().toStdString() << "\n";
        return 2;
    }
    out << "wrote " << args[1] << "\n";
    return 0;
}

} // namespace forcelab::cli
