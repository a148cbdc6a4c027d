#pragma once
// Text from a lesson file or the command line quoted in a one-line message:
// a stranger's 100,000-character key or value is shown by its start and its
// length, never whole.

#include <QString>
#include <QStringList>

namespace forcelab::lessons {

inline constexpr qsizetype kEchoedCharacters = 60; ///< characters of a long value a message shows

/// `text` whole when it is short; else its first kEchoedCharacters characters
/// (never half of one) and "… (N characters)".
inline QString cutForMessage(const QString& text)
{
    if (text.size() <= kEchoedCharacters + 20)
        return text;
    qsizetype cut = kEchoedCharacters;
    if (text.at(cut).isLowSurrogate())
        --cut;
    return text.left(cut) + QStringLiteral("… (%1 characters)").arg(text.size());
}

/// A key path ("world.kkkk…") with each long key cut as cutForMessage does.
inline QString cutKeyPath(const QString& path)
{
    if (path.size() <= kEchoedCharacters + 20)
        return path;
    QStringList keys = path.split(QLatin1Char('.'));
    for (QString& key : keys)
        key = cutForMessage(key);
    return keys.join(QLatin1Char('.'));
}

} // namespace forcelab::lessons
