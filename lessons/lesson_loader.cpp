#include "lesson_loader.h"

#include "json_text_checks.h"
#include "lesson_controls.h"
#include "lesson_limits.h"
#include "lesson_overrides.h"
#include "lesson_parser.h"
#include "sim/world.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>

namespace forcelab {

using namespace lessons;

namespace {

const QString kResourceDir = QStringLiteral(":/lessons");

QString tooLarge(const QString& source, qint64 bytes)
{
    return QStringLiteral("%1: the file has %2 bytes, more than the limit of %3 bytes (16 MiB)")
        .arg(source)
        .arg(bytes)
        .arg(kMaxFileBytes);
}

LoadResult failure(QStringList errors)
{
    LoadResult r;
    r.errors = std::move(errors);
    return r;
}

QString at(const QString& source, const QByteArray& text, qsizetype offset)
{
    const TextPosition p = positionOf(text, offset);
    return QStringLiteral("%1:%2:%3").arg(source).arg(p.line).arg(p.column);
}

/// Qt's parse errors in words that point at the usual cause.
QString syntaxProblem(const QJsonParseError& e)
{
    switch (e.error) {
    case QJsonParseError::UnterminatedObject:
        return QStringLiteral("expected , or } here (a missing comma, or a { that is never closed)");
    case QJsonParseError::UnterminatedArray:
        return QStringLiteral("expected , or ] here (a missing comma, or a [ that is never closed)");
    case QJsonParseError::MissingNameSeparator:
        return QStringLiteral("expected : after the key");
    case QJsonParseError::MissingValueSeparator:
        return QStringLiteral("expected , between two values");
    case QJsonParseError::IllegalValue:
        return QStringLiteral("not a JSON value (text needs \"double quotes\"; true, false and null are lower case; "
                              "no comma before } or ])");
    case QJsonParseError::IllegalNumber:
        return QStringLiteral("not a valid value (text needs \"double quotes\"; a number must fit a double, "
                              "e.g. 1e999 does not)");
    case QJsonParseError::UnterminatedString:
        return QStringLiteral("a string that is never closed with \"");
    case QJsonParseError::IllegalEscapeSequence:
        return QStringLiteral("an unknown escape after \\ in a string");
    case QJsonParseError::GarbageAtEnd:
        return QStringLiteral("more text after the end of the lesson object");
    default:
        return e.errorString();
    }
}

/// The source an error on `keyPath` belongs to: the last override that set
/// this path, a path inside it, or a path on the way to it; else the file.
QString sourceFor(const QString& keyPath, const QString& fileSource, const QList<Override>& overrides)
{
    for (qsizetype i = overrides.size() - 1; i >= 0; --i) {
        const QString& p = overrides[i].keyPath;
        if (p == keyPath || p.startsWith(keyPath + QLatin1Char('.')) || keyPath.startsWith(p + QLatin1Char('.')))
            return overrideSource(overrides[i]);
    }
    return fileSource;
}

/// The JSON of a built-in lesson, for matching its id without a full load.
QString builtInId(const QString& resource)
{
    QFile f(resource);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QJsonDocument::fromJson(f.readAll()).object().value(QStringLiteral("id")).toString();
}

} // namespace

LoadResult LessonLoader::load(const QString& pathOrId, const QList<Override>& overrides)
{
    if (QFileInfo(pathOrId).exists()) // a file, or a folder that loadFile names as one
        return loadFile(pathOrId, overrides);
    // A built-in lesson by file stem ("07-gravity") or by id ("gravity").
    const QStringList builtIn = builtInFiles();
    for (const QString& resource : builtIn)
        if (QFileInfo(resource).completeBaseName() == pathOrId)
            return loadFile(resource, overrides);
    for (const QString& resource : builtIn)
        if (builtInId(resource) == pathOrId)
            return loadFile(resource, overrides);

    QStringList ids;
    for (const QString& resource : builtIn)
        ids << builtInId(resource);
    const bool looksLikePath = pathOrId.contains(QLatin1Char('/')) || pathOrId.endsWith(QStringLiteral(".json"));
    return failure({QStringLiteral("%1: %2; built-in lessons: %3")
                        .arg(pathOrId,
                             looksLikePath ? QStringLiteral("no such file") : QStringLiteral("no such file or built-in lesson"),
                             ids.join(QStringLiteral(", ")))});
}

LoadResult LessonLoader::loadFile(const QString& path, const QList<Override>& overrides)
{
    QFile file(path);
    const QFileInfo info(path);
    if (info.isDir())
        return failure({path + QStringLiteral(": is a folder, not a lesson file; give one of the .json files in it")});
    if (info.exists() && !info.isFile())
        return failure({path + QStringLiteral(": is not a file")});
    if (!file.open(QIODevice::ReadOnly))
        return failure({path + QStringLiteral(": cannot open: ") + file.errorString()});
    // Check the size before reading so a huge file costs nothing.
    if (file.size() > kMaxFileBytes)
        return failure({tooLarge(path, file.size())});
    const QByteArray bytes = file.read(kMaxFileBytes + 1);
    if (file.error() != QFileDevice::NoError)
        return failure({path + QStringLiteral(": cannot read: ") + file.errorString()});
    return loadBytes(bytes, path, overrides);
}

LoadResult LessonLoader::loadBytes(const QByteArray& json, const QString& source, const QList<Override>& overrides)
{
    if (json.size() > kMaxFileBytes)
        return failure({tooLarge(source, json.size())});
    if (const auto bad = firstInvalidUtf8(json))
        return failure({at(source, json, *bad) +
                        QStringLiteral(": bytes that are not UTF-8 text; save the file as UTF-8")});

    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        // Qt gives up at its own depth (1024), far past ours, without a key
        // path: our scan finds where the lesson first went past ours.
        if (parseError.error == QJsonParseError::DeepNesting) {
            const QList<StructureProblem> deep = scanStructure(json, kMaxDepth, 1);
            if (!deep.isEmpty())
                return failure({QStringLiteral("%1:%2:%3: %4: %5")
                                    .arg(source)
                                    .arg(deep.first().position.line)
                                    .arg(deep.first().position.column)
                                    .arg(deep.first().keyPath, deep.first().problem)});
            return failure({at(source, json, parseError.offset) +
                            QStringLiteral(": nested deeper than %1 levels").arg(kMaxDepth)});
        }
        // Qt's offset lies just past the offending token, except for trailing garbage.
        // Qt's offset lies just past the offending token, except for trailing
        // garbage and bad numbers, where we look for the token's start.
        qsizetype offset = parseError.offset;
        if (parseError.error == QJsonParseError::IllegalNumber) {
            while (offset > 0 && QByteArrayView("0123456789+-.eE").contains(json[offset - 1]))
                --offset;
        } else if (parseError.error != QJsonParseError::GarbageAtEnd) {
            offset = std::max<qsizetype>(0, offset - 1);
        }
        const QString what = syntaxProblem(parseError);
        return failure({at(source, json, offset) + QStringLiteral(": syntax error: ") + what});
    }

