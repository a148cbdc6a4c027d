#pragma once
// The known key closest to a misspelt one, for "did you mean" hints.

#include <QString>
#include <QStringList>

#include <optional>

namespace forcelab::lessons {

/// Edit distance (insertions, deletions, substitutions, swaps of neighbours), case-insensitive.
int editDistance(const QString& a, const QString& b);

/// The nearest of `known` to `key` when it is close enough to be a likely
/// typo (distance at most 1 for short keys, up to 3 for long ones; keys of
/// one or two letters only match up to case).
std::optional<QString> nearestKey(const QString& key, const QStringList& known);

/// "unknown key "gravty"; did you mean "gravity"?" or, without a close
/// match, "unknown key "foo"; known keys here: a, b, c".
QString unknownKeyMessage(const QString& key, const QStringList& known);

} // namespace forcelab::lessons
