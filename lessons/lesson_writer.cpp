// saveLesson: a Lesson back to format-1 JSON text. Written by hand rather
// than with QJsonDocument so the keys come in reading order (QJsonObject sorts
// them) and every double is printed with the shortest digits that read back
// to the same bits (sim::shortestText, which is std::to_chars).

#include "colour_names.h"
#include "lesson_languages.h"
#include "lesson_limits.h"
#include "lesson_loader.h"
#include "sim/world/names.h"
#include "sim/world/number_text.h"
#include "sim/world/parameters.h"
#include "sim/world/scene_keys.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace forcelab {
namespace {

using lessons::kMaxNumberSeed;

QByteArray num(double v)
{
    // Non-finite values cannot be written as JSON: they never pass the loader
    // either, so writing null makes the problem visible on the next load.
    if (!std::isfinite(v))
        return "null";
    return QByteArray::fromStdString(sim::shortestText(v));
}

QByteArray num(int v)
{
    return QByteArray::number(v);
}

QByteArray seed(std::uint64_t v)
{
    // Larger seeds would lose digits as JSON numbers (doubles): write them as strings.
    return v <= kMaxNumberSeed ? QByteArray::number(static_cast<qulonglong>(v))
                               : '"' + QByteArray::number(static_cast<qulonglong>(v)) + '"';
}

QByteArray str(const QString& s)
{
    QByteArray out;
    out.reserve(s.size() + 2);
    out += '"';
    for (const char c : s.toUtf8()) {
        switch (c) {
        case '"': out += "\\\""; break;
        case '\\': out += "\\\\"; break;
        case '\n': out += "\\n"; break;
        case '\r': out += "\\r"; break;
        case '\t': out += "\\t"; break;
        case '\b': out += "\\b"; break;
        case '\f': out += "\\f"; break;
        default:
            if (static_cast<unsigned char>(c) < 0x20) {
                char buf[8];
                std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(c));
                out += buf;
            } else {
                out += c;
            }
        }
    }
    out += '"';
    return out;
}

QByteArray str(std::string_view s)
{
    return str(QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size())));
}

// A listed colour by its name ("red"), as a teacher writes it; any other as "#rrggbb".
QByteArray colour(sim::Rgb c)
{
    const QString name = lessons::nameOfColour(c);
    if (!name.isEmpty())
        return str(name);
    char buf[16];
    std::snprintf(buf, sizeof buf, "\"#%06x\"", static_cast<unsigned>(c & 0xffffff));
    return buf;
}

using Fields = std::vector<std::pair<const char*, QByteArray>>;

/// {"a": 1, "b": 2} on one line.
QByteArray inlineObject(const Fields& fields)
{
    QByteArray out = "{";
    for (std::size_t i = 0; i < fields.size(); ++i) {
        if (i)
            out += ", ";
        out += '"';
        out += fields[i].first;
        out += "\": ";
        out += fields[i].second;
    }
    return out + '}';
}

QByteArray inlineArray(const QList<QByteArray>& items)
{
    return '[' + items.join(", ") + ']';
}

/// An array with one entry per line, indented by `indent` spaces.
QByteArray blockArray(const QList<QByteArray>& items, int indent)
{
    if (items.isEmpty())
        return "[]";
    const QByteArray pad(indent + 2, ' ');
    QByteArray out = "[\n";
    for (qsizetype i = 0; i < items.size(); ++i)
        out += pad + items[i] + (i + 1 < items.size() ? ",\n" : "\n");
    return out + QByteArray(indent, ' ') + ']';
}

/// Strings on one line, or one per line indented by `indent` spaces.
QByteArray strings(const QStringList& list, bool block, int indent = 2)
{
    QList<QByteArray> items;
    for (const QString& s : list)
        items << str(s);
    return block ? blockArray(items, indent) : inlineArray(items);
}