    QStringList errors;
    for (const StructureProblem& p : scanStructure(json, kMaxDepth, kMaxErrors))
        errors << QStringLiteral("%1:%2:%3: %4: %5")
                      .arg(source)
                      .arg(p.position.line)
                      .arg(p.position.column)
                      .arg(p.keyPath, p.problem);
    if (!errors.isEmpty())
        return failure(errors);
    if (!doc.isObject())
        return failure({source + QStringLiteral(": the lesson must be one JSON object { … }")});

    QJsonObject root = doc.object();
    for (const Override& o : overrides) {
        QString problem;
        const auto value = overrideValue(o, &problem);
        if (!value) {
            errors << overrideSource(o) + QStringLiteral(": ") + o.keyPath + QStringLiteral(": ") + problem;
            continue;
        }
        if (const auto e = applyOverride(root, o.keyPath, *value))
            errors << overrideSource(o) + QStringLiteral(": ") + *e;
    }
    if (!errors.isEmpty())
        return failure(errors);

    ParseResult parsed = parseLesson(root);
    for (const KeyProblem& p : parsed.problems)
        errors << sourceFor(p.keyPath, source, overrides) + QStringLiteral(": ") +
                      (p.keyPath.isEmpty() ? p.problem : p.keyPath + QStringLiteral(": ") + p.problem);
    if (parsed.unlisted > 0)
        errors << source + QStringLiteral(": %1 more problems not listed").arg(parsed.unlisted);
    if (!errors.isEmpty())
        return failure(errors);

    // Checks across fields (e.g. the exact integrator with drag) live in the
    // simulation core, so the workbench and the loader agree on them.
    std::optional<std::string> problem = sim::validateSettings(parsed.lesson.scene.settings);
    if (!problem)
        problem = sim::validateSpawn(parsed.lesson.scene.spawn);
    if (problem) {
        const QString text = QString::fromStdString(*problem);
        const QString keyPath = text.section(QStringLiteral(": "), 0, 0);
        return failure({sourceFor(keyPath, source, overrides) + QStringLiteral(": ") + text});
    }

    parsed.lesson.source = source;
    LoadResult result;
    result.lesson = std::move(parsed.lesson);
    return result;
}

QStringList LessonLoader::builtInFiles()
{
    QStringList files;
    const QStringList names = QDir(kResourceDir).entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name);
    for (const QString& name : names)
        files << kResourceDir + QLatin1Char('/') + name;
    return files;
}

QStringList LessonLoader::overlayNames()
{
    return lessons::overlayNames();
}

QStringList LessonLoader::controlNames()
{
    return lessons::controlNames();
}

std::optional<Override> LessonLoader::parseOverride(const QString& text, QString* error)
{
    const qsizetype eq = text.indexOf(QLatin1Char('='));
    static const QRegularExpression keyPath(QStringLiteral("^[A-Za-z0-9_]+(\\.[A-Za-z0-9_]+)*$"));
    if (eq <= 0) {
        if (error)
            *error = QStringLiteral("expected KEY.PATH=VALUE, e.g. models.gravity.y=0");
        return std::nullopt;
    }
    const QString key = text.left(eq).trimmed();
    if (!keyPath.match(key).hasMatch()) {
        if (error)
            *error = QStringLiteral("\"%1\" is not a key path; write keys separated by dots, e.g. models.gravity.y")
                         .arg(key);
        return std::nullopt;
    }
    return Override{key, text.mid(eq + 1)};
}

} // namespace forcelab
