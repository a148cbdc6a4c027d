// Reader (lesson_reader.h): typed values read out of a lesson's JSON, with
// every problem collected under its key path, and the helpers its messages
// use to show keys, values, numbers and ranges.

#include "lesson_reader.h"

#include "colour_names.h"
#include "message_text.h"
#include "nearest_key.h"
#include "sim/world/names.h"
#include "sim/world/number_text.h"

#include <QRegularExpression>

#include <cmath>

namespace forcelab::lessons {

QString Range::text() const
{
    return QString::fromStdString(sim::rangeText(lo, hi, unit, loOpen, hiOpen));
}

namespace parsing {

QString join(const QString& path, const QString& key)
{
    return path.isEmpty() ? key : path + QLatin1Char('.') + key;
}

QString join(const QString& path, qsizetype index)
{
    return path + QLatin1Char('.') + QString::number(index);
}

QString numberText(double v)
{
    return QString::fromStdString(sim::numberText(v));
}

QString rangeText(int lo, int hi)
{
    return QString::fromStdString(sim::rangeText(lo, hi));
}

QString quoted(const QString& s)
{
    const QString shown = cutForMessage(s);
    return QLatin1Char('"') + shown + QLatin1Char('"');
}

/// "the string "abc"", "the number 3", "an array", ... for "got ..." messages.
QString describe(const QJsonValue& v)
{
    switch (v.type()) {
    case QJsonValue::Null:
        return QStringLiteral("null");
    case QJsonValue::Bool:
        return v.toBool() ? QStringLiteral("true") : QStringLiteral("false");
    case QJsonValue::Double:
        return QStringLiteral("the number ") + numberText(v.toDouble());
    case QJsonValue::String:
        return QStringLiteral("the string ") + quoted(v.toString());
    case QJsonValue::Array:
        return QStringLiteral("an array");
    case QJsonValue::Object:
        return QStringLiteral("an object");
    case QJsonValue::Undefined:
        break;
    }
    return QStringLiteral("nothing");
}

QString qs(std::string_view s)
{
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

QString names(std::span<const std::string_view> list)
{
    return qs(sim::joinNames(list));
}

namespace {

/// Words that mean NaN or infinity (they reach us as strings from `--set`).
bool namesNonFinite(const QString& s)
{
    static const QRegularExpression re(QStringLiteral("^\\s*[+-]?(nan|inf|infinity)\\s*$"),
                                       QRegularExpression::CaseInsensitiveOption);
    return re.match(s).hasMatch();
}

std::optional<sim::Rgb> parseColour(const QString& s)
{
    static const QRegularExpression re(QStringLiteral("^#[0-9a-fA-F]{6}$"));
    if (!re.match(s).hasMatch())
        return std::nullopt;
    return static_cast<sim::Rgb>(s.mid(1).toUInt(nullptr, 16));
}

} // namespace

void Reader::fail(const QString& path, const QString& problem)
{
    if (m_result.problems.size() < kMaxErrors)
        m_result.problems.append({path, problem});
    else
        ++m_result.unlisted;
}

void Reader::checkKeys(const QJsonObject& o, const QString& path, const QStringList& known)
{
    for (auto it = o.begin(); it != o.end(); ++it)
        if (!known.contains(it.key()))
            fail(join(path, it.key()), unknownKeyMessage(it.key(), known));
}

bool Reader::require(const QJsonObject& o, const QString& path, const QString& key, const QString& what)
{
    if (o.contains(key))
        return true;
    fail(join(path, key), QStringLiteral("missing; give %1").arg(what));
    return false;
}

std::optional<QJsonObject> Reader::object(const QJsonObject& o, const QString& path, const QString& key)
{
    if (!o.contains(key))
        return std::nullopt;
    const QJsonValue v = o.value(key);
    if (!v.isObject()) {
        fail(join(path, key), QStringLiteral("expected an object { … }, got ") + describe(v));
        return std::nullopt;
    }
    return v.toObject();
}

std::optional<QJsonArray> Reader::array(const QJsonObject& o, const QString& path, const QString& key,
                                        const QString& what)
{
    if (!o.contains(key))
        return std::nullopt;
    const QJsonValue v = o.value(key);
    if (!v.isArray()) {
        fail(join(path, key), QStringLiteral("expected %1, got %2").arg(what, describe(v)));
        return std::nullopt;
    }
    return v.toArray();
}

bool Reader::numberValue(const QJsonValue& v, const QString& path, const Range& r, double& out)
{
    if (!v.isDouble()) {
        if (v.isString() && namesNonFinite(v.toString()))
            fail(path, QStringLiteral("%1 is not a finite number; NaN and infinity are not allowed")
                           .arg(quoted(v.toString())));
        else
            fail(path, QStringLiteral("expected a number in %1, got %2").arg(r.text(), describe(v)));
        return false;
    }
    const double d = v.toDouble();
    if (!std::isfinite(d)) {
        fail(path, QStringLiteral("%1 is not a finite number; NaN and infinity are not allowed").arg(numberText(d)));
        return false;
    }
    if (!r.contains(d)) {
        fail(path, QStringLiteral("%1 is outside %2").arg(numberText(d), r.text()));
        return false;
    }
    out = d;
    return true;
}

bool Reader::number(const QJsonObject& o, const QString& path, const QString& key, const Range& r, double& out)
{
    if (!o.contains(key))
        return false;
    return numberValue(o.value(key), join(path, key), r, out);
}

bool Reader::integer(const QJsonObject& o, const QString& path, const QString& key, int lo, int hi, int& out)
{
    if (!o.contains(key))
        return false;
    const QString p = join(path, key);
    const QJsonValue v = o.value(key);
    if (!v.isDouble()) {
        fail(p, QStringLiteral("expected a whole number in %1, got %2").arg(rangeText(lo, hi), describe(v)));
        return false;
    }
    const double d = v.toDouble();
    if (std::floor(d) != d) {
        fail(p, QStringLiteral("expected a whole number, got %1").arg(numberText(d)));
        return false;
    }
    if (d < lo || d > hi) {
        fail(p, QStringLiteral("%1 is outside %2").arg(numberText(d), rangeText(lo, hi)));
        return false;
    }
    out = static_cast<int>(d);
    return true;
}

bool Reader::seed(const QJsonObject& o, const QString& path, const QString& key, std::uint64_t& out)
{
    if (!o.contains(key))
        return false;
    const QString p = join(path, key);
    const QJsonValue v = o.value(key);
    const QString hint = QStringLiteral("a whole number in [0, 9007199254740992], or a string of digits up to "
                                        "18446744073709551615");
    if (v.isString()) {
        static const QRegularExpression digits(QStringLiteral("^[0-9]{1,20}$"));
        bool ok = false;
        const qulonglong s = v.toString().toULongLong(&ok);
        if (!digits.match(v.toString()).hasMatch() || !ok) {
            fail(p, QStringLiteral("expected %1, got %2").arg(hint, describe(v)));
            return false;
        }
        out = s;
        return true;
    }
    const double d = v.toDouble();
    if (!v.isDouble() || std::floor(d) != d || d < 0 || d > static_cast<double>(kMaxNumberSeed)) {
        fail(p, QStringLiteral("expected %1, got %2").arg(hint, describe(v)));
        return false;
    }
    out = static_cast<std::uint64_t>(d);
    return true;
}

bool Reader::boolean(const QJsonObject& o, const QString& path, const QString& key, bool& out)
{
    if (!o.contains(key))
        return false;
    const QJsonValue v = o.value(key);
    if (!v.isBool()) {
        fail(join(path, key), QStringLiteral("expected true or false, got ") + describe(v));
        return false;
    }
    out = v.toBool();
    return true;
}

bool Reader::string(const QJsonObject& o, const QString& path, const QString& key, QString& out)
{
    if (!o.contains(key))
        return false;
    const QJsonValue v = o.value(key);
    if (!v.isString()) {
        fail(join(path, key), QStringLiteral("expected a string, got ") + describe(v));
        return false;
    }
    out = v.toString();
    return true;
}

bool Reader::stringList(const QJsonObject& o, const QString& path, const QString& key, QStringList& out)
{
    const auto a = array(o, path, key, QStringLiteral("an array of strings"));
    if (!a)
        return false;
    const QString p = join(path, key);
    if (a->size() > kMaxListEntries) {
        fail(p, QStringLiteral("%1 entries is more than the limit of %2").arg(a->size()).arg(kMaxListEntries));
        return false;
    }
    QStringList list;
    bool ok = true;
    for (qsizetype i = 0; i < a->size(); ++i) {
        const QJsonValue v = a->at(i);
        if (!v.isString()) {
            fail(join(p, i), QStringLiteral("expected a string, got ") + describe(v));
            ok = false;
        } else {
            list << v.toString();
        }
    }
    if (ok)
        out = list;
    return ok;
}

bool Reader::colourValue(const QJsonValue& v, const QString& path, sim::Rgb& out)
{
    // A listed name ("red") or "#rrggbb"; a string that is neither is taken
    // for a misspelt name unless it starts with '#'.
    if (v.isString()) {
        const QString s = v.toString();
        if (const auto named = lessons::colourOfName(s)) {
            out = *named;
            return true;
        }
        if (const auto c = parseColour(s)) {
            out = *c;
            return true;
        }
        if (!s.trimmed().startsWith(QLatin1Char('#'))) {
            fail(path, QStringLiteral("%1 is not a colour name; one of %2, or \"#rrggbb\"")
                           .arg(quoted(s), lessons::colourWords().join(QStringLiteral(", "))));
            return false;
        }
    }
    fail(path, QStringLiteral("expected a colour name (e.g. \"red\") or \"#rrggbb\" (e.g. \"#e05050\"), got ") +
                   describe(v));
    return false;
}

bool Reader::choice(const QJsonObject& o, const QString& path, const QString& key, const sim::Parameter& row,
                    sim::WorldSettings& s)
{
    if (!o.contains(key))
        return false;
    const QString p = join(path, key);
    const QJsonValue v = o.value(key);
    const auto allowed = row.choices();
    if (!v.isString()) {
        fail(p, QStringLiteral("expected a string, one of %1, got %2").arg(names(allowed), describe(v)));
        return false;
    }
    const QByteArray utf8 = v.toString().toUtf8();
    const int index = sim::choiceIndex(row, std::string_view(utf8.constData(), static_cast<std::size_t>(utf8.size())));
    if (index < 0) {
        fail(p, QStringLiteral("%1 is not one of %2").arg(quoted(v.toString()), names(allowed)));
        return false;
    }
    row.set(s, index);
    return true;
}

bool Reader::interval(const QJsonObject& o, const QString& path, const QString& key, const Range& r, double& lo,
                      double& hi)
{
    if (!o.contains(key))
        return false;
    const QString p = join(path, key);
    const QJsonValue v = o.value(key);
    if (v.isDouble()) {
        double d = 0.0;
        if (!numberValue(v, p, r, d))
            return false;
        lo = hi = d;
        return true;
    }
    if (!v.isArray() || v.toArray().size() != 2) {
        fail(p, QStringLiteral("expected [min, max] or one number, in %1, got %2").arg(r.text(), describe(v)));
        return false;
    }
    const QJsonArray a = v.toArray();
    double a0 = 0.0, a1 = 0.0;
    const bool ok0 = numberValue(a.at(0), join(p, 0), r, a0);
    const bool ok1 = numberValue(a.at(1), join(p, 1), r, a1);
    if (!ok0 || !ok1)
        return false;
    if (a0 > a1) {
        fail(p, QStringLiteral("the minimum %1 is larger than the maximum %2").arg(numberText(a0), numberText(a1)));
        return false;
    }
    lo = a0;
    hi = a1;
    return true;
}

void Reader::row(const QJsonObject& o, const QString& path, const sim::Parameter& p, sim::WorldSettings& s)
{
    const QString key = qs(sim::rowName(p));
    switch (p.type) {
    case sim::ParameterType::Number: {
        double v = 0.0;
        // The table's units are string literals, so their data() ends in a NUL.
        const char* unit = p.unit.empty() ? "" : p.unit.data();
        if (number(o, path, key, Range{p.lo, p.hi, p.loOpen, p.hiOpen, unit}, v))
            p.set(s, v);
        return;
    }
    case sim::ParameterType::Integer: {
        int v = 0;
        if (integer(o, path, key, static_cast<int>(p.lo), static_cast<int>(p.hi), v))
            p.set(s, v);
        return;
    }
    case sim::ParameterType::Boolean: {
        bool v = false;
        if (boolean(o, path, key, v))
            p.set(s, v ? 1.0 : 0.0);
        return;
    }
    case sim::ParameterType::Choice:
        choice(o, path, key, p, s);
        return;
    }
}

void Reader::section(const QJsonObject& o, const QString& path, sim::WorldSettings& s,
                     const QStringList& extraKeys)
{
    const std::vector<const sim::Parameter*> rows = sim::sectionRows(path.toStdString());
    QStringList known;
    for (const sim::Parameter* p : rows)
        known << qs(sim::rowName(*p));
    checkKeys(o, path, known + extraKeys);
    for (const sim::Parameter* p : rows)
        if (!std::isnan(p->whenListed))
            p->set(s, p->whenListed);
    for (const sim::Parameter* p : rows)
        row(o, path, *p, s);
}

} // namespace parsing

} // namespace forcelab::lessons