/// A model's fields, with "enabled": false in front when it is off. A model
/// that is off and still has its default values is left out entirely.
void addModel(QList<QByteArray>& models, const char* name, bool enabled, Fields fields, const Fields& defaults)
{
    if (!enabled) {
        if (fields == defaults)
            return;
        fields.insert(fields.begin(), {"enabled", "false"});
    }
    models << '"' + QByteArray(name) + "\": " + inlineObject(fields);
}

/// The value of one row as JSON text.
QByteArray rowValue(const sim::Parameter& p, const sim::WorldSettings& s)
{
    const double v = p.get(s);
    switch (p.type) {
    case sim::ParameterType::Boolean:
        return v != 0.0 ? "true" : "false";
    case sim::ParameterType::Choice:
        return str(p.choices()[static_cast<std::size_t>(v)]);
    case sim::ParameterType::Integer:
        return num(static_cast<int>(v));
    case sim::ParameterType::Number:
        break;
    }
    return num(v);
}

/// {"key.path": value, …} of a claim's or a compare pane's settings, each
/// value written as its row writes it (choices by name).
QByteArray setObject(const std::vector<std::pair<std::string, double>>& entries)
{
    sim::WorldSettings values;
    QByteArray set = "{";
    for (const auto& [key, value] : entries) {
        const sim::Parameter* p = sim::findParameter(key);
        if (!p && !sim::isSceneKey(key))
            continue;
        if (set.size() > 1)
            set += ", ";
        if (!p) { // a ball's field or the spawn count: a plain number
            set += str(key) + ": " + num(value);
            continue;
        }
        p->set(values, value);
        set += str(key) + ": " + rowValue(*p, values);
    }
    return set + '}';
}

/// One claim on one line, with only the keys that differ from a claim's
/// defaults (apart from says, measure, at and the test, which are always there).
QByteArray claimLine(const sim::Claim& c)
{
    const sim::Claim d;
    Fields f{{"says", str(c.text)}, {"measure", str(c.measure)}};
    if (c.ball != d.ball)
        f.push_back({"ball", num(c.ball)});
    if (c.other != d.other)
        f.push_back({"other", num(c.other)});
    f.push_back({"at", num(c.at)});
    if (c.occurrence != d.occurrence)
        f.push_back({"n", num(c.occurrence)});
    if (c.axis != d.axis)
        f.push_back({"axis", c.axis == 'x' ? QByteArray("\"x\"") : QByteArray("\"y\"")});
    if (c.distance != d.distance)
        f.push_back({"distance", num(c.distance)});
    switch (c.test) {
    case sim::ClaimTest::Near:
        f.push_back({"near", num(c.value)});
        f.push_back(c.relative ? std::pair{"within_percent", num(std::min(100.0, 100.0 * c.tolerance))} : std::pair{"within", num(c.tolerance)});
        break;
    case sim::ClaimTest::Below:
        f.push_back({"below", num(c.value)});
        break;
    case sim::ClaimTest::Above:
        f.push_back({"above", num(c.value)});
        break;
    }
    if (!c.set.empty())
        f.push_back({"set", setObject(c.set)});
    return inlineObject(f);
}

/// A question on one line: the question, its claim and its choices.
QByteArray predictLine(const Prediction& q)
{
    Fields f{{"ask", str(q.ask)}, {"claim", num(q.claim)}};
    if (!q.choices.isEmpty()) {
        QList<QByteArray> choices;
        for (qsizetype k = 0; k < q.choices.size() && static_cast<std::size_t>(k) < q.values.size(); ++k)
            choices << inlineObject({{"label", str(q.choices[k])}, {"value", num(q.values[static_cast<std::size_t>(k)])}});
        f.push_back({"choices", '[' + choices.join(", ") + ']'});
    }
    return inlineObject(f);
}

/// A compare pane on one line: its label and its settings.
QByteArray compareLine(const ComparePane& pane)
{
    return inlineObject({{"label", str(pane.label)}, {"set", setObject(pane.set)}});
}

/// The rows of a section as fields, leaving out `enabled` (a model's switch
/// is written by addModel).
Fields sectionFields(std::string_view section, const sim::WorldSettings& s)
{
    Fields out;
    for (const sim::Parameter* p : sim::sectionRows(section))
        if (sim::rowName(*p) != "enabled")
            out.push_back({p->key.data() + section.size() + 1, rowValue(*p, s)});
    return out;
}

