// parseLesson (lesson_parser.h): the top level of a lesson file (format,
// id, title, text, lists of names, teacher notes) and the order in which the
// sections are read (lesson_parse_sections.h), then the checks across them:
// the prose's markup and the work of the claims.

#include "lesson_parser.h"

#include "lesson_controls.h"
#include "lesson_languages.h"
#include "lesson_tools.h"
#include "lesson_limits.h"
#include "lesson_markup.h"
#include "lesson_parse_sections.h"

#include <QRegularExpression>

#include <functional>

namespace forcelab::lessons {

using namespace parsing;

namespace {

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

/// Every text a reader sees is in the markup subset and within its length
/// (lesson_markup.h): a problem names the field and the character. The
/// lesson's own words and each translation's are checked alike.
void checkProse(Reader& r, const LessonWords& w)
{
    auto check = [&r](const QString& path, const QString& text, qsizetype maxChars) {
        if (const auto problem = checkMarkup(text, maxChars))
            r.fail(path, QStringLiteral("character %1: %2").arg(problem->at + 1).arg(problem->message));
    };
    auto checkList = [&](const QString& path, const QStringList& texts, const char* key = nullptr) {
        for (qsizetype i = 0; i < texts.size(); ++i)
            check(key ? join(join(path, i), key) : join(path, i), texts[i], kMaxProseChars);
    };
    check(QStringLiteral("title"), w.title, kMaxProseChars);
    check(QStringLiteral("text"), w.text, kMaxTextChars);
    checkList(QStringLiteral("challenges"), w.challenges);
    check(QStringLiteral("teacher.goal"), w.goal, kMaxProseChars);
    checkList(QStringLiteral("teacher.misconceptions"), w.misconceptions);
    checkList(QStringLiteral("teacher.answers"), w.answers);
    for (qsizetype k = 0; k < w.predictAsks.size(); ++k) {
        const QString path = join(QStringLiteral("predict"), k);
        check(join(path, "ask"), w.predictAsks[k], kMaxProseChars);
        if (std::size_t(k) < w.predictChoices.size())
            checkList(join(path, "choices"), w.predictChoices[std::size_t(k)], "label");
    }
    checkList(QStringLiteral("compare"), w.compare, "label");
    checkList(QStringLiteral("claims"), w.claims, "says");
    for (qsizetype k = 0; k < w.notMeasuredSays.size(); ++k) {
        const QString path = join(QStringLiteral("not_measured"), k);
        check(join(path, "says"), w.notMeasuredSays[k], kMaxProseChars);
        check(join(path, "why"), w.notMeasuredWhy.value(k), kMaxProseChars);
    }
}

/// The text, every challenge and every answer name only tools the lesson lists, so the
/// stage view can offer each one (lesson_tools.h).
void checkToolsNamed(Reader& r, const Lesson& lesson)
{
    auto check = [&](const QString& path, const QString& text) {
        for (const QString& name : undeclaredToolsIn(markupToPlainText(text), lesson))
            r.fail(path, QStringLiteral("names the %1 panel; list %2 in \"tools\" so the stage view offers it")
                             .arg(findTool(name)->title, quoted(name)));
    };
    check(QStringLiteral("text"), lesson.text);
    for (qsizetype i = 0; i < lesson.challenges.size(); ++i)
        check(join(QStringLiteral("challenges"), i), lesson.challenges[i]);
    // The answers say how the class does a challenge, on the stage too.
    for (qsizetype i = 0; i < lesson.teacher.answers.size(); ++i)
        check(join(QStringLiteral("teacher.answers"), i), lesson.teacher.answers[i]);
}

/// A challenge that asks for a change ("Turn the bottom wall off") names a
/// control the lesson lists, so the stage's sliders offer it.
void checkControlsNamed(Reader& r, const Lesson& lesson)
{
    for (qsizetype i = 0; i < lesson.challenges.size(); ++i) {
        const QString plain = markupToPlainText(lesson.challenges[i]);
        for (const ControlPhrase& phrase : undeclaredControlsIn(plain, lesson.controls)) {
            QStringList names;
            for (const QString& name : phrase.anyOf)
                names << quoted(name);
            r.fail(join(QStringLiteral("challenges"), i),
                   QStringLiteral("%1 asks for a control the lesson does not list; list %2 in \"controls\" so the "
                                  "stage offers it")
                       .arg(quoted(phrase.words), names.join(QStringLiteral(" or "))));
        }
    }
}

/// "student_code": {"walls.js": "…"}: file names of the course's kind (lower
/// case, digits, '_', ending in .js) and their text. Only the sizes are
/// checked here; the names are matched to the course's files when the code runs.
void parseStudentCode(Reader& r, const QJsonObject& o, QMap<QString, QString>& out)
{
    static const QRegularExpression namePattern(QStringLiteral("^[a-z0-9_]{1,60}\\.js$"));
    if (o.size() > kMaxStudentFiles) {
        r.fail(QStringLiteral("student_code"),
               QStringLiteral("%1 files is more than the limit of %2").arg(o.size()).arg(kMaxStudentFiles));
        return;
    }
    QMap<QString, QString> files;
    bool ok = true;
    for (auto it = o.begin(); it != o.end(); ++it) {
        const QString path = QStringLiteral("student_code.%1").arg(it.key());
        if (!namePattern.match(it.key()).hasMatch()) {
            r.fail(path, QStringLiteral("%1 is not a file name of the course's code (such as \"walls.js\")").arg(quoted(it.key())));
            ok = false;
        } else if (!it.value().isString()) {
            r.fail(path, QStringLiteral("expected the file's text as a string, got %1").arg(describe(it.value())));
            ok = false;
        } else if (it.value().toString().size() > kMaxStudentFileChars) {
            r.fail(path, QStringLiteral("%1 characters is more than the limit of %2")
                             .arg(it.value().toString().size()).arg(kMaxStudentFileChars));
            ok = false;
        } else {
            files.insert(it.key(), it.value().toString());
        }
    }
    if (ok)
        out = files;
}

/// One translation under "languages": the lesson's fields in another
/// language (lesson_languages.h). Its shape is checked against the lesson's
/// own words once they are all read.
LessonWords parseWords(Reader& r, const QJsonObject& o, const QString& p)
{
    LessonWords w;
    r.checkKeys(o, p, {"title", "text", "challenges", "predict", "teacher", "claims", "not_measured", "compare"});
    r.string(o, p, "title", w.title);
    r.string(o, p, "text", w.text);
    r.stringList(o, p, "challenges", w.challenges);
    r.stringList(o, p, "claims", w.claims);
    r.stringList(o, p, "compare", w.compare);
    if (const auto t = r.object(o, p, "teacher")) {
        const QString tp = join(p, "teacher");
        r.checkKeys(*t, tp, {"goal", "misconceptions", "answers"});
        r.string(*t, tp, "goal", w.goal);
        r.stringList(*t, tp, "misconceptions", w.misconceptions);
        r.stringList(*t, tp, "answers", w.answers);
    }
    auto objects = [&](const QString& key, const std::function<void(const QJsonObject&, const QString&)>& one) {
        const auto a = r.array(o, p, key, QStringLiteral("an array of objects"));
        if (!a)
            return;
        if (a->size() > kMaxListEntries) {
            r.fail(join(p, key), QStringLiteral("%1 entries is more than the limit of %2").arg(a->size()).arg(kMaxListEntries));
            return;
        }
        for (qsizetype i = 0; i < a->size(); ++i) {
            const QString ip = join(join(p, key), i);
            if (!a->at(i).isObject())
                r.fail(ip, QStringLiteral("expected an object, got %1").arg(describe(a->at(i))));
            else
                one(a->at(i).toObject(), ip);
        }
    };
    objects(QStringLiteral("predict"), [&](const QJsonObject& q, const QString& qp) {
        r.checkKeys(q, qp, {"ask", "choices"});
        QString ask;
        QStringList choices;
        r.string(q, qp, "ask", ask);
        r.stringList(q, qp, "choices", choices);
        w.predictAsks << ask;
        w.predictChoices.push_back(choices);
    });
    objects(QStringLiteral("not_measured"), [&](const QJsonObject& n, const QString& np) {
        r.checkKeys(n, np, {"says", "why"});
        QString says, why;
        r.string(n, np, "says", says);
        r.string(n, np, "why", why);
        w.notMeasuredSays << says;
        w.notMeasuredWhy << why;
    });
    return w;
}

/// "language": the language of the file's own words; "languages": the
/// same words in others, by code.
void parseLanguages(Reader& r, const QJsonObject& root, Lesson& lesson)
{
    QString own;
    if (r.string(root, QString(), "language", own)) {
        if (isLanguageCode(own)) {
            lesson.language = lesson.fileLanguage = own;
        } else {
            r.fail(QStringLiteral("language"),
                   QStringLiteral("%1 is not a language code such as \"en\" or \"de\"").arg(quoted(own)));
        }
    }
    const auto o = r.object(root, QString(), "languages");
    if (!o)
        return;
    if (o->size() > kMaxLessonLanguages) {
        r.fail(QStringLiteral("languages"),
               QStringLiteral("%1 languages is more than the limit of %2").arg(o->size()).arg(kMaxLessonLanguages));
        return;
    }
    for (auto it = o->begin(); it != o->end(); ++it) {
        const QString path = join(QStringLiteral("languages"), it.key());
        if (!isLanguageCode(it.key())) {
            r.fail(path, QStringLiteral("%1 is not a language code such as \"de\" or \"es\"").arg(quoted(it.key())));
        } else if (it.key() == lesson.fileLanguage) {
            r.fail(path, QStringLiteral("is the file's own language; its words are the lesson's own fields"));
        } else if (!it.value().isObject()) {
            r.fail(path, QStringLiteral("expected the lesson's words as an object, got %1").arg(describe(it.value())));
        } else {
            lesson.languages.insert(it.key(), parseWords(r, it.value().toObject(), path));
        }
    }
}

/// Every translation has the lesson's fields and counts (so its claims and
/// questions are the lesson's, in order), its markup is the lesson's subset,
/// and its numbers are the lesson's.
void checkLanguages(Reader& r, const Lesson& lesson)
{
    auto failLine = [&r](const QString& line) {
        const qsizetype colon = line.indexOf(QStringLiteral(": "));
        r.fail(line.left(colon), line.mid(colon + 2));
    };
    const LessonWords own = wordsOf(lesson);
    for (auto it = lesson.languages.cbegin(); it != lesson.languages.cend(); ++it) {
        const QString path = join(QStringLiteral("languages"), it.key());
        const QStringList shape = shapeProblems(lesson, *it, path);
        for (const QString& line : shape)
            failLine(line);
        if (!shape.isEmpty())
            continue;
        ParseResult prose;
        Reader proseReader(prose);
        checkProse(proseReader, *it);
        for (const KeyProblem& k : prose.problems)
            r.fail(join(path, k.keyPath), k.problem);
        for (const QString& line : numberProblems(own, lesson.language, *it, it.key()))
            failLine(line);
    }
}

} // namespace

const QStringList& overlayNames()
{
    static const QStringList names{"grid",    "velocity", "acceleration", "readout",   "colliding", "markers",
                                   "vanes",   "trails",   "impact",       "broadphase", "histogram", "totals",
                                   "forces",  "sources",  "centre-of-mass", "momenta", "apexes"};
    return names;
}



ParseResult parseLesson(const QJsonObject& root)
{
    ParseResult result;
    Reader r(result);
    Lesson& lesson = result.lesson;
    const QString top;
    r.checkKeys(root, top,
                {"format", "id", "title", "stage", "text", "challenges", "world", "time", "models", "balls", "spawn",
                 "controls", "overlays", "tools", "claims", "not_measured", "teacher", "compare", "predict", "units", "student_code",
                 "language", "languages"});

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
    nameList(r, root, "tools", toolNames(), lesson.tools);

    if (const auto o = r.object(root, top, "units"))
        parseUnits(r, *o, lesson.units);
    if (const auto o = r.object(root, top, "student_code"))
        parseStudentCode(r, *o, lesson.studentCode);

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
    checkProse(r, wordsOf(lesson));
    checkToolsNamed(r, lesson);
    checkControlsNamed(r, lesson);
    checkClaimWork(r, lesson);
    parseLanguages(r, root, lesson);
    checkLanguages(r, lesson);
    return result;
}

} // namespace forcelab::lessons
