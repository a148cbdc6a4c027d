#include "ui/docks/code_snippets.h"

#include "sim/world/parameters.h"

#include <QDirIterator>
#include <QFile>
#include <QRegularExpression>

namespace forcelab {

namespace {

const QString kSourceRoot = QStringLiteral(":/sim-source");

/// The value a parameter row stores for `text`: a choice's index, 1/0 for a
/// switch, or the number; nullopt when the row cannot take it.
std::optional<double> valueOf(const sim::Parameter& p, const QString& text)
{
    switch (p.type) {
    case sim::ParameterType::Choice: {
        const int i = sim::choiceIndex(p, text.toStdString());
        return i < 0 ? std::nullopt : std::optional<double>(i);
    }
    case sim::ParameterType::Boolean:
        if (text == QStringLiteral("true") || text == QStringLiteral("false"))
            return text == QStringLiteral("true") ? 1.0 : 0.0;
        return std::nullopt;
    case sim::ParameterType::Number:
    case sim::ParameterType::Integer:
        break;
    }
    bool ok = false;
    const double v = text.toDouble(&ok);
    return ok ? std::optional<double>(v) : std::nullopt;
}

SettingTest parseTest(const QString& text)
{
    const qsizetype eq = text.indexOf(QLatin1Char('='));
    if (eq <= 0)
        return {};
    return SettingTest{text.left(eq).trimmed(), text.mid(eq + 1).trimmed()};
}

} // namespace

bool SettingTest::valid() const
{
    const sim::Parameter* p = sim::findParameter(key.toStdString());
    return p && valueOf(*p, value);
}

bool SettingTest::holds(const sim::WorldSettings& settings) const
{
    const sim::Parameter* p = sim::findParameter(key.toStdString());
    if (!p)
        return false;
    const auto v = valueOf(*p, value);
    return v && p->get(settings) == *v;
}

QStringList CodeRegion::keys() const
{
    QStringList out;
    if (!test.key.isEmpty())
        out << test.key;
    for (const CodeLine& l : lines)
        if (!l.test.key.isEmpty() && !out.contains(l.test.key))
            out << l.test.key;
    return out;
}

QList<CodeRegion> parseCodeRegions(const QString& text, const QString& file, QStringList* problems)
{
    static const QRegularExpression open(QStringLiteral(R"(^\s*// \[code ([\w.-]+)(?: if ([\w.]+=[\w.-]+))?: ([^\]]+)\]\s*$)"));
    static const QRegularExpression close(QStringLiteral(R"(^\s*// \[/code\]\s*$)"));
    static const QRegularExpression lineTest(QStringLiteral(R"(\s*// \[if ([\w.]+=[\w.-]+)\]\s*$)"));
    auto complain = [&](int line, const QString& what) {
        if (problems)
            *problems << QStringLiteral("%1:%2: %3").arg(file).arg(line).arg(what);
    };
    QList<CodeRegion> regions;
    std::optional<CodeRegion> current;
    int openedAt = 0;
    const QStringList lines = text.split(QLatin1Char('\n'));
    for (qsizetype k = 0; k < lines.size(); ++k) {
        const int number = static_cast<int>(k) + 1;
        const QString& line = lines[k];
        if (const auto m = open.match(line); m.hasMatch()) {
            if (current)
                complain(number, QStringLiteral("a region opens inside region %1").arg(current->name));
            current = CodeRegion{m.captured(1), m.captured(3).trimmed(), file, parseTest(m.captured(2)), {}};
            openedAt = number;
            if (!m.captured(2).isEmpty() && !current->test.valid())
                complain(number, QStringLiteral("%1 is not a parameter and a value it can take").arg(m.captured(2)));
            continue;
        }
        if (close.match(line).hasMatch()) {
            if (!current)
                complain(number, QStringLiteral("[/code] without a region"));
            else
                regions << *current;
            current.reset();
            continue;
        }
        if (line.contains(QStringLiteral("// [code")))
            complain(number, QStringLiteral("a [code …] marker that does not parse"));
        if (!current)
            continue;
        CodeLine l{number, line, {}};
        if (const auto m = lineTest.match(line); m.hasMatch()) {
            l.text = line.left(m.capturedStart());
            l.test = parseTest(m.captured(1));
            if (!l.test.valid())
                complain(number, QStringLiteral("%1 is not a parameter and a value it can take").arg(m.captured(1)));
        }
        current->lines << l;
    }
    if (current)
        complain(openedAt, QStringLiteral("region %1 is never closed with // [/code]").arg(current->name));
    return regions;
}

const QList<CodeRegion>& builtInCodeRegions()
{
    static const QList<CodeRegion> regions = [] {
        QList<CodeRegion> all;
        QDirIterator it(kSourceRoot, QDir::Files, QDirIterator::Subdirectories);
        QStringList files;
        while (it.hasNext())
            files << it.next();
        files.sort();
        for (const QString& path : files) {
            QFile f(path);
            if (!f.open(QIODevice::ReadOnly))
                continue;
            all << parseCodeRegions(QString::fromUtf8(f.readAll()), path.mid(kSourceRoot.size() + 1));
        }
        return all;
    }();
    return regions;
}

QList<const CodeRegion*> regionsFor(const sim::WorldSettings& settings, const QStringList& controlKeys)
{
    QList<const CodeRegion*> out;
    for (const CodeRegion& r : builtInCodeRegions()) {
        bool shown = r.test.key.isEmpty() || r.test.holds(settings);
        for (const QString& key : r.keys())
            shown = shown || controlKeys.contains(key);
        if (shown)
            out << &r;
    }
    return out;
}

} // namespace forcelab
