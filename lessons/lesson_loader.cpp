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

/// A problem with the input as a whole, or at a key path (no line known).
sim::Error problem(const QString& source, const QString& message, const QString& keyPath = {})
{
    sim::Error e = sim::keyError(keyPath.toStdString(), message.toStdString());
    e.source = source.toStdString();
    return e;
}

/// A problem at a place in the text.
sim::Error problemAt(const QString& source, TextPosition p, const QString& keyPath, const QString& message)
{
    sim::Error e = problem(source, message, keyPath);
    e.line = p.line;
    e.column = p.column;
    return e;
}

sim::Error tooLarge(const QString& source, qint64 bytes)
{
    return problem(source, QStringLiteral("the file has %1 bytes, more than the limit of %2 bytes (16 MiB)")
                               .arg(bytes)
                               .arg(kMaxFileBytes));
}

LoadResult failure(QList<sim::Error> problems)
{
    LoadResult r;
    r.problems = std::move(problems);
    return r;
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

/// The override that an error on `keyPath` belongs to: the last one that set
/// this path, a path inside it, or a path on the way to it; else none (the file).
const Override* overrideFor(const QString& keyPath, const QList<Override>& overrides)
{
    for (qsizetype i = overrides.size() - 1; i >= 0; --i) {
        const QString& p = overrides[i].keyPath;
        if (p == keyPath || p.startsWith(keyPath + QLatin1Char('.')) || keyPath.startsWith(p + QLatin1Char('.')))
            return &overrides[i];
    }
    return nullptr;
}

/// A problem found at a key path of the lesson: it belongs to the override
/// that set the path, or else to the file, where it is located in the text.
sim::Error problemAtKey(const QString& keyPath, const QString& message, const QString& source, const QByteArray& json,
                        const QList<Override>& overrides)
{
    if (const Override* o = overrideFor(keyPath, overrides))
        return problem(overrideSource(*o), message, keyPath);
    if (const auto p = positionOfKeyPath(json, keyPath, kMaxDepth))
        return problemAt(source, *p, keyPath, message);
    return problem(source, message, keyPath);
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

QString errorLine(const sim::Error& error)
{
    return QString::fromStdString(sim::toString(error));
}

QStringList LoadResult::errors() const
{
    QStringList lines;
    for (const sim::Error& e : problems)
        lines << errorLine(e);
    return lines;
}

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
    return failure({problem(pathOrId, QStringLiteral("%1; built-in lessons: %2")
                                          .arg(looksLikePath ? QStringLiteral("no such file")
                                                             : QStringLiteral("no such file or built-in lesson"),
                                               ids.join(QStringLiteral(", "))))});
}

LoadResult LessonLoader::loadFile(const QString& path, const QList<Override>& overrides)
{
    QFile file(path);
    const QFileInfo info(path);
    if (info.isDir())
        return failure({problem(path, QStringLiteral("is a folder, not a lesson file; give one of the .json files in it"))});
    if (info.exists() && !info.isFile())
        return failure({problem(path, QStringLiteral("is not a file"))});
    if (!file.open(QIODevice::ReadOnly))
        return failure({problem(path, QStringLiteral("cannot open: ") + file.errorString())});
    // Check the size before reading so a huge file costs nothing.
    if (file.size() > kMaxFileBytes)
        return failure({tooLarge(path, file.size())});
    const QByteArray bytes = file.read(kMaxFileBytes + 1);
    if (file.error() != QFileDevice::NoError)
        return failure({problem(path, QStringLiteral("cannot read: ") + file.errorString())});
    return loadBytes(bytes, path, overrides);
}

LoadResult LessonLoader::loadBytes(const QByteArray& json, const QString& source, const QList<Override>& overrides)
{
    if (json.size() > kMaxFileBytes)
        return failure({tooLarge(source, json.size())});
    if (const auto bad = firstInvalidUtf8(json))
        return failure({problemAt(source, positionOf(json, *bad), {},
                                  QStringLiteral("bytes that are not UTF-8 text; save the file as UTF-8"))});

    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        // Qt gives up at its own depth (1024), far past ours, without a key
        // path: our scan finds where the lesson first went past ours.
        if (parseError.error == QJsonParseError::DeepNesting) {
            const QList<StructureProblem> deep = scanStructure(json, kMaxDepth, 1);
            if (!deep.isEmpty())
                return failure({problemAt(source, deep.first().position, deep.first().keyPath, deep.first().problem)});
            return failure({problemAt(source, positionOf(json, parseError.offset), {},
                                      QStringLiteral("nested deeper than %1 levels").arg(kMaxDepth))});
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
        return failure({problemAt(source, positionOf(json, offset), {}, QStringLiteral("syntax error: ") + what)});
    }

    QList<sim::Error> errors;
    for (const StructureProblem& p : scanStructure(json, kMaxDepth, kMaxErrors))
        errors << problemAt(source, p.position, p.keyPath, p.problem);
    if (!errors.isEmpty())
        return failure(errors);
    if (!doc.isObject())
        return failure({problem(source, QStringLiteral("the lesson must be one JSON object { … }"))});

    QJsonObject root = doc.object();
    for (const Override& o : overrides) {
        QString why;
        const auto value = overrideValue(o, &why);
        if (!value) {
            errors << problem(overrideSource(o), why, o.keyPath);
            continue;
        }
        if (const auto e = applyOverride(root, o.keyPath, *value))
            errors << problem(overrideSource(o), e->problem, e->keyPath);
    }
    if (!errors.isEmpty())
        return failure(errors);

    ParseResult parsed = parseLesson(root);
    for (const KeyProblem& p : parsed.problems)
        errors << problemAtKey(p.keyPath, p.problem, source, json, overrides);
    if (parsed.unlisted > 0)
        errors << problem(source, QStringLiteral("%1 more problems not listed").arg(parsed.unlisted));
    if (!errors.isEmpty())
        return failure(errors);

    // Checks across fields (e.g. the exact integrator with drag) live in the
    // simulation core, so the workbench and the loader agree on them.
    if (const std::optional<sim::Error> e = sim::validateScene(parsed.lesson.scene))
        return failure({problemAtKey(QString::fromStdString(e->keyPath), QString::fromStdString(e->message), source,
                                     json, overrides)});

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