/// The custom force's formulas and constants ({"k": 4}, with their slider
/// ranges as "ranges": {"k": [0, 20]}).
Fields customFields(const sim::CustomForceSettings& c)
{
    Fields f{{"fx", str(c.fx)}, {"fy", str(c.fy)}};
    if (!c.potential.empty())
        f.push_back({"potential", str(c.potential)});
    if (!c.constants.empty()) {
        Fields values, ranges;
        for (const sim::CustomConstant& k : c.constants) {
            values.push_back({k.name.c_str(), num(k.value)});
            ranges.push_back({k.name.c_str(), inlineArray({num(k.min), num(k.max)})});
        }
        f.push_back({"constants", inlineObject(values)});
        f.push_back({"ranges", inlineObject(ranges)});
    }
    return f;
}

QByteArray modelsBlock(const sim::WorldSettings& s)
{
    const sim::WorldSettings d; // defaults
    QList<QByteArray> m;
    // The models are the sections of the parameter table under "models.".
    std::vector<std::string_view> sections;
    for (const sim::Parameter& p : sim::parameters())
        if (p.key.substr(0, 7) == "models.") {
            const std::string_view section = p.key.substr(0, p.key.rfind('.'));
            if (sections.empty() || sections.back() != section)
                sections.push_back(section);
        }
    for (const std::string_view section : sections) {
        const std::string name(section.substr(7));
        Fields fields = sectionFields(section, s);
        Fields defaults = sectionFields(section, d);
        if (name == "custom") {
            const Fields more = customFields(s.custom), moreDefaults = customFields(d.custom);
            fields.insert(fields.end(), more.begin(), more.end());
            defaults.insert(defaults.end(), moreDefaults.begin(), moreDefaults.end());
        }
        if (const sim::Parameter* on = sim::findParameter(std::string(section) + ".enabled")) {
            addModel(m, name.c_str(), on->get(s) != 0.0, fields, defaults);
        } else if (fields != sectionFields(section, d)) {
            // No switch (wind, collisions): a mode such as "off" or "none"
            // switches it off; written when anything differs from the defaults.
            m << '"' + QByteArray::fromStdString(name) + "\": " + inlineObject(fields);
        }
    }
    if (m.isEmpty())
        return "{}";
    QByteArray out = "{\n";
    for (qsizetype i = 0; i < m.size(); ++i)
        out += "    " + m[i] + (i + 1 < m.size() ? ",\n" : "\n");
    return out + "  }";
}

QByteArray ballLine(const sim::Ball& b)
{
    Fields f{{"x", num(b.position.x())},
             {"y", num(b.position.y())},
             {"vx", num(b.velocity.x())},
             {"vy", num(b.velocity.y())},
             {"r", num(b.radius)}};
    if (b.mass != 0.0) // 0 means "density 1 sphere": leave the key out
        f.push_back({"mass", num(b.mass)});
    if (b.charge != 1.0) // 1 is the default
        f.push_back({"q", num(b.charge)});
    if (b.pinned) // written only when set: a file without it means a free ball
        f.push_back({"pinned", "true"});
    if (sim::hasOwnRestitution(b.restitution)) // absent: the world's restitution
        f.push_back({"restitution", num(b.restitution)});
    f.push_back({"color", colour(b.color)});
    return inlineObject(f);
}

