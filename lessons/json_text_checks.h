#pragma once
// Checks on the raw text of a lesson file that QJsonDocument does not make:
// UTF-8 validity with a position, nesting depth, and duplicate keys (the
// parser silently keeps the last of two equal keys). Also turns a byte offset
// into the line and column an editor shows.

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <optional>

namespace forcelab::lessons {

struct TextPosition {
    int line = 1;   ///< 1-based
    int column = 1; ///< 1-based, in characters (UTF-8 code points), not bytes
};

/// Line and column of byte `offset` of UTF-8 text (clamped to the text).
TextPosition positionOf(const QByteArray& text, qsizetype offset);

/// Byte offset of the first byte that is not part of well-formed UTF-8
/// (overlong forms, surrogates and code points above U+10FFFF are errors).
std::optional<qsizetype> firstInvalidUtf8(const QByteArray& text);

/// A problem found by scanStructure: where, the key path, and what is wrong.
struct StructureProblem {
    TextPosition position;
    QString keyPath;
    QString problem;
};

/// Scans text that QJsonDocument has already accepted as valid JSON for
/// nesting deeper than `maxDepth` (stops there) and for duplicate keys in any
/// object (all of them, up to `maxProblems`).
QList<StructureProblem> scanStructure(const QByteArray& text, int maxDepth, int maxProblems);

/// Where `keyPath` ("models.drag.k", "balls.3.r") is written in text that
/// QJsonDocument has already accepted: at its key, or at the start of the
/// array element; for a path that is not written (a missing key), where its
/// longest written parent is. Nullopt when no part of the path is written.
std::optional<TextPosition> positionOfKeyPath(const QByteArray& text, const QString& keyPath, int maxDepth);

} // namespace forcelab::lessons
