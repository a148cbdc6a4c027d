#include "lesson_controls.h"

#include "sim/world/parameters.h"

#include <QList>
#include <QRegularExpression>
#include <QSet>

#include <algorithm>

namespace forcelab::lessons {

// Which rows each lesson `controls` name shows. A name may show rows of
// several sections ("restitution": the walls' and the balls').
const QHash<QString, QStringList>& controlRows()
{
    static const QHash<QString, QStringList> rows = [] {
    QHash<QString, QStringList> rows{
        {QStringLiteral("gravity"), {"gravity_x", "gravity_y"}},
        {QStringLiteral("drag"), {"drag_law", "drag_k", "drag_scale"}},
        {QStringLiteral("wind"), {"wind_mode", "wind_strength", "wind_scale", "wind_smoothed_step", "wind_frequency"}},
        {QStringLiteral("wind_compare"), {"wind_mode", "wind_compare", "wind_strength"}},
        {QStringLiteral("random_accel"), {"random_fixed", "random_strength"}},
        {QStringLiteral("point"), {"point_kind", "point_x", "point_y", "point_strength", "point_clamp", "point_scale"}},
        {QStringLiteral("spring"), {"spring_k", "spring_x", "spring_y"}},
        {QStringLiteral("mutual_gravity"), {"mutual_g", "mutual_softening"}},
        {QStringLiteral("homing"), {"homing_strength"}},
        {QStringLiteral("pointer"), {"pointer_strength", "pointer_clamp"}},
        {QStringLiteral("speed_limit"), {"speed_limit"}},
        {QStringLiteral("custom"), {"custom_acceleration"}},
        {QStringLiteral("collisions"), {"detection", "response", "ball_restitution", "continuous", "resting"}},
        {QStringLiteral("walls"), {"wall_sides", "wall_model", "wall_restitution"}},
        {QStringLiteral("box"), {"box_width", "box_height"}},
        {QStringLiteral("wall_model"), {"wall_model"}},
        {QStringLiteral("restitution"), {"wall_restitution", "ball_restitution"}},
        {QStringLiteral("middle_wall"), {"middle_wall"}},
        {QStringLiteral("centre_only"), {"centre_only"}},
        {QStringLiteral("integrator"), {"integrator"}},
        {QStringLiteral("dt"), {"dt"}},
        {QStringLiteral("substeps"), {"substeps"}},
        {QStringLiteral("tolerance"), {"tolerance"}},
        {QStringLiteral("per_frame"), {"per_frame"}},
        {QStringLiteral("close_passes"), {"close_passes"}},
        {QStringLiteral("seed"), {"seed"}},
        {QStringLiteral("spawn"), {"ball_count"}},
        {QStringLiteral("spawn_speed"), {"spawn_min_speed", "spawn_max_speed"}},
        {QStringLiteral("fully_inside"), {"fully_inside"}},
        {QStringLiteral("point_clamp"), {"point_clamp"}},
        {QStringLiteral("response"), {"response"}},
        {QStringLiteral("detection"), {"detection"}},
        {QStringLiteral("resting"), {"resting"}},
        {QStringLiteral("time_scale"), {"time_scale"}},
    };
    // A model that has no entry above shows its own rows under its own name
    // ("models.magnetic.*" → "magnetic"), so a new model needs no entry here.
    QSet<QString> added;
    for (const sim::Parameter& p : sim::parameters()) {
        const QString key = QString::fromUtf8(p.key.data(), static_cast<qsizetype>(p.key.size()));
        if (!key.startsWith(QStringLiteral("models.")) || key.endsWith(QStringLiteral(".enabled")))
            continue;
        const QString model = key.section(QLatin1Char('.'), 1, 1);
        if (rows.contains(model) && !added.contains(model))
            continue;
        added.insert(model);
        rows[model] << QString::fromUtf8(p.control.data(), static_cast<qsizetype>(p.control.size()));
    }
    return rows;
    }();
    return rows;
}

const QStringList& controlNames()
{
    static const QStringList names = [] {
        QStringList out = controlRows().keys();
        out.sort();
        return out;
    }();
    return names;
}

namespace {

struct PhraseRule {
    QRegularExpression pattern;
    QStringList anyOf; ///< empty: the first capture is itself the control's name
};

QRegularExpression words(const char* pattern, bool caseSensitive = false)
{
    return QRegularExpression(QString::fromUtf8(pattern),
                              caseSensitive ? QRegularExpression::NoPatternOption
                                            : QRegularExpression::CaseInsensitiveOption);
}

// The wordings with which a challenge asks for a change. Each rule needs a
// verb of change or an on/off, so "watch the ball reach the right wall" and
// "gravity pulls" are not requests; names of the Parameters panel's own rows
// written as code (per_frame) are requests wherever they stand.
const QList<PhraseRule>& phraseRules()
{
    static const QList<PhraseRule> rules{
        {words(R"(\b(?:turn|switch)(?: on| off)? (?:the )?(?:(?:top|bottom|left|right)(?: and (?:top|bottom|left|right))? )?walls?\b)"),
         {"walls"}},
        {words(R"(\bwall model\b)"), {"wall_model", "walls"}},
        {words(R"(\b(?:switch|change) to (?:clamp|mirror|reverse)\b)"), {"wall_model", "walls"}},
        {words(R"(\b(?:set|change|raise|lower|drag) the wall restitution\b)"), {"restitution", "walls"}},
        {words(R"(\b(?:set|change|raise|lower|drag) the (?:collision|ball) restitution\b)"),
         {"restitution", "collisions"}},
        {words(R"(\b(?:set|change|raise|lower|drag) the restitution\b)"), {"restitution", "collisions", "walls"}},
        {words(R"(\b(?:set|add|change|turn|switch) (?:the )?gravity\b)"), {"gravity"}},
        {words(R"(\b(?:switch|change|set) the integrator\b)"), {"integrator"}},
        {words(R"(\b(?:switch|change) to (?:euler|rk4|verlet|semi-implicit-euler)\b)"), {"integrator"}},
        {words(R"(\b(?:halve|double|set|change|lower|raise|try)(?: and double)? (?:the )?dt\b)"), {"dt"}},
        {words(R"(\b(?:raise|set|use|lower) (?:the )?(?:\d+ )?sub-?steps\b)"), {"substeps"}},
        {words(R"(\b(?:switch|turn) (?:the )?drag (?:off|on)\b|\braise the drag\b|\bwith the drag (?:on|off)\b)"),
         {"drag"}},
        {words(R"(\b(?:switch|turn|set) the speed limit\b)"), {"speed_limit"}},
        {words(R"(\b(?:set|change) the softening\b)"), {"mutual_gravity"}},
        {words(R"(\b(?:Double|Halve|Make|Set|double|halve|make|set) G\b)", true), {"mutual_gravity"}},
        {words(R"(\b(?:switch|set|change) (?:the )?response\b|\bresponse none\b)"), {"response", "collisions"}},
        {words(R"(\b(?:switch|change) to (?:1d-elastic|1d-reverse|2d-axis|2d-impulse)\b)"), {"response", "collisions"}},
        {words(R"(\b(?:switch|set|change) (?:the )?detection\b)"), {"detection", "collisions"}},
        {words(R"(\bwith(?:out)? continuous detection\b)"), {"collisions"}},
        {words(R"(\b(?:switch )?resting contacts (?:off|on|back on)\b)"), {"resting", "collisions"}},
        {words(R"(\b(?:double|halve|change|set) the (?:ball count|number of balls)\b)"), {"spawn"}},
        {words(R"(\b(?:change|set|raise|lower) the spawn speeds?(?: range)?\b)"), {"spawn_speed"}},
        {words(R"(\bmax_accel to\b|\bwith(?:out)? the clamp\b)"), {"point_clamp", "point"}},
        {words(R"(\b(centre_only|fully_inside|per_frame)\b)"), {}},
        {words(R"(\bsmoothed_step\b|\bmake the wind\b)"), {"wind", "wind_compare"}},
    };
    return rules;
}

} // namespace

QList<ControlPhrase> undeclaredControlsIn(const QString& plainText, const QStringList& declared)
{
    QList<ControlPhrase> missing;
    for (const PhraseRule& rule : phraseRules()) {
        auto it = rule.pattern.globalMatch(plainText);
        while (it.hasNext()) {
            const QRegularExpressionMatch m = it.next();
            const QStringList anyOf = rule.anyOf.isEmpty() ? QStringList{m.captured(1)} : rule.anyOf;
            const bool offered = std::any_of(anyOf.begin(), anyOf.end(),
                                             [&](const QString& name) { return declared.contains(name); });
            if (!offered)
                missing << ControlPhrase{m.captured(0), anyOf};
        }
    }
    return missing;
}

} // namespace forcelab::lessons