/// One language's words under "languages", with the fields the lesson has.
QByteArray wordsBlock(const Lesson& lesson, const LessonWords& w)
{
    QList<QByteArray> fields;
    fields << "\"title\": " + str(w.title);
    if (!lesson.text.isEmpty())
        fields << "\"text\": " + str(w.text);
    if (!lesson.challenges.isEmpty())
        fields << "\"challenges\": " + strings(w.challenges, true, 6);
    if (!lesson.predict.empty()) {
        QList<QByteArray> questions;
        for (qsizetype k = 0; k < w.predictAsks.size(); ++k) {
            Fields f{{"ask", str(w.predictAsks[k])}};
            if (std::size_t(k) < w.predictChoices.size() && !w.predictChoices[std::size_t(k)].isEmpty())
                f.push_back({"choices", strings(w.predictChoices[std::size_t(k)], false)});
            questions << inlineObject(f);
        }
        fields << "\"predict\": " + blockArray(questions, 6);
    }
    QList<QByteArray> teacher;
    if (!lesson.teacher.goal.isEmpty())
        teacher << "\"goal\": " + str(w.goal);
    if (!lesson.teacher.misconceptions.isEmpty())
        teacher << "\"misconceptions\": " + strings(w.misconceptions, true, 8);
    if (!lesson.teacher.answers.isEmpty())
        teacher << "\"answers\": " + strings(w.answers, true, 8);
    if (!teacher.isEmpty())
        fields << "\"teacher\": {\n        " + teacher.join(",\n        ") + "\n      }";
    if (!lesson.claims.empty())
        fields << "\"claims\": " + strings(w.claims, true, 6);
    if (!lesson.notMeasured.empty()) {
        QList<QByteArray> entries;
        for (qsizetype k = 0; k < w.notMeasuredSays.size(); ++k) {
            Fields f{{"says", str(w.notMeasuredSays[k])}};
            if (!w.notMeasuredWhy.value(k).isEmpty())
                f.push_back({"why", str(w.notMeasuredWhy[k])});
            entries << inlineObject(f);
        }
        fields << "\"not_measured\": " + blockArray(entries, 6);
    }
    if (!lesson.compare.empty())
        fields << "\"compare\": " + strings(w.compare, false);
    return "{\n      " + fields.join(",\n      ") + "\n    }";
}

} // namespace

