#include "json_text_checks.h"

#include <QHash>
#include <QJsonArray>
#include <QJsonDocument>

#include <algorithm>
#include <vector>

namespace forcelab::lessons {

TextPosition positionOf(const QByteArray& text, qsizetype offset)
{
    offset = std::clamp<qsizetype>(offset, 0, text.size());
    TextPosition p;
    for (qsizetype i = 0; i < offset; ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c == '\n') {
            ++p.line;
            p.column = 1;
        } else if ((c & 0xC0) != 0x80) { // count lead bytes only: one per character
            ++p.column;
        }
    }
    return p;
}

std::optional<qsizetype> firstInvalidUtf8(const QByteArray& text)
{
    const auto* s = reinterpret_cast<const unsigned char*>(text.constData());
    const qsizetype n = text.size();
    qsizetype i = 0;
    while (i < n) {
        const unsigned char c = s[i];
        if (c < 0x80) {
            ++i;
            continue;
        }
        int len = 0;
        char32_t cp = 0;
        char32_t min = 0;
        if ((c & 0xE0) == 0xC0) {
            len = 2, cp = c & 0x1F, min = 0x80;
        } else if ((c & 0xF0) == 0xE0) {
            len = 3, cp = c & 0x0F, min = 0x800;
        } else if ((c & 0xF8) == 0xF0) {
            len = 4, cp = c & 0x07, min = 0x10000;
        } else {
            return i;
        }
        if (i + len > n)
            return i;
        for (int k = 1; k < len; ++k) {
            const unsigned char t = s[i + k];
            if ((t & 0xC0) != 0x80)
                return i;
            cp = (cp << 6) | (t & 0x3F);
        }
        if (cp < min || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF))
            return i;
        i += len;
    }
    return std::nullopt;
}

namespace {

// One open object or array while scanning.
struct Frame {
    bool object = false;
    bool expectKey = false;     // objects: the next string is a key
    bool expectElement = false; // arrays: the next value starts an element
    int index = 0;              // arrays: index of the current element
    QByteArray key;             // objects: the current key (decoded)
    QHash<QByteArray, int> lines; // objects: key -> line of its first occurrence
};

QByteArray decodeString(const QByteArray& raw)
{
    if (!raw.contains('\\'))
        return raw.mid(1, raw.size() - 2);
    // Rare: let the JSON parser undo the escapes so "\u0061" equals "a".
    const QJsonDocument doc = QJsonDocument::fromJson("[" + raw + "]");
    return doc.array().at(0).toString().toUtf8();
}

bool isSpace(char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

/// Walks text that QJsonDocument has already accepted, keeping the stack of
/// open objects and arrays. `visit` is called where each member's key and
/// each array element starts, with the byte offset, the line, and the key
/// path of that member or element; it returns false to stop the walk. The
/// walk stops before nesting deeper than `maxDepth`, and returns the offset
/// where that happened (or nullopt).
template<typename Visit>
std::optional<qsizetype> walk(const QByteArray& text, int maxDepth, Visit&& visit)
{
    std::vector<Frame> frames(static_cast<std::size_t>(maxDepth) + 1);
    int depth = 0;
    int line = 1;
    const auto pathTo = [&](int upTo) {
        QStringList parts;
        for (int d = 0; d < upTo; ++d) {
            const Frame& f = frames[static_cast<std::size_t>(d)];
            parts << (f.object ? QString::fromUtf8(f.key) : QString::number(f.index));
        }
        return parts.join('.');
    };
    const qsizetype n = text.size();
    for (qsizetype i = 0; i < n; ++i) {
        const char c = text[i];
        if (depth > 0 && !isSpace(c) && c != ']') {
            Frame& top = frames[static_cast<std::size_t>(depth - 1)];
            if (!top.object && top.expectElement) {
                top.expectElement = false;
                if (!visit(i, line, pathTo(depth), frames[static_cast<std::size_t>(depth - 1)]))
                    return std::nullopt;
            }
        }
        switch (c) {
        case '\n':
            ++line;
            break;
        case '"': {
            const qsizetype start = i;
            for (++i; i < n && text[i] != '"'; ++i)
                if (text[i] == '\\')
                    ++i;
            if (depth == 0)
                break;
            Frame& f = frames[static_cast<std::size_t>(depth - 1)];
            if (!f.object || !f.expectKey)
                break;
            f.expectKey = false;
            f.key = decodeString(text.mid(start, i - start + 1));
            if (!visit(start, line, pathTo(depth), f))
                return std::nullopt;
            break;
        }
        case '{':
        case '[': {
            if (depth == maxDepth)
                return i;
            Frame& f = frames[static_cast<std::size_t>(depth++)];
            f.object = c == '{';
            f.expectKey = f.object;
            f.expectElement = !f.object;
            f.index = 0;
            f.key.clear();
            f.lines.clear();
            break;
        }
        case '}':
        case ']':
            if (depth > 0)
                --depth;
            break;
        case ',':
            if (depth > 0) {
                Frame& f = frames[static_cast<std::size_t>(depth - 1)];
                if (f.object) {
                    f.expectKey = true;
                } else {
                    ++f.index;
                    f.expectElement = true;
                }
            }
            break;
        default:
            break;
        }
    }
    return std::nullopt;
}

} // namespace

QList<StructureProblem> scanStructure(const QByteArray& text, int maxDepth, int maxProblems)
{
    QList<StructureProblem> problems;
    QString deepest; // the path of the last member or element seen, for the depth problem
    const auto tooDeep = walk(text, maxDepth, [&](qsizetype at, int line, const QString& path, Frame& f) {
        deepest = path;
        if (!f.object)
            return true;
        const auto it = f.lines.constFind(f.key);
        if (it == f.lines.cend()) {
            f.lines.insert(f.key, line);
        } else if (problems.size() < maxProblems) {
            problems.append({positionOf(text, at), path,
                             QStringLiteral("duplicate key (first given on line %1); give each key once").arg(it.value())});
        }
        return true;
    });
    if (tooDeep)
        problems.append({positionOf(text, *tooDeep), deepest, QStringLiteral("nested deeper than %1 levels").arg(maxDepth)});
    return problems;
}

std::optional<TextPosition> positionOfKeyPath(const QByteArray& text, const QString& keyPath, int maxDepth)
{
    if (keyPath.isEmpty())
        return std::nullopt;
    std::optional<qsizetype> best;
    qsizetype bestLength = 0;
    walk(text, maxDepth, [&](qsizetype at, int, const QString& path, Frame&) {
        const bool prefix = keyPath == path || (keyPath.startsWith(path) && keyPath[path.size()] == QLatin1Char('.'));
        if (prefix && path.size() > bestLength) {
            best = at;
            bestLength = path.size();
        }
        return path != keyPath; // the whole path found: done
    });
    if (!best)
        return std::nullopt;
    return positionOf(text, *best);
}

} // namespace forcelab::lessons
