#include "lesson_overrides.h"

#include "lesson_limits.h"
#include "message_text.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QRegularExpression>

#include <cmath>
#include <charconv>

namespace forcelab::lessons {

// An override is echoed with every problem it causes; a long key or value (a
// formula of thousands of characters) only by its start and its length. The
// problem's own message shows the part around the error where it has one.
QString overrideSource(const Override& o)
{
    return QStringLiteral("--set ") + cutKeyPath(o.keyPath) + QLatin1Char('=') + cutForMessage(o.value);
}

std::optional<QJsonValue> overrideValue(const Override& o, QString* problem)
{
    const QByteArray text = o.value.toUtf8();
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson("[" + text + "]", &error);
    if (error.error == QJsonParseError::NoError && doc.array().size() == 1)
        return doc.array().at(0);
    // Not JSON. A word for NaN or infinity, or a number too large for a
    // double, must not quietly become a string that then fails as "wrong type".
    static const QRegularExpression words(QStringLiteral("^\\s*[+-]?(nan|inf|infinity)\\s*$"),
                                          QRegularExpression::CaseInsensitiveOption);
    static const QRegularExpression numeric(QStringLiteral("^\\s*[+-]?([0-9]+\\.?[0-9]*|\\.[0-9]+)([eE][+-]?[0-9]+)?\\s*$"));
    const QString trimmed = o.value.trimmed();
    if (words.match(trimmed).hasMatch()) {
        *problem = QStringLiteral("%1 is not a finite number; NaN and infinity are not allowed").arg(trimmed);
        return std::nullopt;
    }
    if (numeric.match(trimmed).hasMatch()) {
        // from_chars ignores the C locale's decimal comma and takes no '+'.
        const QByteArray digits = trimmed.toLatin1();
        const char* first = digits.constData() + (digits.startsWith('+') ? 1 : 0);
        double d = 0.0;
        const auto [end, ec] = std::from_chars(first, digits.constData() + digits.size(), d);
        if (ec != std::errc() || end != digits.constData() + digits.size() || !std::isfinite(d)) {
            *problem = QStringLiteral("%1 is too large or too small for a double; infinity is not allowed").arg(trimmed);
            return std::nullopt;
        }
        return QJsonValue(d); // forms JSON does not allow but people type: "+1", "1.", ".5", "007"
    }
    return QJsonValue(o.value);
}

namespace {

bool isIndex(const QString& segment)
{
    static const QRegularExpression digits(QStringLiteral("^[0-9]{1,9}$"));
    return digits.match(segment).hasMatch();
}

QString typeWord(const QJsonValue& v)
{
    switch (v.type()) {
    case QJsonValue::Bool:
        return QStringLiteral("true or false");
    case QJsonValue::Double:
        return QStringLiteral("a number");
    case QJsonValue::String:
        return QStringLiteral("a string");
    case QJsonValue::Null:
        return QStringLiteral("null");
    default:
        return QStringLiteral("a value");
    }
}

// Returns `node` with the value set at segments[i..]; `path` is the key path of
// `node` for messages.
std::optional<KeyProblem> setIn(QJsonValue& node, const QStringList& segments, qsizetype i, const QString& path,
                             const QJsonValue& value)
{
    if (i == segments.size()) {
        node = value;
        return std::nullopt;
    }
    const QString& seg = segments[i];
    const QString here = path.isEmpty() ? seg : path + QLatin1Char('.') + seg;
    if (node.isArray()) {
        if (!isIndex(seg))
            return KeyProblem{here, path + QStringLiteral(" is an array; expected an index such as ") + path +
                                        QStringLiteral(".0")};
        QJsonArray a = node.toArray();
        const qsizetype k = seg.toLongLong();
        if (k > a.size())
            return KeyProblem{here, QStringLiteral("index %1 is past the end (the array has %2 entries)").arg(k).arg(a.size())};
        QJsonValue child = k < a.size() ? a.at(k) : QJsonValue(QJsonObject{});
        if (auto e = setIn(child, segments, i + 1, here, value))
            return e;
        if (k == a.size())
            a.append(child);
        else
            a[k] = child;
        node = a;
        return std::nullopt;
    }
    if (node.isUndefined() || node.isNull())
        node = QJsonObject{}; // create the missing object: enabling a model by setting one of its keys
    if (!node.isObject())
        return KeyProblem{path, QStringLiteral("is %1, so it has no key \"%2\"").arg(typeWord(node), seg)};
    QJsonObject o = node.toObject();
    QJsonValue child = o.value(seg);
    if (auto e = setIn(child, segments, i + 1, here, value))
        return e;
    o.insert(seg, child);
    node = o;
    return std::nullopt;
}

} // namespace

std::optional<KeyProblem> applyOverride(QJsonObject& root, const QString& keyPath, const QJsonValue& value)
{
    const QStringList segments = keyPath.split(QLatin1Char('.'));
    if (segments.size() > kMaxDepth)
        return KeyProblem{keyPath, QStringLiteral("nested deeper than %1 levels").arg(kMaxDepth)};
    QJsonValue node(root);
    if (auto e = setIn(node, segments, 0, QString(), value))
        return e;
    root = node.toObject();
    return std::nullopt;
}

} // namespace forcelab::lessons