QByteArray saveLesson(const Lesson& shown)
{
    // The file's own words go back into its own fields, whichever language
    // was on the screen.
    const Lesson lesson = lessons::shownIn(shown, shown.fileLanguage);
    const sim::WorldSettings& s = lesson.scene.settings;
    const sim::SpawnSettings& spawn = lesson.scene.spawn;

    QList<QByteArray> walls;
    if (s.walls.left)
        walls << "\"left\"";
    if (s.walls.right)
        walls << "\"right\"";
    if (s.walls.top)
        walls << "\"top\"";
    if (s.walls.bottom)
        walls << "\"bottom\"";

    QList<QByteArray> balls;
    balls.reserve(static_cast<qsizetype>(lesson.scene.balls.size()));
    for (const sim::Ball& b : lesson.scene.balls)
        balls << ballLine(b);

    Fields spawnFields{{"count", num(spawn.count)},
                       {"radius", inlineArray({num(spawn.minRadius), num(spawn.maxRadius)})},
                       {"speed", inlineArray({num(spawn.minSpeed), num(spawn.maxSpeed)})},
                       {"seed", seed(spawn.seed)},
                       {"horizontal", spawn.horizontal ? "true" : "false"},
                       {"fully_inside", spawn.fullyInside ? "true" : "false"},
                       {"per_step", num(spawn.perStep)},
                       {"max_count", num(spawn.maxCount)}};
    if (!spawn.palette.empty()) {
        QList<QByteArray> colours;
        for (const sim::Rgb c : spawn.palette)
            colours << colour(c);
        spawnFields.push_back({"palette", inlineArray(colours)});
    }

    // The walls are a list of names after the box size; the seed (not a row
    // of doubles) comes before per_frame.
    Fields world = sectionFields("world", s);
    world.insert(world.begin() + 2, {"walls", inlineArray(walls)});
    Fields time = sectionFields("time", s);
    const auto perFrame = std::find_if(time.begin(), time.end(), [](const auto& f) { return std::string_view(f.first) == "per_frame"; });
    time.insert(perFrame, {"seed", seed(s.time.seed)});

    Fields top{
        {"format", num(lessons::kFormat)},
        {"id", str(lesson.id)},
        {"title", str(lesson.title)},
        {"stage", num(lesson.stage)},
        {"text", str(lesson.text)},
        {"challenges", strings(lesson.challenges, true)},
        {"world", inlineObject(world)},
        {"time", inlineObject(time)},
        {"models", modelsBlock(s)},
        {"balls", blockArray(balls, 2)},
        {"spawn", inlineObject(spawnFields)},
        {"controls", strings(lesson.controls, false)},
        {"overlays", strings(lesson.overlays, false)},
    };
    if (!lesson.tools.isEmpty()) // only when listed, so a lesson without tools saves as before
        top.push_back({"tools", strings(lesson.tools, false)});
    if (lesson.units) // only in SI, so a pixel lesson saves as before
        top.push_back({"units", inlineObject({{"px_per_metre", num(lesson.units->pxPerMetre)},
                                              {"kg_per_mass", num(lesson.units->kgPerMass)}})});
    if (!lesson.teacher.empty()) {
        // Only what the notes hold: an empty list or goal is left out.
        const TeacherNotes& t = lesson.teacher;
        QList<QByteArray> fields;
        if (!t.goal.isEmpty())
            fields << "\"goal\": " + str(t.goal);
        if (t.minutes > 0)
            fields << "\"minutes\": " + num(t.minutes);
        if (!t.misconceptions.isEmpty())
            fields << "\"misconceptions\": " + strings(t.misconceptions, true, 4);
        if (!t.answers.isEmpty())
            fields << "\"answers\": " + strings(t.answers, true, 4);
        top.push_back({"teacher", "{\n    " + fields.join(",\n    ") + "\n  }"});
    }
    if (!lesson.claims.empty()) {
        QList<QByteArray> claims;
        for (const sim::Claim& c : lesson.claims)
            claims << claimLine(c);
        top.push_back({"claims", blockArray(claims, 2)});
    }
    if (!lesson.notMeasured.empty()) {
        QList<QByteArray> entries;
        for (const NotMeasured& n : lesson.notMeasured) {
            Fields f{{"says", str(n.says)}, {"because", str(QString::fromLatin1(kNotMeasuredReasons[int(n.because)]))}};
            if (!n.why.isEmpty())
                f.push_back({"why", str(n.why)});
            entries << inlineObject(f);
        }
        top.push_back({"not_measured", blockArray(entries, 2)});
    }

    if (!lesson.predict.empty()) {
        QList<QByteArray> questions;
        for (const Prediction& q : lesson.predict)
            questions << predictLine(q);
        top.push_back({"predict", blockArray(questions, 2)});
    }
    if (!lesson.studentCode.isEmpty()) { // only with a student's code, so a lesson saves as before
        QList<QByteArray> files;
        for (auto it = lesson.studentCode.cbegin(); it != lesson.studentCode.cend(); ++it)
            files << str(it.key()) + ": " + str(it.value());
        top.push_back({"student_code", "{\n    " + files.join(",\n    ") + "\n  }"});
    }
    if (!lesson.compare.empty()) {
        QList<QByteArray> panes;
        for (const ComparePane& pane : lesson.compare)
            panes << compareLine(pane);
        top.push_back({"compare", blockArray(panes, 2)});
    }
    if (lesson.fileLanguage != QLatin1String("en")) // only when not English, so a lesson saves as before
        top.insert(top.begin() + 2, {"language", str(lesson.fileLanguage)});
    if (!lesson.languages.isEmpty()) {
        QList<QByteArray> languages;
        for (auto it = lesson.languages.cbegin(); it != lesson.languages.cend(); ++it)
            languages << str(it.key()) + ": " + wordsBlock(lesson, *it);
        top.push_back({"languages", "{\n    " + languages.join(",\n    ") + "\n  }"});
    }

    QByteArray out = "{\n";
    for (std::size_t i = 0; i < top.size(); ++i) {
        out += "  \"";
        out += top[i].first;
        out += "\": ";
        out += top[i].second;
        out += i + 1 < top.size() ? ",\n" : "\n";
    }
    return out + "}\n";
}

} // namespace forcelab
