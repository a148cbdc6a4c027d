#include "lesson_loader.h"

#include "json_text_checks.h"
#include "lesson_controls.h"
#include "lesson_limits.h"
#include "lesson_overrides.h"
#include "message_text.h"
#include "lesson_parser.h"
#include "sim/world/number_text.h"
#include "sim/world/world.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonArray>
#include <QJsonObject>
#include <QRegularExpression>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace forcelab {

using namespace lessons;

namespace {

const QString kResourceDir = QStringLiteral(":/lessons");

/// A problem with the input as a whole, or at a key path (no line known).
sim::Error problem(const QString& source, const QString& message, const QString& keyPath = {})
{
    sim::Error e = sim::keyError(cutKeyPath(keyPath).toStdString(), message.toStdString());
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

/// The longest start of `keyPath` ("balls.4.y" → "balls.4", "balls") that
/// the file itself writes, or empty when not even its first key is written.
QString longestWrittenPrefix(const QJsonObject& root, const QString& keyPath)
{
    QJsonValue at = root;
    QString written;
    for (const QString& part : keyPath.split(QLatin1Char('.'))) {
        bool isIndex = false;
        const int index = part.toInt(&isIndex);
        if (at.isObject() && at.toObject().contains(part))
            at = at.toObject().value(part);
        else if (at.isArray() && isIndex && index >= 0 && index < at.toArray().size())
            at = at.toArray().at(index);
        else
            break;
        written += (written.isEmpty() ? QString() : QStringLiteral(".")) + part;
    }
    return written;
}

/// A problem found at a key path of the lesson: it belongs to the override
/// that set the path, or that made the part of it the file does not write
/// (`--set balls.4.x=1` on a file with four balls makes ball 4, so its
/// missing y is the override's); else to the file, where it is located in
/// the text.
sim::Error problemAtKey(const QString& keyPath, const QString& message, const QString& source, const QByteArray& json,
                        const QList<Override>& overrides)
{
    if (const Override* o = overrideFor(keyPath, overrides))
        return problem(overrideSource(*o), message, keyPath);
    if (!overrides.isEmpty()) {
        const QJsonObject root = QJsonDocument::fromJson(json).object();
        const QString written = longestWrittenPrefix(root, keyPath);
        if (written != keyPath) {
            const QString made = written.isEmpty() ? keyPath.section(QLatin1Char('.'), 0, 0)
                                                   : keyPath.section(QLatin1Char('.'), 0, written.count(QLatin1Char('.')) + 1);
            for (qsizetype i = overrides.size() - 1; i >= 0; --i)
                if (overrides[i].keyPath == made || overrides[i].keyPath.startsWith(made + QLatin1Char('.')))
                    return problem(overrideSource(overrides[i]), message, keyPath);
        }
    }
    if (const auto p = positionOfKeyPath(json, keyPath, kMaxDepth))
        return problemAt(source, *p, keyPath, message);
    return problem(source, message, keyPath);
}

/// A number as a reader writes it, to 6 significant digits: "600", "0.5", "18.1".
QString plain(double v)
{
    return QString::fromStdString(sim::roundedText(v, 6));
}

/// Whether the balls fit their box, before any work is done: a ball whose
/// centre lies beyond a wall that is on, a ball wider than the walls it sits
/// between, and more colliding balls than the box can hold (their discs'
/// area against the densest packing of equal discs, π/√3 / 2 ≈ 90.7%). The
/// simulation would otherwise move such a ball without a word, or spend
/// minutes and gigabytes on a pile that cannot exist.
std::optional<KeyProblem> sceneProblem(const sim::Scene& scene)
{
    const sim::WorldSettings& s = scene.settings;
    const double w = s.box.width, h = s.box.height;
    const QString box = QStringLiteral("%1 × %2 px").arg(plain(w), plain(h));
    for (std::size_t i = 0; i < scene.balls.size(); ++i) {
        const sim::Ball& b = scene.balls[i];
        const QString at = QStringLiteral("balls.%1").arg(i);
        const double x = b.position.x(), y = b.position.y();
        auto outside = [&](const char* key, double v, const char* wall, double lo, double hi) {
            return KeyProblem{at + QLatin1Char('.') + QLatin1String(key),
                              QStringLiteral("%1 = %2 px puts the ball's centre outside the %3 box (%1 from %4 to %5 "
                                             "px) while the %6 wall is on; put the ball inside, or switch that wall off")
                                  .arg(QLatin1String(key), plain(v), box, plain(lo), plain(hi), QLatin1String(wall))};
        };
        if (s.walls.left && x < 0.0)
            return outside("x", x, "left", 0.0, w);
        if (s.walls.right && x > w)
            return outside("x", x, "right", 0.0, w);
        if (s.walls.top && y < 0.0)
            return outside("y", y, "top", 0.0, h);
        if (s.walls.bottom && y > h)
            return outside("y", y, "bottom", 0.0, h);
        const bool across = s.walls.left && s.walls.right && 2.0 * b.radius > w;
        const bool upDown = s.walls.top && s.walls.bottom && 2.0 * b.radius > h;
        if (across || upDown)
            return KeyProblem{at + QStringLiteral(".r"),
                              QStringLiteral("a ball of radius %1 px does not fit between the walls of the %2 box (a "
                                             "radius of %3 px at most)")
                                  .arg(plain(b.radius), box, plain(0.5 * std::min(across ? w : h, upDown ? h : w)))};
    }
    const sim::SpawnSettings& sp = scene.spawn;
    const int spawned = std::max(sp.count, sp.perStep > 0.0 ? sp.maxCount : 0);
    if (spawned > 0 && ((s.walls.left && s.walls.right && 2.0 * sp.minRadius > w) ||
                        (s.walls.top && s.walls.bottom && 2.0 * sp.minRadius > h)))
        return KeyProblem{QStringLiteral("spawn.radius"),
                          QStringLiteral("balls of radius %1 px or more do not fit between the walls of the %2 box")
                              .arg(plain(sp.minRadius), box)};
    if (s.collisions.response == sim::Response::None || w <= 0.0 || h <= 0.0)
        return std::nullopt;
    constexpr double kDensestFill = 0.9069; // π / (2√3): equal discs in a hexagonal packing
    double listedArea = 0.0;
    for (const sim::Ball& b : scene.balls)
        listedArea += std::numbers::pi * b.radius * b.radius;
    // The mean disc of a radius uniform in [a, b]: π (a² + ab + b²) / 3.
    const double a = sp.minRadius, bMax = sp.maxRadius;
    const double meanDisc = std::numbers::pi * (a * a + a * bMax + bMax * bMax) / 3.0;
    const double fill = (listedArea + spawned * meanDisc) / (w * h);
    if (fill <= kDensestFill)
        return std::nullopt;
    const QString cover = fill >= 1.0 ? QStringLiteral("%1 times the area of").arg(fill, 0, 'f', 1)
                                      : QStringLiteral("%1% of").arg(100.0 * fill, 0, 'f', 0);
    if (spawned > 0) {
        const double room = std::max(0.0, kDensestFill * w * h - listedArea);
        return KeyProblem{sp.count >= spawned ? QStringLiteral("spawn.count") : QStringLiteral("spawn.max_count"),
                          QStringLiteral("%1 colliding balls of radius %2 to %3 px would cover %4 the %5 box; "
                                         "colliding balls fill at most 91% of a box, so %6 of them fit at most (or make "
                                         "the box larger or the balls smaller)")
                              .arg(spawned)
                              .arg(plain(a), plain(bMax), cover, box)
                              .arg(static_cast<long long>(room / meanDisc))};
    }
    return KeyProblem{QStringLiteral("balls"),
                      QStringLiteral("the colliding balls would cover %1 the %2 box; colliding balls fill at most "
                                     "91% of a box")
                          .arg(cover, box)};
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
    // A file, a folder that loadFile names as one, or a link that leads
    // nowhere (a loop, a missing target): loadFile says what the system says,
    // as `validate` does.
    const QFileInfo info(pathOrId);
    if (info.exists() || info.isSymLink())
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

    if (const auto p = sceneProblem(parsed.lesson.scene))
        return failure({problemAtKey(p->keyPath, p->problem, source, json, overrides)});

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
