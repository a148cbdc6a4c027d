#include "nearest_key.h"
#include "message_text.h"

#include <algorithm>
#include <vector>

namespace forcelab::lessons {

int editDistance(const QString& a0, const QString& b0)
{
    // Optimal string alignment: Levenshtein plus swapping two neighbouring
    // letters as one edit ("titel" is one edit from "title").
    const QString a = a0.toCaseFolded();
    const QString b = b0.toCaseFolded();
    const std::size_t n = static_cast<std::size_t>(a.size());
    const std::size_t m = static_cast<std::size_t>(b.size());
    std::vector<int> d((n + 1) * (m + 1));
    auto at = [&](std::size_t i, std::size_t j) -> int& { return d[i * (m + 1) + j]; };
    for (std::size_t i = 0; i <= n; ++i)
        at(i, 0) = static_cast<int>(i);
    for (std::size_t j = 0; j <= m; ++j)
        at(0, j) = static_cast<int>(j);
    for (std::size_t i = 1; i <= n; ++i) {
        for (std::size_t j = 1; j <= m; ++j) {
            const int cost = a[i - 1] == b[j - 1] ? 0 : 1;
            at(i, j) = std::min({at(i - 1, j) + 1, at(i, j - 1) + 1, at(i - 1, j - 1) + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                at(i, j) = std::min(at(i, j), at(i - 2, j - 2) + 1);
        }
    }
    return at(n, m);
}

std::optional<QString> nearestKey(const QString& key, const QStringList& known)
{
    if (key.size() > 200) // a key that long is no typo; also bounds the work
        return std::nullopt;
    // One- and two-letter keys ("x", "vy") are too short to guess from,
    // except for a difference in case.
    const int allowed = key.size() < 3 ? 0 : std::clamp(static_cast<int>(key.size()) / 3, 1, 3);
    std::optional<QString> best;
    int bestDistance = allowed + 1;
    for (const QString& k : known) {
        const int d = editDistance(key, k);
        if (d < bestDistance) {
            bestDistance = d;
            best = k;
        }
    }
    return best;
}

QString unknownKeyMessage(const QString& key, const QStringList& known)
{
    const QString shown = cutForMessage(key);
    if (const auto near = nearestKey(key, known))
        return QStringLiteral("unknown key \"%1\"; did you mean \"%2\"?").arg(shown, *near);
    return QStringLiteral("unknown key \"%1\"; known keys here: %2").arg(shown, known.join(QStringLiteral(", ")));
}

} // namespace forcelab::lessons
