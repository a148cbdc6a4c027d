#include "lesson_parser.h"

#include "lesson_markup.h"
#include "message_text.h"

#include "lesson_controls.h"
#include "lesson_limits.h"
#include "nearest_key.h"
#include "sim/world/names.h"
#include "sim/world/parameters.h"
#include "sim/world/scene_keys.h"

#include <QJsonArray>
#include <QRegularExpression>

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <string_view>

namespace forcelab::lessons {

namespace {

QString join(const QString& path, const QString& key)
{
    return path.isEmpty() ? key : path + QLatin1Char('.') + key;
}

QString join(const QString& path, qsizetype index)
{
    return path + QLatin1Char('.') + QString::number(index);
}

/// A number for messages: whole numbers up to 1e9 in full, others in the
/// shortest form that reads back to the same double.
QString numberText(double v)
{
    if (std::isfinite(v) && std::floor(v) == v && std::abs(v) <= 1e9)
        return QString::number(static_cast<qint64>(v));
    return QString::number(v, 'g', QLocale::FloatingPointShortest);
}

} // namespace

QString Range::text() const
{
    QString s = QStringLiteral("%1%2, %3%4").arg(loOpen ? "(" : "[", numberText(lo), numberText(hi), hiOpen ? ")" : "]");
    if (*unit)
        s += QLatin1Char(' ') + QString::fromUtf8(unit);
    return s;
}

namespace {

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

const QStringList kWallNames{QStringLiteral("left"), QStringLiteral("right"), QStringLiteral("top"),
                             QStringLiteral("bottom")};

// Reads typed values out of JSON objects, collecting every problem with its
// key path. A setter assigns its output only when the value is present and
// valid, so absent keys keep the struct defaults.
class Reader {
public:
    explicit Reader(ParseResult& result) : m_result(result) {}

    void fail(const QString& path, const QString& problem)
    {
        if (m_result.problems.size() < kMaxErrors)
            m_result.problems.append({path, problem});
        else
            ++m_result.unlisted;
    }

    void checkKeys(const QJsonObject& o, const QString& path, const QStringList& known)
    {
        for (auto it = o.begin(); it != o.end(); ++it)
            if (!known.contains(it.key()))
                fail(join(path, it.key()), unknownKeyMessage(it.key(), known));
    }

    bool require(const QJsonObject& o, const QString& path, const QString& key, const QString& what)
    {
        if (o.contains(key))
            return true;
        fail(join(path, key), QStringLiteral("missing; give %1").arg(what));
        return false;
    }

    /// The object under `key`, or nullopt when absent or not an object (reported).
    std::optional<QJsonObject> object(const QJsonObject& o, const QString& path, const QString& key)
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

