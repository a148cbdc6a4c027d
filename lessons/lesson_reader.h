#pragma once
// The lesson reader's toolkit, shared by the units of parseLesson
// (lesson_parser.h): key paths, values quoted in messages, and Reader, which
// reads typed values out of JSON objects and collects every problem with
// its key path. Numbers and ranges are written by sim's formatter
// (sim/world/number_text.h), as sim's own messages write them.

#include "lesson_limits.h"
#include "lesson_parser.h"
#include "sim/world/parameters.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QJsonValue>
#include <QString>
#include <QStringList>

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace forcelab::lessons::parsing {

/// "models.wind" + "mode" is "models.wind.mode"; an empty path gives the key.
QString join(const QString& path, const QString& key);
/// "balls" + 3 is "balls.3".
QString join(const QString& path, qsizetype index);

/// A number for messages: sim::numberText (whole numbers up to 1e9 in full,
/// others in the shortest form that reads back to the same double).
QString numberText(double v);
/// A closed whole-number interval for messages: "[0, 99]" (sim::rangeText).
QString rangeText(int lo, int hi);

/// `s` in double quotes, cut as cutForMessage does.
QString quoted(const QString& s);
/// "the string "abc"", "the number 3", "an array", ... for "got ..." messages.
QString describe(const QJsonValue& v);

/// UTF-8 text from sim as a QString.
QString qs(std::string_view s);
/// "a, b or c" (sim::joinNames).
QString names(std::span<const std::string_view> list);

// Reads typed values out of JSON objects, collecting every problem with its
// key path. A setter assigns its output only when the value is present and
// valid, so absent keys keep the struct defaults.
class Reader {
public:
    explicit Reader(ParseResult& result) : m_result(result) {}

    /// Records a problem at `path` (counted, not listed, past kMaxErrors).
    void fail(const QString& path, const QString& problem);
    /// Reports each key of `o` that is not in `known` (with the nearest known key).
    void checkKeys(const QJsonObject& o, const QString& path, const QStringList& known);
    /// Whether `o` has `key`; when not, reports it missing and says to give `what`.
    bool require(const QJsonObject& o, const QString& path, const QString& key, const QString& what);

    /// The object under `key`, or nullopt when absent or not an object (reported).
    std::optional<QJsonObject> object(const QJsonObject& o, const QString& path, const QString& key);
    /// The array under `key`, or nullopt when absent or not an array (reported as not `what`).
    std::optional<QJsonArray> array(const QJsonObject& o, const QString& path, const QString& key,
                                    const QString& what);

    // Each setter below returns whether `out` was written: the key is present
    // and its value valid.

    /// A finite number in `r` (NaN and infinity, also as words, refused).
    bool numberValue(const QJsonValue& v, const QString& path, const Range& r, double& out);
    bool number(const QJsonObject& o, const QString& path, const QString& key, const Range& r, double& out);
    /// A whole number in [lo, hi].
    bool integer(const QJsonObject& o, const QString& path, const QString& key, int lo, int hi, int& out);
    /// A seed: a whole number in [0, 2^53], or a string of decimal digits for larger ones.
    bool seed(const QJsonObject& o, const QString& path, const QString& key, std::uint64_t& out);
    bool boolean(const QJsonObject& o, const QString& path, const QString& key, bool& out);
    bool string(const QJsonObject& o, const QString& path, const QString& key, QString& out);
    /// An array of strings of at most kMaxListEntries; `out` is written only when every entry is a string.
    bool stringList(const QJsonObject& o, const QString& path, const QString& key, QStringList& out);
    /// A colour written "#rrggbb".
    bool colourValue(const QJsonValue& v, const QString& path, sim::Rgb& out);
    /// A Choice row: its value is one of the row's names (or an alias).
    bool choice(const QJsonObject& o, const QString& path, const QString& key, const sim::Parameter& row,
                sim::WorldSettings& s);
    /// A [min, max] pair, or one number for both.
    bool interval(const QJsonObject& o, const QString& path, const QString& key, const Range& r, double& lo,
                  double& hi);

    /// One row of the parameter table, read from the section object `o` at
    /// `path`; written into `s` only when present and valid.
    void row(const QJsonObject& o, const QString& path, const sim::Parameter& p, sim::WorldSettings& s);
    /// Every row of a section: the keys the object may hold, what listing the
    /// section means (whenListed), then each row present.
    void section(const QJsonObject& o, const QString& path, sim::WorldSettings& s,
                 const QStringList& extraKeys = {});

private:
    ParseResult& m_result;
};

/// A list of objects with at most `most` entries (`unit` names them in the
/// message): each object is read by parseOne(object, path), which returns
/// the entry; an entry that is not an object is refused with `expected`, and
/// the list is read on. Too long a list is refused whole and `out` kept.
template <class T, class ParseOne>
void objectList(Reader& r, const QJsonArray& a, const QString& base, int most, const char* unit,
                const QString& expected, std::vector<T>& out, ParseOne parseOne)
{
    if (a.size() > most) {
        r.fail(base, QStringLiteral("%1 %2 is more than the limit of %3").arg(a.size()).arg(QLatin1String(unit)).arg(most));
        return;
    }
    out.clear();
    for (qsizetype i = 0; i < a.size(); ++i) {
        const QString p = join(base, i);
        if (!a.at(i).isObject()) {
            r.fail(p, QStringLiteral("expected %1, got %2").arg(expected, describe(a.at(i))));
            continue;
        }
        out.push_back(parseOne(a.at(i).toObject(), p));
    }
}

} // namespace forcelab::lessons::parsing
