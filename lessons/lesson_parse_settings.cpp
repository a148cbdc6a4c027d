// The world, time and models sections of a lesson file: rows of the
// parameter table (sim/world/parameters.h), read section by section, plus
// what is not a row: the walls list, the seed, the custom force's formulas.

#include "lesson_parse_sections.h"

#include "sim/world/parameters.h"

#include <algorithm>

namespace forcelab::lessons::parsing {

namespace {

const QStringList kWallNames{QStringLiteral("left"), QStringLiteral("right"), QStringLiteral("top"),
                             QStringLiteral("bottom")};


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

} // namespace

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

void parseUnits(Reader& r, const QJsonObject& o, std::optional<LessonUnits>& out)
{
    const QString path = QStringLiteral("units");
    r.checkKeys(o, path, {"px_per_metre", "kg_per_mass"});
    LessonUnits units;
    r.number(o, path, "px_per_metre", range::kPxPerMetre, units.pxPerMetre);
    r.number(o, path, "kg_per_mass", range::kKgPerMass, units.kgPerMass);
    out = units;
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

} // namespace forcelab::lessons::parsing