    std::optional<QJsonArray> array(const QJsonObject& o, const QString& path, const QString& key,
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

    bool numberValue(const QJsonValue& v, const QString& path, const Range& r, double& out)
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

    bool number(const QJsonObject& o, const QString& path, const QString& key, const Range& r, double& out)
    {
        if (!o.contains(key))
            return false;
        return numberValue(o.value(key), join(path, key), r, out);
    }

    bool integer(const QJsonObject& o, const QString& path, const QString& key, int lo, int hi, int& out)
    {
        if (!o.contains(key))
            return false;
        const QString p = join(path, key);
        const QJsonValue v = o.value(key);
        if (!v.isDouble()) {
            fail(p, QStringLiteral("expected a whole number in [%1, %2], got %3").arg(lo).arg(hi).arg(describe(v)));
            return false;
        }
        const double d = v.toDouble();
        if (std::floor(d) != d) {
            fail(p, QStringLiteral("expected a whole number, got %1").arg(numberText(d)));
            return false;
        }
        if (d < lo || d > hi) {
            fail(p, QStringLiteral("%1 is outside [%2, %3]").arg(numberText(d)).arg(lo).arg(hi));
            return false;
        }
        out = static_cast<int>(d);
        return true;
    }

    /// A seed: a whole number in [0, 2^53], or a string of decimal digits for larger ones.
    bool seed(const QJsonObject& o, const QString& path, const QString& key, std::uint64_t& out)
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

    bool boolean(const QJsonObject& o, const QString& path, const QString& key, bool& out)
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

    bool string(const QJsonObject& o, const QString& path, const QString& key, QString& out)
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

    bool stringList(const QJsonObject& o, const QString& path, const QString& key, QStringList& out)
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

    bool colourValue(const QJsonValue& v, const QString& path, sim::Rgb& out)
    {
        const auto c = v.isString() ? parseColour(v.toString()) : std::nullopt;
        if (!c) {
            fail(path, QStringLiteral("expected a colour written \"#rrggbb\" (e.g. \"#e05050\"), got ") + describe(v));
            return false;
        }
        out = *c;
        return true;
    }

    /// A Choice row: its value is one of the row's names (or an alias).
    bool choice(const QJsonObject& o, const QString& path, const QString& key, const sim::Parameter& row,
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

    /// A [min, max] pair, or one number for both.
    bool interval(const QJsonObject& o, const QString& path, const QString& key, const Range& r, double& lo, double& hi)
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

    /// One row of the parameter table, read from the section object `o` at
    /// `path`; written into `s` only when present and valid.
    void row(const QJsonObject& o, const QString& path, const sim::Parameter& p, sim::WorldSettings& s)
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

    /// Every row of a section: the keys the object may hold, what listing the
    /// section means (whenListed), then each row present.
    void section(const QJsonObject& o, const QString& path, sim::WorldSettings& s, const QStringList& extraKeys = {})
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

private:
    ParseResult& m_result;
};

void parseWorld(Reader& r, const QJsonObject& o, sim::WorldSettings& s)
{
    const QString path = QStringLiteral("world");
    r.section(o, path, s, {QStringLiteral("walls")});
    // The walls are a list of names in the file, one switch each in the table.
    if (const auto walls = r.array(o, path, "walls", QStringLiteral("an array of wall names (left, right, top, bottom)"))) {
        bool on[4] = {false, false, false, false};
        bool ok = true;
        if (walls->size() > 4) {
            r.fail(join(path, "walls"), QStringLiteral("at most four walls: left, right, top, bottom"));
            ok = false;
        }
        for (qsizetype i = 0; ok && i < walls->size(); ++i) {
            const QString p = join(join(path, "walls"), i);
            const QJsonValue v = walls->at(i);
            const qsizetype k = v.isString() ? kWallNames.indexOf(v.toString()) : -1;
            if (!v.isString()) {
                r.fail(p, QStringLiteral("expected a string, one of left, right, top, bottom, got ") + describe(v));
                ok = false;
            } else if (k < 0) {
                r.fail(p, QStringLiteral("%1 is not one of left, right, top, bottom").arg(quoted(v.toString())));
                ok = false;
            } else if (on[k]) {
                r.fail(p, QStringLiteral("%1 is listed twice").arg(quoted(v.toString())));
                ok = false;
            } else {
                on[k] = true;
            }
        }
        if (ok)
            for (int k = 0; k < 4; ++k)
                sim::findParameter("world.walls." + kWallNames[k].toStdString())->set(s, on[k] ? 1.0 : 0.0);
    }
}

void parseTime(Reader& r, const QJsonObject& o, sim::WorldSettings& s)
{
    const QString path = QStringLiteral("time");
    r.section(o, path, s, {QStringLiteral("seed")});
    r.seed(o, path, "seed", s.time.seed); // a whole number up to 2^64 − 1: not a row of doubles
}

/// The custom force's formulas and constants: "fx", "fy", "potential" as
/// strings, "constants": {"k": 4}, "ranges": {"k": [0, 20]} (a slider's
/// range; without one it runs from 0, or twice a negative value, to twice
/// the value, or 1). Whether the formulas compile is sim's check, made with
/// the whole settings (validateSettings) and reported at the formula's key.
void parseCustom(Reader& r, const QJsonObject& o, const QString& path, sim::CustomForceSettings& c)
{
    QString text;
    if (r.string(o, path, "fx", text))
        c.fx = text.toStdString();
    if (r.string(o, path, "fy", text))
        c.fy = text.toStdString();
    if (r.string(o, path, "potential", text))
        c.potential = text.toStdString();
    c.constants.clear();
    if (const auto k = r.object(o, path, "constants")) {
        const QString kp = join(path, "constants");
        for (auto it = k->begin(); it != k->end(); ++it) {
            sim::CustomConstant constant;
            constant.name = it.key().toStdString();
            if (!r.numberValue(it.value(), join(kp, it.key()), range::kClaimNumber, constant.value))
                continue;
            constant.min = constant.value < 0 ? 2 * constant.value : 0.0;
            constant.max = constant.value > 0 ? 2 * constant.value : 1.0;
            c.constants.push_back(constant);
        }
    }
    if (const auto ranges = r.object(o, path, "ranges")) {
        const QString rp = join(path, "ranges");
        for (auto it = ranges->begin(); it != ranges->end(); ++it) {
            const QString p = join(rp, it.key());
            auto found = std::find_if(c.constants.begin(), c.constants.end(),
                                      [&](const sim::CustomConstant& k) { return k.name == it.key().toStdString(); });
            if (found == c.constants.end()) {
                r.fail(p, QStringLiteral("a range for %1, which is not one of the constants").arg(quoted(it.key())));
                continue;
            }
            const QJsonArray a = it.value().toArray();
            double lo = 0.0, hi = 0.0;
            if (!it.value().isArray() || a.size() != 2) {
                r.fail(p, QStringLiteral("expected [min, max], got ") + describe(it.value()));
                continue;
            }
            if (r.numberValue(a.at(0), join(p, 0), range::kClaimNumber, lo) &&
                r.numberValue(a.at(1), join(p, 1), range::kClaimNumber, hi)) {
                found->min = lo;
                found->max = hi;
            }
        }
    }
}

void parseModels(Reader& r, const QJsonObject& models, sim::WorldSettings& s)
{
    const QString base = QStringLiteral("models");
    // The models are the sections of the parameter table under "models.".
    QStringList known;
    for (const sim::Parameter& p : sim::parameters()) {
        const QString key = qs(p.key);
        if (!key.startsWith(base + QLatin1Char('.')))
            continue;
        const QString model = key.section(QLatin1Char('.'), 1, 1);
        if (!known.contains(model))
            known << model;
    }
    r.checkKeys(models, base, known);
    for (const QString& model : known) {
        const auto o = r.object(models, base, model);
        if (!o)
            continue;
        const bool custom = model == QStringLiteral("custom");
        r.section(*o, join(base, model), s,
                  custom ? QStringList{"fx", "fy", "potential", "constants", "ranges"} : QStringList{});
        if (custom)
            parseCustom(r, *o, join(base, model), s.custom);
    }
}

void parseBalls(Reader& r, const QJsonArray& balls, std::vector<sim::Ball>& out)
{
    const QString base = QStringLiteral("balls");
    if (balls.size() > kMaxBalls) {
        r.fail(base, QStringLiteral("%1 balls is more than the limit of %2").arg(balls.size()).arg(kMaxBalls));
        return;
    }
    const QStringList known{"x", "y", "vx", "vy", "r", "mass", "q", "color"};
    out.clear();
    out.reserve(static_cast<std::size_t>(balls.size()));
    for (qsizetype i = 0; i < balls.size(); ++i) {
        const QString p = join(base, i);
        const QJsonValue v = balls.at(i);
        if (!v.isObject()) {
            r.fail(p, QStringLiteral("expected a ball object {\"x\": …, \"y\": …}, got ") + describe(v));
            continue;
        }
        const QJsonObject o = v.toObject();
        r.checkKeys(o, p, known);
        sim::Ball b;
        r.require(o, p, "x", QStringLiteral("the ball's centre x in px"));
        r.require(o, p, "y", QStringLiteral("the ball's centre y in px"));
        r.number(o, p, "x", range::kBallPosition, b.position.x());
        r.number(o, p, "y", range::kBallPosition, b.position.y());
        r.number(o, p, "vx", range::kBallVelocity, b.velocity.x());
        r.number(o, p, "vy", range::kBallVelocity, b.velocity.y());
        r.number(o, p, "r", range::kRadius, b.radius);
        r.number(o, p, "mass", range::kMass, b.mass);
        r.number(o, p, "q", range::kCharge, b.charge);
        if (o.contains("color"))
            r.colourValue(o.value("color"), join(p, "color"), b.color);
        out.push_back(b);
    }
}

void parseSpawn(Reader& r, const QJsonObject& o, int listed, sim::SpawnSettings& s)
{
    const QString path = QStringLiteral("spawn");
    r.checkKeys(o, path,
                {"count", "radius", "speed", "seed", "palette", "horizontal", "fully_inside", "per_step", "max_count"});
    if (r.integer(o, path, "count", 0, kMaxBalls, s.count) && listed + s.count > kMaxBalls) {
        r.fail(join(path, "count"), QStringLiteral("%1 spawned + %2 listed balls is more than the limit of %3")
                                        .arg(s.count)
                                        .arg(listed)
                                        .arg(kMaxBalls));
    }
    r.interval(o, path, "radius", range::kRadius, s.minRadius, s.maxRadius);
    r.interval(o, path, "speed", range::kSpawnSpeed, s.minSpeed, s.maxSpeed);
    r.seed(o, path, "seed", s.seed);
    r.boolean(o, path, "horizontal", s.horizontal);
    r.boolean(o, path, "fully_inside", s.fullyInside);
    r.number(o, path, "per_step", range::kUnit, s.perStep);
    r.integer(o, path, "max_count", 0, kMaxBalls, s.maxCount);
    if (const auto a = r.array(o, path, "palette", QStringLiteral("an array of colours \"#rrggbb\""))) {
        const QString p = join(path, "palette");
        if (a->size() > kMaxPaletteColours) {
            r.fail(p, QStringLiteral("%1 colours is more than the limit of %2").arg(a->size()).arg(kMaxPaletteColours));
            return;
        }
        std::vector<sim::Rgb> palette;
        bool ok = true;
        for (qsizetype i = 0; i < a->size(); ++i) {
            sim::Rgb c = 0;
            if (r.colourValue(a->at(i), join(p, i), c))
                palette.push_back(c);
            else
                ok = false;
        }
        if (ok)
            s.palette = std::move(palette);
    }
}

/// {"key.path": value, …}: parameter rows and values allowed for them
/// (choices by name, switches as true/false), as claims' and compare panes'
/// "set". With `scene`, a claim's: its keys may also name a listed ball's
/// start or the random balls' count and ranges (sim/world/scene_keys.h), which are
/// applied to one copy of the scene, made at the first such key, so that
/// the ranges are checked as the claim will run them.
void parseSet(Reader& r, const QJsonObject& set, const QString& sp, std::vector<std::pair<std::string, double>>& out,
              const sim::Scene* scene = nullptr)
{
    std::optional<sim::Scene> changed;
    for (auto it = set.begin(); it != set.end(); ++it) {
        const QString key = it.key();
        if (scene && sim::isSceneKey(key.toStdString())) {
            const QJsonValue v = it.value();
            if (!v.isDouble() && !v.isBool()) {
                r.fail(join(sp, key), QStringLiteral("expected a number (or true or false for a switch), got ") +
                                          describe(v));
                continue;
            }
            const double value = v.isBool() ? (v.toBool() ? 1.0 : 0.0) : v.toDouble();
            if (!changed)
                changed = *scene;
            if (const auto problem = sim::setSceneKey(*changed, key.toStdString(), value)) {
                r.fail(join(sp, key), qs(*problem));
                continue;
            }
            out.emplace_back(key.toStdString(), value);
            continue;
        }
        const sim::Parameter* row = sim::findParameter(key.toStdString());
        if (!row) {
            r.fail(join(sp, key), QStringLiteral("not a parameter key path (docs/parameters.md lists them)"));
            continue;
        }
        const QJsonValue v = it.value();
        double value = 0.0;
        switch (row->type) {
        case sim::ParameterType::Boolean:
            if (!v.isBool()) {
                r.fail(join(sp, key), QStringLiteral("expected true or false, got ") + describe(v));
                continue;
            }
            value = v.toBool() ? 1.0 : 0.0;
            break;
        case sim::ParameterType::Choice: {
            const int i = v.isString() ? sim::choiceIndex(*row, v.toString().toStdString()) : -1;
            if (i < 0) {
                r.fail(join(sp, key), QStringLiteral("%1 is not one of %2").arg(describe(v), names(row->choices())));
                continue;
            }
            value = i;
            break;
        }
        case sim::ParameterType::Number:
        case sim::ParameterType::Integer:
            if (!v.isDouble() || sim::checkValue(*row, v.toDouble())) {
                r.fail(join(sp, key), QStringLiteral("expected a number allowed for %1, got %2").arg(key, describe(v)));
                continue;
            }
            value = v.toDouble();
            break;
        }
        out.emplace_back(key.toStdString(), value);
    }
    if (changed)
        if (const auto problem = sim::checkSpawnRanges(changed->spawn))
            r.fail(sp, qs(*problem));
}

/// One claim: {"says": "…", "measure": "apex", "ball": 0, "n": 1, "at": 10,
/// "near": 192, "within": 1} (or "within_percent", or "below"/"above" instead
/// of "near"), optionally "axis", "other", "distance" and "set": {key: value}.
void parseClaim(Reader& r, const QJsonObject& o, const QString& p, const sim::Scene& scene, sim::Claim& c)
{
    const int balls = static_cast<int>(scene.balls.size()) + scene.spawn.count;
    r.checkKeys(o, p,
                {"says", "measure", "ball", "other", "at", "n", "axis", "distance", "near", "within", "within_percent",
                 "below", "above", "set"});
    QString text;
    if (r.require(o, p, "says", QStringLiteral("the sentence of the text this claim checks")) &&
        r.string(o, p, "says", text))
        c.text = text.toStdString();
    QString measure;
    QStringList measures;
    for (const sim::ClaimMeasure& m : sim::claimMeasures())
        measures << qs(m.name);
    if (r.require(o, p, "measure", QStringLiteral("one of ") + measures.join(", ")) &&
        r.string(o, p, "measure", measure)) {
        if (!sim::findClaimMeasure(measure.toStdString()))
            r.fail(join(p, "measure"), QStringLiteral("%1 is not one of %2").arg(quoted(measure), measures.join(", ")));
        c.measure = measure.toStdString();
    }
    const int lastBall = std::max(0, balls - 1);
    r.integer(o, p, "ball", 0, lastBall, c.ball);
    r.integer(o, p, "other", 0, lastBall, c.other);
    r.require(o, p, "at", QStringLiteral("the time in s it is measured at (or the run's length, or the latest time "
                                         "for the event)"));
    r.number(o, p, "at", range::kClaimTime, c.at);
    r.integer(o, p, "n", 1, 1000, c.occurrence);
    QString axis;
    if (r.string(o, p, "axis", axis)) {
        if (axis != QStringLiteral("x") && axis != QStringLiteral("y"))
            r.fail(join(p, "axis"), QStringLiteral("%1 is not one of x, y").arg(quoted(axis)));
        else
            c.axis = axis == QStringLiteral("x") ? 'x' : 'y';
    }
    r.number(o, p, "distance", range::kClaimNumber, c.distance);
    const int tests = int(o.contains("near")) + int(o.contains("below")) + int(o.contains("above"));
    if (tests != 1)
        r.fail(p, QStringLiteral("give exactly one of \"near\" (with \"within\" or \"within_percent\"), "
                                 "\"below\" or \"above\""));
    if (r.number(o, p, "below", range::kClaimNumber, c.value))
        c.test = sim::ClaimTest::Below;
    if (r.number(o, p, "above", range::kClaimNumber, c.value))
        c.test = sim::ClaimTest::Above;
    if (r.number(o, p, "near", range::kClaimNumber, c.value)) {
        c.test = sim::ClaimTest::Near;
        double percent = 0.0;
        if (o.contains("within") == o.contains("within_percent"))
            r.fail(p, QStringLiteral("give \"near\" one tolerance: \"within\" (in the measurement's unit) or "
                                     "\"within_percent\""));
        else if (r.number(o, p, "within_percent", range::kPercent, percent))
            c.relative = true, c.tolerance = percent / 100.0;
        else
            r.number(o, p, "within", range::kClaimTolerance, c.tolerance);
    }
    if (const auto set = r.object(o, p, "set"))
        parseSet(r, *set, join(p, "set"), c.set, &scene);
}

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

void parseClaims(Reader& r, const QJsonArray& a, const sim::Scene& scene, std::vector<sim::Claim>& out)
{
    objectList(r, a, QStringLiteral("claims"), kMaxListEntries, "entries",
               QStringLiteral("a claim object {\"says\": …, \"measure\": …}"), out,
               [&](const QJsonObject& o, const QString& p) {
                   sim::Claim c;
                   parseClaim(r, o, p, scene, c);
                   return c;
               });
}

/// [{"says": "…", "because": "question"}, {"says": "…", "because": "unmeasured", "why": "…"}]:
/// sentences with numbers that are not claims, and why (lesson.h).
void parseNotMeasured(Reader& r, const QJsonArray& a, std::vector<NotMeasured>& out)
{
    QStringList reasons;
    for (const char* name : kNotMeasuredReasons)
        reasons << QLatin1String(name);
    objectList(r, a, QStringLiteral("not_measured"), kMaxListEntries, "entries",
               QStringLiteral("an entry {\"says\": …, \"because\": …}"), out,
               [&](const QJsonObject& o, const QString& p) {
                   r.checkKeys(o, p, {"says", "because", "why"});
                   NotMeasured n;
                   if (r.require(o, p, "says", QStringLiteral("the sentence, as the lesson writes it")))
                       r.string(o, p, "says", n.says);
                   QString because;
                   if (r.require(o, p, "because", QStringLiteral("one of ") + reasons.join(", ")) &&
                       r.string(o, p, "because", because)) {
                       const qsizetype i = reasons.indexOf(because);
                       if (i < 0)
                           r.fail(join(p, "because"),
                                  QStringLiteral("%1 is not one of %2").arg(quoted(because), reasons.join(", ")));
                       else
                           n.because = static_cast<NotMeasured::Because>(i);
                   }
                   r.string(o, p, "why", n.why);
                   if (n.because == NotMeasured::Because::Unmeasured && n.why.trimmed().isEmpty())
                       r.fail(join(p, "why"), QStringLiteral("an unmeasured sentence needs \"why\": how it was checked "
                                                             "and which measurement it lacks"));
                   return n;
               });
}

/// {"ask": "How high …?", "claim": 0, "choices": [{"label": "…", "value": 0}, …]}:
/// one question, answered by the claim with that index.
Prediction parseQuestion(Reader& r, const QJsonObject& o, const QString& p, int claims)
{
    r.checkKeys(o, p, {"ask", "claim", "choices"});
    Prediction q;
    if (r.require(o, p, "ask", QStringLiteral("the question, e.g. \"How high will the ball rise?\"")))
        r.string(o, p, "ask", q.ask);
    if (r.require(o, p, "claim", QStringLiteral("the index of the claim whose measurement answers it"))) {
        if (claims == 0)
            r.fail(join(p, "claim"), QStringLiteral("the lesson has no claims to answer the question"));
        else
            r.integer(o, p, "claim", 0, claims - 1, q.claim);
    }
    if (const auto c = r.array(o, p, "choices", QStringLiteral("an array of {\"label\": …, \"value\": …}"))) {
        const QString cp = join(p, "choices");
        if (c->size() < 2 || c->size() > 8)
            r.fail(cp, QStringLiteral("%1 %2; give 2 to 8").arg(c->size()).arg(c->size() == 1 ? "choice" : "choices"));
        for (qsizetype k = 0; k < c->size(); ++k) {
            const QString kp = join(cp, k);
            if (!c->at(k).isObject()) {
                r.fail(kp, QStringLiteral("expected {\"label\": …, \"value\": …}, got ") + describe(c->at(k)));
                continue;
            }
            const QJsonObject choice = c->at(k).toObject();
            r.checkKeys(choice, kp, {"label", "value"});
            QString label;
            double value = 0.0;
            r.require(choice, kp, "label", QStringLiteral("the answer as the student reads it"));
            r.require(choice, kp, "value", QStringLiteral("the answer in the claim's unit"));
            if (r.string(choice, kp, "label", label) && r.number(choice, kp, "value", range::kClaimNumber, value)) {
                q.choices << label;
                q.values.push_back(value);
            }
        }
    }
    return q;
}

/// [{"ask": "How high …?", "claim": 0}, {"ask": "…", "claim": 1, "choices":
/// [{"label": "…", "value": 0}, …]}]: each question is answered by a claim.
void parsePredict(Reader& r, const QJsonArray& a, int claims, std::vector<Prediction>& out)
{
    objectList(r, a, QStringLiteral("predict"), kMaxListEntries, "entries",
               QStringLiteral("a question {\"ask\": …, \"claim\": …}"), out,
               [&](const QJsonObject& o, const QString& p) { return parseQuestion(r, o, p, claims); });
}

/// [{"label": "mirror", "set": {"world.wall_model": "mirror"}}, …]
void parseCompare(Reader& r, const QJsonArray& a, std::vector<ComparePane>& out)
{
    objectList(r, a, QStringLiteral("compare"), Lesson::kMaxComparePanes, "panes",
               QStringLiteral("a pane {\"label\": …, \"set\": {…}}"), out,
               [&](const QJsonObject& o, const QString& p) {
                   r.checkKeys(o, p, {"label", "set"});
                   ComparePane pane;
                   if (r.require(o, p, "label", QStringLiteral("the pane's name, e.g. \"mirror\"")))
                       r.string(o, p, "label", pane.label);
                   if (r.require(o, p, "set", QStringLiteral("the settings this pane runs with, {\"key.path\": value}")))
                       if (const auto set = r.object(o, p, "set"))
                           parseSet(r, *set, join(p, "set"), pane.set);
                   return pane;
               });
}

/// {"goal": "…", "minutes": 20, "misconceptions": […], "answers": […]}: one
/// answer per challenge when answers are given.
void parseTeacher(Reader& r, const QJsonObject& o, qsizetype challenges, TeacherNotes& t)
{
    const QString p = QStringLiteral("teacher");
    r.checkKeys(o, p, {"goal", "minutes", "misconceptions", "answers"});
    r.string(o, p, "goal", t.goal);
    r.integer(o, p, "minutes", 0, 600, t.minutes);
    r.stringList(o, p, "misconceptions", t.misconceptions);
    // No answers yet is allowed; once given, one per challenge.
    if (r.stringList(o, p, "answers", t.answers) && !t.answers.isEmpty() && t.answers.size() != challenges)
        r.fail(join(p, "answers"), QStringLiteral("%1 %2 for %3 %4; give one answer per challenge, in order")
                                       .arg(t.answers.size())
                                       .arg(t.answers.size() == 1 ? "answer" : "answers")
                                       .arg(challenges)
                                       .arg(challenges == 1 ? "challenge" : "challenges"));
}

/// A list of names each of which must be one of `allowed`.
void nameList(Reader& r, const QJsonObject& root, const QString& key, const QStringList& allowed, QStringList& out)
{
    QStringList list;
    if (!r.stringList(root, QString(), key, list))
        return;
    bool ok = true;
    for (qsizetype i = 0; i < list.size(); ++i) {
        if (!allowed.contains(list[i])) {
            r.fail(join(key, i), QStringLiteral("%1 is not one of %2").arg(quoted(list[i]), allowed.join(", ")));
            ok = false;
        }
    }
    if (ok)
        out = list;
}

} // namespace

const QStringList& overlayNames()
{
    static const QStringList names{"grid",    "velocity", "acceleration", "readout",   "colliding", "markers",
                                   "vanes",   "trails",   "impact",       "broadphase", "histogram", "totals",
                                   "forces",  "sources",  "centre-of-mass", "momenta", "apexes"};
    return names;
}

/// Every text a reader sees is in the markup subset and within its length
/// (lesson_markup.h): a problem names the field and the character.
void checkProse(Reader& r, const Lesson& lesson)
{
    auto check = [&r](const QString& path, const QString& text, qsizetype maxChars) {
        if (const auto problem = checkMarkup(text, maxChars))
            r.fail(path, QStringLiteral("character %1: %2").arg(problem->at + 1).arg(problem->message));
    };
    auto checkList = [&](const QString& path, const QStringList& texts) {
        for (qsizetype i = 0; i < texts.size(); ++i)
            check(join(path, i), texts[i], kMaxProseChars);
    };
    check(QStringLiteral("title"), lesson.title, kMaxProseChars);
    check(QStringLiteral("text"), lesson.text, kMaxTextChars);
    checkList(QStringLiteral("challenges"), lesson.challenges);
    check(QStringLiteral("teacher.goal"), lesson.teacher.goal, kMaxProseChars);
    checkList(QStringLiteral("teacher.misconceptions"), lesson.teacher.misconceptions);
    checkList(QStringLiteral("teacher.answers"), lesson.teacher.answers);
    for (std::size_t k = 0; k < lesson.predict.size(); ++k) {
        const QString path = join(QStringLiteral("predict"), static_cast<qsizetype>(k));
        check(join(path, "ask"), lesson.predict[k].ask, kMaxProseChars);
        for (qsizetype c = 0; c < lesson.predict[k].choices.size(); ++c)
            check(join(join(join(path, "choices"), c), "label"), lesson.predict[k].choices[c], kMaxProseChars);
    }
    for (std::size_t k = 0; k < lesson.compare.size(); ++k)
        check(join(join(QStringLiteral("compare"), static_cast<qsizetype>(k)), "label"), lesson.compare[k].label,
              kMaxProseChars);
    for (std::size_t k = 0; k < lesson.claims.size(); ++k)
        check(join(join(QStringLiteral("claims"), static_cast<qsizetype>(k)), "says"),
              QString::fromStdString(lesson.claims[k].text), kMaxProseChars);
    for (std::size_t k = 0; k < lesson.notMeasured.size(); ++k) {
        const QString path = join(QStringLiteral("not_measured"), static_cast<qsizetype>(k));
        check(join(path, "says"), lesson.notMeasured[k].says, kMaxProseChars);
        check(join(path, "why"), lesson.notMeasured[k].why, kMaxProseChars);
    }
}

/// A whole number with its thousands grouped: "360,000,000,000".
QString groupedDigits(double v)
{
    QString digits = QString::number(v, 'f', 0);
    for (qsizetype at = digits.size() - 3; at > 0; at -= 3)
        digits.insert(at, QLatin1Char(','));
    return digits;
}

/// Each claim runs its scene to `at`: refused when that takes more sub-steps
/// than kMaxClaimSteps, with the claim's own dt and sub-steps where it sets them.
void checkClaimWork(Reader& r, const Lesson& lesson)
{
    const sim::TimeSettings& time = lesson.scene.settings.time;
    for (std::size_t k = 0; k < lesson.claims.size(); ++k) {
        const sim::Claim& c = lesson.claims[k];
        double dt = time.dt, substeps = time.substeps;
        for (const auto& [key, value] : c.set) {
            if (key == "time.dt")
                dt = value;
            else if (key == "time.substeps")
                substeps = value;
        }
        if (!(dt > 0.0))
            continue; // a bad dt is reported where it is set
        const double steps = std::ceil(c.at / dt) * std::max(1.0, substeps);
        if (steps > kMaxClaimSteps)
            r.fail(join(join(QStringLiteral("claims"), static_cast<qsizetype>(k)), "at"),
                   QStringLiteral("%1 s at dt = %2 s is %3 sub-steps, more than the %4 a claim may run; claim an "
                                  "earlier time or use a larger dt")
                       .arg(numberText(c.at), numberText(dt), groupedDigits(steps), groupedDigits(kMaxClaimSteps)));
    }
}

ParseResult parseLesson(const QJsonObject& root)
{
    ParseResult result;
    Reader r(result);
    Lesson& lesson = result.lesson;
    const QString top;
    r.checkKeys(root, top,
                {"format", "id", "title", "stage", "text", "challenges", "world", "time", "models", "balls", "spawn",
                 "controls", "overlays", "claims", "not_measured", "teacher", "compare", "predict"});

    if (r.require(root, top, "format", QStringLiteral("\"format\": 1"))) {
        const QJsonValue v = root.value("format");
        if (!v.isDouble() || v.toDouble() != kFormat)
            r.fail("format", QStringLiteral("%1 is not a format this version reads; it reads format %2")
                                 .arg(v.isDouble() ? numberText(v.toDouble()) : describe(v))
                                 .arg(kFormat));
    }
    lesson.format = kFormat;

    if (r.require(root, top, "id", QStringLiteral("a short name such as \"gravity\"")) &&
        r.string(root, top, "id", lesson.id)) {
        static const QRegularExpression idPattern(QStringLiteral("^[A-Za-z0-9_-]{1,64}$"));
        if (!idPattern.match(lesson.id).hasMatch())
            r.fail("id", QStringLiteral("%1 is not a valid id; use 1 to 64 letters, digits, '-' or '_'")
                             .arg(quoted(lesson.id)));
    }
    if (!r.string(root, top, "title", lesson.title))
        lesson.title = lesson.id;
    r.integer(root, top, "stage", intrange::kStageLo, intrange::kStageHi, lesson.stage);
    r.string(root, top, "text", lesson.text);
    r.stringList(root, top, "challenges", lesson.challenges);
    nameList(r, root, "controls", controlNames(), lesson.controls);
    nameList(r, root, "overlays", overlayNames(), lesson.overlays);

    sim::Scene& scene = lesson.scene;
    if (const auto o = r.object(root, top, "world"))
        parseWorld(r, *o, scene.settings);
    if (const auto o = r.object(root, top, "time"))
        parseTime(r, *o, scene.settings);
    if (const auto o = r.object(root, top, "models"))
        parseModels(r, *o, scene.settings);
    if (const auto a = r.array(root, top, "balls", QStringLiteral("an array of ball objects")))
        parseBalls(r, *a, scene.balls);
    if (const auto o = r.object(root, top, "spawn"))
        parseSpawn(r, *o, static_cast<int>(scene.balls.size()), scene.spawn);
    if (const auto a = r.array(root, top, "claims", QStringLiteral("an array of claim objects")))
        parseClaims(r, *a, scene, lesson.claims);
    if (const auto a = r.array(root, top, "not_measured", QStringLiteral("an array of sentence objects")))
        parseNotMeasured(r, *a, lesson.notMeasured);
    if (const auto o = r.object(root, top, "teacher"))
        parseTeacher(r, *o, lesson.challenges.size(), lesson.teacher);
    if (const auto a = r.array(root, top, "compare", QStringLiteral("an array of panes")))
        parseCompare(r, *a, lesson.compare);
    if (const auto a = r.array(root, top, "predict", QStringLiteral("an array of questions")))
        parsePredict(r, *a, static_cast<int>(lesson.claims.size()), lesson.predict);
    checkProse(r, lesson);
    checkClaimWork(r, lesson);
    return result;
}

} // namespace forcelab::lessons
