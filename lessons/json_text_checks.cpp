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
    bool expectKey = false;
    int index = 0;           // arrays: index of the current element
    QByteArray key;          // objects: the current key (decoded)
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

QString pathOf(const std::vector<Frame>& frames, int depth, const QByteArray& lastKey)
{
    QStringList parts;
    for (int d = 0; d < depth; ++d) {
        const Frame& f = frames[static_cast<std::size_t>(d)];
        if (d == depth - 1 && f.object) {
            parts << QString::fromUtf8(lastKey);
            break;
        }
        parts << (f.object ? QString::fromUtf8(f.key) : QString::number(f.index));
    }
    return parts.join('.');
}

} // namespace

QList<StructureProblem> scanStructure(const QByteArray& text, int maxDepth, int maxProblems)
{
    QList<StructureProblem> problems;
    std::vector<Frame> frames(static_cast<std::size_t>(maxDepth) + 1);
    int depth = 0;
    int line = 1;
    const qsizetype n = text.size();
    for (qsizetype i = 0; i < n; ++i) {
        const char c = text[i];
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
            const QByteArray key = decodeString(text.mid(start, i - start + 1));
            const auto it = f.lines.constFind(key);
            if (it != f.lines.cend()) {
                if (problems.size() < maxProblems)
                    problems.append({positionOf(text, start), pathOf(frames, depth, key),
                                     QStringLiteral("duplicate key (first given on line %1); give each key once")
                                         .arg(it.value())});
            } else {
                f.lines.insert(key, line);
            }
            f.key = key;
            break;
        }
        case '{':
        case '[': {
            if (depth == maxDepth) {
                problems.append({positionOf(text, i), pathOf(frames, depth, frames[static_cast<std::size_t>(depth - 1)].key),
                                 QStringLiteral("nested deeper than %1 levels").arg(maxDepth)});
                return problems;
            }
            Frame& f = frames[static_cast<std::size_t>(depth++)];
            f.object = c == '{';
            f.expectKey = f.object;
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
                if (f.object)
                    f.expectKey = true;
                else
                    ++f.index;
            }
            break;
        default:
            break;
        }
    }
    return problems;
}

} // namespace forcelab::lessons
