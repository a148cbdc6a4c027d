// The claims and not_measured sections of a lesson file: each claim's
// measurement, test and "set" (shared with compare panes), the sentences
// that are not claims, and the limit on the work a claim may take.

#include "lesson_parse_sections.h"

#include "sim/world/scene_keys.h"


#include <algorithm>
#include <cmath>
#include <optional>

namespace forcelab::lessons::parsing {

namespace {


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

/// A whole number with its thousands grouped: "360,000,000,000".
QString groupedDigits(double v)
{
    QString digits = QString::number(v, 'f', 0);
    for (qsizetype at = digits.size() - 3; at > 0; at -= 3)
        digits.insert(at, QLatin1Char(','));
    return digits;
}

} // namespace

void parseSet(Reader& r, const QJsonObject& set, const QString& sp, std::vector<std::pair<std::string, double>>& out,
              const sim::Scene* scene)
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

} // namespace forcelab::lessons::parsing
