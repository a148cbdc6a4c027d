// The lesson loader: built-in lessons load, every key lands in its struct
// member, each class of bad input gives its one-line message, overrides act
// like edits of the file, and save -> load gives back the same bits.

#include "sim_test_util.h"

#include "lessons/lesson_loader.h"
#include "lessons/lesson_tools.h"
#include "lessons/lesson_markup.h"
#include "lessons/sentence_check.h"
#include "sim/world/names.h"
#include "sim/world/world.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <bit>
#include <cmath>
#include <cstdint>

using namespace forcelab;

namespace {

const QString kSrc = QStringLiteral("t.json");

LoadResult loadText(const QByteArray& json, const QList<Override>& overrides = {})
{
    return LessonLoader::loadBytes(json, kSrc, overrides);
}

/// A minimal valid lesson with `extra` spliced into the top-level object.
QByteArray minimal(const QByteArray& extra = {})
{
    return "{\"format\": 1, \"id\": \"t\"" + (extra.isEmpty() ? QByteArray() : ", " + extra) + "}";
}

std::uint64_t bits(double v)
{
    return std::bit_cast<std::uint64_t>(v);
}

#define COMPARE_BITS(a, b)                                                                                          \
    do {                                                                                                            \
        if (bits(a) != bits(b))                                                                                     \
            QFAIL(qPrintable(QStringLiteral("%1: %2 != %3").arg(#a).arg((a), 0, 'g', 17).arg((b), 0, 'g', 17)));    \
    } while (false)

/// An enum by its lesson-file name, so QCOMPARE can print it.
template <typename E>
QString nameOf(E e)
{
    const std::string_view s = sim::toString(e);
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

#define COMPARE_ENUM(a, b) QCOMPARE(nameOf(a), nameOf(b))

/// Every field of two lessons equal, doubles bit for bit (the source aside).
void compareLessons(const Lesson& a, const Lesson& b)
{
    QCOMPARE(a.format, b.format);
    QCOMPARE(a.id, b.id);
    QCOMPARE(a.title, b.title);
    QCOMPARE(a.stage, b.stage);
    QCOMPARE(a.text, b.text);
    QCOMPARE(a.challenges, b.challenges);
    QCOMPARE(a.controls, b.controls);
    QCOMPARE(a.overlays, b.overlays);
    QCOMPARE(a.tools, b.tools);
    QVERIFY(a.teacher == b.teacher);
    QCOMPARE(a.claims.size(), b.claims.size());
    for (std::size_t i = 0; i < a.claims.size(); ++i)
        QVERIFY2(a.claims[i] == b.claims[i], a.claims[i].text.c_str());
    QVERIFY(a.notMeasured == b.notMeasured);
    QCOMPARE(a.fileLanguage, b.fileLanguage);
    QCOMPARE(a.languages.keys(), b.languages.keys());
    QVERIFY(a.languages == b.languages);

    const sim::WorldSettings& s = a.scene.settings;
    const sim::WorldSettings& t = b.scene.settings;
    COMPARE_BITS(s.box.width, t.box.width);
    COMPARE_BITS(s.box.height, t.box.height);
    QCOMPARE(s.walls.left, t.walls.left);
    QCOMPARE(s.walls.right, t.walls.right);
    QCOMPARE(s.walls.top, t.walls.top);
    QCOMPARE(s.walls.bottom, t.walls.bottom);
    COMPARE_ENUM(s.walls.model, t.walls.model);
    COMPARE_BITS(s.walls.restitution, t.walls.restitution);
    QCOMPARE(s.walls.middle, t.walls.middle);
    QCOMPARE(s.walls.centreOnly, t.walls.centreOnly);
    COMPARE_ENUM(s.time.integrator, t.time.integrator);
    COMPARE_BITS(s.time.dt, t.time.dt);
    QCOMPARE(s.time.substeps, t.time.substeps);
    COMPARE_BITS(s.time.tolerance, t.time.tolerance);
    QCOMPARE(s.time.seed, t.time.seed);
    QCOMPARE(s.time.perFrame, t.time.perFrame);
    QCOMPARE(s.gravity.enabled, t.gravity.enabled);
    COMPARE_BITS(s.gravity.g.x(), t.gravity.g.x());
    COMPARE_BITS(s.gravity.g.y(), t.gravity.g.y());
    QCOMPARE(s.drag.enabled, t.drag.enabled);
    COMPARE_ENUM(s.drag.law, t.drag.law);
    COMPARE_BITS(s.drag.k, t.drag.k);
    COMPARE_ENUM(s.drag.scale, t.drag.scale);
    COMPARE_ENUM(s.wind.mode, t.wind.mode);
    COMPARE_BITS(s.wind.strength, t.wind.strength);
    COMPARE_ENUM(s.wind.scale, t.wind.scale);
    COMPARE_BITS(s.wind.smoothedStep, t.wind.smoothedStep);
    COMPARE_BITS(s.wind.noiseFrequency, t.wind.noiseFrequency);
    COMPARE_ENUM(s.wind.compare, t.wind.compare);
    QCOMPARE(s.randomAccel.enabled, t.randomAccel.enabled);
    QCOMPARE(s.randomAccel.fixed, t.randomAccel.fixed);
    COMPARE_BITS(s.randomAccel.strength, t.randomAccel.strength);
    QCOMPARE(s.point.enabled, t.point.enabled);
    COMPARE_ENUM(s.point.kind, t.point.kind);
    COMPARE_BITS(s.point.position.x(), t.point.position.x());
    COMPARE_BITS(s.point.position.y(), t.point.position.y());
    COMPARE_BITS(s.point.strength, t.point.strength);
    COMPARE_BITS(s.point.maxAccel, t.point.maxAccel);
    COMPARE_ENUM(s.point.scale, t.point.scale);
    QCOMPARE(s.spring.enabled, t.spring.enabled);
    COMPARE_BITS(s.spring.anchor.x(), t.spring.anchor.x());
    COMPARE_BITS(s.spring.anchor.y(), t.spring.anchor.y());
    COMPARE_BITS(s.spring.k, t.spring.k);
    QCOMPARE(s.mutualGravity.enabled, t.mutualGravity.enabled);
    COMPARE_BITS(s.mutualGravity.G, t.mutualGravity.G);
    COMPARE_BITS(s.mutualGravity.softening, t.mutualGravity.softening);
    QCOMPARE(s.homing.enabled, t.homing.enabled);
    COMPARE_BITS(s.homing.strength, t.homing.strength);
    QCOMPARE(s.pointer.enabled, t.pointer.enabled);
    COMPARE_BITS(s.pointer.strength, t.pointer.strength);
    COMPARE_BITS(s.pointer.maxAccel, t.pointer.maxAccel);
    QCOMPARE(s.speedLimit.enabled, t.speedLimit.enabled);
    COMPARE_BITS(s.speedLimit.max, t.speedLimit.max);
    COMPARE_ENUM(s.collisions.detection, t.collisions.detection);
    COMPARE_ENUM(s.collisions.response, t.collisions.response);
    COMPARE_BITS(s.collisions.restitution, t.collisions.restitution);
    QCOMPARE(s.collisions.continuous, t.collisions.continuous);
    QCOMPARE(s.collisions.resting, t.collisions.resting);

    QCOMPARE(a.scene.balls.size(), b.scene.balls.size());
    for (std::size_t i = 0; i < a.scene.balls.size(); ++i) {
        const sim::Ball& p = a.scene.balls[i];
        const sim::Ball& q = b.scene.balls[i];
        COMPARE_BITS(p.position.x(), q.position.x());
        COMPARE_BITS(p.position.y(), q.position.y());
        COMPARE_BITS(p.velocity.x(), q.velocity.x());
        COMPARE_BITS(p.velocity.y(), q.velocity.y());
        COMPARE_BITS(p.radius, q.radius);
        COMPARE_BITS(p.mass, q.mass);
        COMPARE_BITS(p.charge, q.charge);
        QCOMPARE(p.color, q.color);
        QCOMPARE(p.pinned, q.pinned);
        COMPARE_BITS(p.restitution, q.restitution);
    }
    const sim::SpawnSettings& u = a.scene.spawn;
    const sim::SpawnSettings& v = b.scene.spawn;
    QCOMPARE(u.count, v.count);
    COMPARE_BITS(u.minRadius, v.minRadius);
    COMPARE_BITS(u.maxRadius, v.maxRadius);
    COMPARE_BITS(u.minSpeed, v.minSpeed);
    COMPARE_BITS(u.maxSpeed, v.maxSpeed);
    QCOMPARE(u.seed, v.seed);
    QCOMPARE(u.palette, v.palette);
    QCOMPARE(u.horizontal, v.horizontal);
    QCOMPARE(u.fullyInside, v.fullyInside);
    COMPARE_BITS(u.perStep, v.perStep);
    QCOMPARE(u.maxCount, v.maxCount);
}

QString firstError(const LoadResult& r)
{
    return r.errors().isEmpty() ? QStringLiteral("<no error>") : r.errors().first();
}

} // namespace

class TestLessonLoader : public QObject {
    Q_OBJECT

private slots:
    void claimsAreReadCheckedAndWritten();
    void teacherNotesAreReadAndWritten();
    void longKeysAreCutInMessages();
    void claimSetNamesBallsAndRandomBalls();
    void notMeasuredIsReadAndWritten();
    void sentencesWithNumbersNeedAClaimOrAReason_data();
    void sentencesWithNumbersNeedAClaimOrAReason();
    void numbersAndComparisonsAreFound_data();
    void numbersAndComparisonsAreFound();
    void builtInFilesAreCompiledIn();
    void everyBuiltInLessonLoads();
    void builtInByIdAndStem();
    void builtInLessonsRun();
    void eachKeyLandsInItsMember();
    void absentModelsAreOff();
    void presentModelWithEnabledFalseIsOff();
    void toolsAreListedAndNamedOnlyWhenListed();
    void challengesAskOnlyForListedControls();
    void badInput_data();
    void badInput();
    void lessonTextIsASafeSubset_data();
    void lessonTextIsASafeSubset();
    void markupKeepsOnlyTheSubset();
    void scenesThatCannotBeAreRefused_data();
    void scenesThatCannotBeAreRefused();
    void everyProblemIsReported();
    void tooLargeFile();
    void tooManyBalls();
    void semanticCheckFromTheCore();
    void overrides();
    void badOverrides_data();
    void badOverrides();
    void parseOverride();
    void saveLoadRoundTripIsBitIdentical();
    void builtInLessonsRoundTrip();
    void everyParameterRoundTrips();
};

// A lesson's claims: every key read into its member, a wrong one named with
// its key path, and the same claims back after save and load.
void TestLessonLoader::claimsAreReadCheckedAndWritten()
{
    const LoadResult r = loadText(minimal(R"("balls": [{"x": 100, "y": 90}, {"x": 300, "y": 90}], "claims": [
        {"says": "After one bounce it rises to 192 px.", "measure": "apex", "ball": 1, "n": 2, "at": 10, "near": 192, "within": 1},
        {"says": "The period is 3.14 s.", "measure": "period", "axis": "x", "at": 60, "near": 3.14, "within_percent": 1},
        {"says": "Without resting contacts the top falls below 200 px.", "measure": "top_height", "at": 1, "below": 200,
         "set": {"models.collisions.resting": false, "world.wall_model": "exact", "time.dt": 0.001}},
        {"says": "Many balls end at a wall.", "measure": "near_wall", "distance": 5, "other": 0, "at": 5, "above": 30}])"));
    QVERIFY2(r.ok(), qPrintable(r.errors().join(" | ")));
    const std::vector<sim::Claim>& c = r.lesson->claims;
    QCOMPARE(c.size(), std::size_t{4});
    QCOMPARE(c[0].text, std::string("After one bounce it rises to 192 px."));
    QCOMPARE(c[0].measure, std::string("apex"));
    QCOMPARE(c[0].ball, 1);
    QCOMPARE(c[0].occurrence, 2);
    QCOMPARE(c[0].at, 10.0);
    QVERIFY(c[0].test == sim::ClaimTest::Near && c[0].value == 192.0 && c[0].tolerance == 1.0 && !c[0].relative);
    QVERIFY(c[1].axis == 'x' && c[1].relative && c[1].tolerance == 0.01);
    QVERIFY(c[2].test == sim::ClaimTest::Below && c[2].value == 200.0);
    QCOMPARE(c[2].set.size(), std::size_t{3});
    QCOMPARE(c[2].set[0], (std::pair<std::string, double>{"models.collisions.resting", 0.0}));
    QCOMPARE(c[2].set[1], (std::pair<std::string, double>{"time.dt", 0.001})); // in key order, as JSON objects are
    QCOMPARE(c[2].set[2], (std::pair<std::string, double>{"world.wall_model", double(sim::WallModel::Exact)}));
    QVERIFY(c[3].test == sim::ClaimTest::Above && c[3].distance == 5.0 && c[3].other == 0);

    const LoadResult back = LessonLoader::loadBytes(saveLesson(*r.lesson), QStringLiteral("saved.json"));
    QVERIFY2(back.ok(), qPrintable(back.errors().join(" | ")));
    compareLessons(*r.lesson, *back.lesson);

    // Wrong claims, each named by its key path.
    const LoadResult bad = loadText(minimal(R"("balls": [{"x": 100, "y": 90}], "claims": [
        {"says": "x", "measure": "apogee", "at": 1, "near": 1, "within": 1},
        {"says": "x", "measure": "apex", "ball": 3, "at": 1, "below": 1},
        {"says": "x", "measure": "apex", "at": 1, "near": 1},
        {"says": "x", "measure": "apex", "at": 1, "below": 1, "set": {"models.drag.kk": 1}},
        {"measure": "apex", "at": 1, "above": 1, "below": 2}])"));
    QVERIFY(!bad.ok());
    const QString all = bad.errors().join(" | ");
    for (const char* expected : {"claims.0.measure: \"apogee\" is not one of position", "claims.1.ball: 3 is outside [0, 0]",
                                 "claims.2: give \"near\" one tolerance", "claims.3.set.models.drag.kk: not a parameter",
                                 "claims.4.says: missing", "claims.4: give exactly one of"})
        QVERIFY2(all.contains(QLatin1String(expected)), qPrintable(QStringLiteral("%1 not in %2").arg(expected, all)));
}

void TestLessonLoader::claimSetNamesBallsAndRandomBalls()
{
    const LoadResult r = loadText(minimal(R"("balls": [{"x": 100, "y": 90}], "spawn": {"count": 2}, "claims": [
        {"says": "s", "measure": "position", "at": 0, "near": 40, "within": 0, "axis": "x",
         "set": {"balls.0.x": 40, "spawn.count": 7, "time.dt": 0.01}}])"));
    QVERIFY2(r.ok(), qPrintable(r.errors().join(" | ")));
    const sim::Claim& c = r.lesson->claims.at(0);
    QCOMPARE(c.set.size(), std::size_t{3});
    QCOMPARE(c.set[0], (std::pair<std::string, double>{"balls.0.x", 40.0}));
    QCOMPARE(c.set[1], (std::pair<std::string, double>{"spawn.count", 7.0}));
    QVERIFY(sim::checkClaim(r.lesson->scene, c).holds);
    const LoadResult back = LessonLoader::loadBytes(saveLesson(*r.lesson), QStringLiteral("saved.json"));
    QVERIFY2(back.ok(), qPrintable(back.errors().join(" | ")));
    compareLessons(*r.lesson, *back.lesson);

    // Each bad key or value is one line naming the key.
    const LoadResult bad = loadText(minimal(R"("balls": [{"x": 100, "y": 90}], "claims": [
        {"says": "s", "measure": "speed", "at": 0, "below": 1,
         "set": {"balls.1.x": 5, "balls.0.r": -1, "balls.0.hue": 3, "spawn.count": 1.5, "balls.0.vx": "fast"}},
        {"says": "s", "measure": "speed", "at": 0, "below": 1, "set": {"spawn.speed.0": 500, "spawn.fully_inside": true}}])"));
    QVERIFY(!bad.ok());
    const QString all = bad.errors().join(" | ");
    for (const char* expected :
         {"claims.0.set.balls.1.x: the lesson lists 1 balls, so there is no listed ball 1", "claims.0.set.balls.0.r: -1 is outside",
          "claims.0.set.balls.0.hue: a ball's fields are", "claims.0.set.spawn.count: 1.5 is not a whole number",
          "claims.0.set.balls.0.vx: expected a number", "claims.1.set: the slowest speed, spawn.speed.0 = 500 px/s, is above"})
        QVERIFY2(all.contains(QLatin1String(expected)), qPrintable(QStringLiteral("%1 not in %2").arg(expected, all)));
}

void TestLessonLoader::notMeasuredIsReadAndWritten()
{
    const LoadResult r = loadText(minimal(R"("text": "How high? Set g to 98 px/s².", "not_measured": [
        {"says": "How high?", "because": "question"},
        {"says": "Set g to 98", "because": "unmeasured", "why": "looked at it"}])"));
    QVERIFY2(r.ok(), qPrintable(r.errors().join(" | ")));
    QCOMPARE(r.lesson->notMeasured.size(), std::size_t{2});
    QVERIFY(r.lesson->notMeasured[0].because == NotMeasured::Because::Question);
    QVERIFY(r.lesson->notMeasured[1].because == NotMeasured::Because::Unmeasured);
    QCOMPARE(r.lesson->notMeasured[1].why, QStringLiteral("looked at it"));
    const LoadResult back = LessonLoader::loadBytes(saveLesson(*r.lesson), QStringLiteral("saved.json"));
    QVERIFY2(back.ok(), qPrintable(back.errors().join(" | ")));
    compareLessons(*r.lesson, *back.lesson);

    const LoadResult bad = loadText(minimal(R"("not_measured": [{"says": "a", "because": "obvious"},
        {"says": "b", "because": "unmeasured"}, {"because": "question"}, 3])"));
    QVERIFY(!bad.ok());
    const QString all = bad.errors().join(" | ");
    for (const char* expected : {"not_measured.0.because: \"obvious\" is not one of question, instruction",
                                 "not_measured.1.why: an unmeasured sentence needs", "not_measured.2.says: missing",
                                 "not_measured.3: expected an entry"})
        QVERIFY2(all.contains(QLatin1String(expected)), qPrintable(QStringLiteral("%1 not in %2").arg(expected, all)));
}

// Each row: a lesson's words and entries, and the problems `check` reports
// (a part of each line, in order; none when the lesson passes).
void TestLessonLoader::sentencesWithNumbersNeedAClaimOrAReason_data()
{
    QTest::addColumn<QByteArray>("extra");
    QTest::addColumn<QStringList>("problems");
    const QByteArray ball = R"("balls": [{"x": 100, "y": 90, "r": 12}], )";
    QTest::newRow("no number") << QByteArray(R"("text": "<p>A ball falls.</p><p>It is red.</p>")") << QStringList{};
    QTest::newRow("a number nothing backs")
        << QByteArray(R"("text": "<p>A ball falls.</p><p>It falls 100 px in a second.</p>")")
        << QStringList{QStringLiteral("text: \"It falls 100 px in a second.\" says \"100\", but no claim checks it")};
    QTest::newRow("a comparison in an answer")
        << QByteArray(R"("challenges": ["Which is first?"], "teacher": {"answers": ["Both land at the same time."]},
                        "not_measured": [{"says": "Which is first?", "because": "question"}])")
        << QStringList{QStringLiteral("teacher.answers.0: \"Both land at the same time.\" says \"same\"")};
    QTest::newRow("backed by a claim, in pieces, in two texts")
        << ball + R"("text": "The ball is at x = 100 px. So it stays.", "teacher": {"answers": ["Yes: the ball is at x = 100 px."]},
                     "challenges": ["Where?"], "not_measured": [{"says": "Where?", "because": "question"}],
                     "claims": [{"says": "ball is at … 100 px", "measure": "position", "axis": "x", "at": 0, "near": 100, "within": 0}])"
        << QStringList{};
    QTest::newRow("a quote that is not there")
        << ball + R"("claims": [{"says": "It rises to 192 px.", "measure": "speed", "at": 0, "below": 1}])"
        << QStringList{QStringLiteral("claims.0.says: \"It rises to 192 px.\" is not in the lesson")};
    QTest::newRow("a quote is whole words")
        << ball + R"("text": "How fast?", "not_measured": [{"says": "How fast?", "because": "question"}],
                     "claims": [{"says": "s", "measure": "speed", "at": 0, "below": 1}])"
        << QStringList{QStringLiteral("claims.0.says: \"s\" is not in the lesson")};
    QTest::newRow("a reason over two sentences")
        << QByteArray(R"("text": "Set dt to 1/60 s. Then 60 steps take 1 s.",
                         "not_measured": [{"says": "1/60 s. Then 60", "because": "instruction"}])")
        << QStringList{QStringLiteral("not_measured.0.says: \"1/60 s. Then 60\" runs over 2 sentences")};
    QTest::newRow("a setting the scene sets")
        << ball + R"("text": "Its radius is 12 px and dt is 1/60 s, 60 steps a second.", "time": {"dt": 0.016666666666666666},
                     "not_measured": [{"says": "Its radius", "because": "setting"}])"
        << QStringList{};
    QTest::newRow("a setting the scene does not set")
        << ball + R"("text": "Its radius is 15 px.", "not_measured": [{"says": "Its radius", "because": "setting"}])"
        << QStringList{QStringLiteral("not_measured.0: \"Its radius is 15 px.\" is called a setting, but 15 is not")};
}

void TestLessonLoader::sentencesWithNumbersNeedAClaimOrAReason()
{
    QFETCH(QByteArray, extra);
    QFETCH(QStringList, problems);
    const LoadResult r = loadText(minimal(extra));
    QVERIFY2(r.ok(), qPrintable(r.errors().join(" | ")));
    const lessons::SentenceReport report = lessons::checkSentences(*r.lesson);
    QCOMPARE(report.problems.size(), problems.size());
    for (qsizetype i = 0; i < problems.size(); ++i)
        QVERIFY2(report.problems[i].contains(problems[i]),
                 qPrintable(QStringLiteral("%1 not in %2").arg(problems[i], report.problems[i])));
}

void TestLessonLoader::numbersAndComparisonsAreFound_data()
{
    QTest::addColumn<QString>("sentence");
    QTest::addColumn<QString>("found");
    QTest::newRow("plain") << QStringLiteral("It rises 211 px.") << QStringLiteral("211");
    QTest::newRow("decimal") << QStringLiteral("e is 0.9 here.") << QStringLiteral("0.9");
    QTest::newRow("fraction") << QStringLiteral("Use dt = 1/60 s.") << QStringLiteral("1/60");
    QTest::newRow("grouped") << QStringLiteral("About 1,200 tests.") << QStringLiteral("1,200");
    QTest::newRow("minus") << QStringLiteral("vx becomes −103.9.") << QStringLiteral("−103.9");
    QTest::newRow("integrator names are not numbers") << QStringLiteral("Try rk4 or yoshida4.") << QString();
    QTest::newRow("response names are not numbers") << QStringLiteral("Switch to 2d-axis.") << QString();
    QTest::newRow("a word") << QStringLiteral("It takes twice as long.") << QStringLiteral("twice");
    QTest::newRow("a comparative") << QStringLiteral("The red one is Faster.") << QStringLiteral("Faster");
    QTest::newRow("pi") << QStringLiteral("The period is π s.") << QStringLiteral("π");
    QTest::newRow("none") << QStringLiteral("The ball turns round.") << QString();
}

void TestLessonLoader::numbersAndComparisonsAreFound()
{
    QFETCH(QString, sentence);
    QFETCH(QString, found);
    QCOMPARE(lessons::numberOrComparison(sentence), found);
}

// A 100,000-character key, in the file or in --set, is named by its start
// and its length in every message.
void TestLessonLoader::longKeysAreCutInMessages()
{
    const QByteArray key(100000, 'k');
    const LoadResult r = loadText(minimal("\"" + key + "\": 1, \"world\": {\"" + key + "\": 2}"));
    QVERIFY(!r.ok());
    const LoadResult o = loadText(minimal(), {Override{QString::fromLatin1(key), QStringLiteral("3")}});
    QVERIFY(!o.ok());
    const QStringList lines = r.errors() + o.errors();
    QCOMPARE(lines.size(), 3);
    for (const QString& line : lines) {
        QVERIFY2(line.size() < 1000, qPrintable(line.left(400)));
        QVERIFY2(line.contains(QStringLiteral("(100000 characters)")), qPrintable(line));
    }
}

void TestLessonLoader::teacherNotesAreReadAndWritten()
{
    const LoadResult r = loadText(minimal(R"("challenges": ["How high?", "How long?"], "teacher": {
        "goal": "Energy is lost at each bounce.", "minutes": 15,
        "misconceptions": ["The ball bounces back to where it started."], "answers": ["192 px", "0.78 s"]})"));
    QVERIFY2(r.ok(), qPrintable(r.errors().join(" | ")));
    const TeacherNotes& t = r.lesson->teacher;
    QCOMPARE(t.goal, QStringLiteral("Energy is lost at each bounce."));
    QCOMPARE(t.minutes, 15);
    QCOMPARE(t.misconceptions, QStringList{QStringLiteral("The ball bounces back to where it started.")});
    QCOMPARE(t.answers, (QStringList{QStringLiteral("192 px"), QStringLiteral("0.78 s")}));
    const LoadResult back = LessonLoader::loadBytes(saveLesson(*r.lesson), QStringLiteral("saved.json"));
    QVERIFY2(back.ok(), qPrintable(back.errors().join(" | ")));
    compareLessons(*r.lesson, *back.lesson);

    // Notes without answers (not written yet) load, and save and load back.
    const LoadResult partial = loadText(minimal(R"("challenges": ["How high?", "How long?"], "teacher": {"goal": "g"})"));
    QVERIFY2(partial.ok(), qPrintable(partial.errors().join(" | ")));
    const LoadResult partialBack = LessonLoader::loadBytes(saveLesson(*partial.lesson), QStringLiteral("saved.json"));
    QVERIFY2(partialBack.ok(), qPrintable(partialBack.errors().join(" | ")));
    compareLessons(*partial.lesson, *partialBack.lesson);

    const LoadResult bad = loadText(minimal(R"("challenges": ["How high?"], "teacher": {"answers": ["a", "b"], "time": 3})"));
    QVERIFY(!bad.ok());
    const QString all = bad.errors().join(" | ");
    QVERIFY2(all.contains(QStringLiteral("teacher.answers: 2 answers for 1 challenge;")), qPrintable(all));
    QVERIFY2(all.contains(QStringLiteral("teacher.time: unknown key")), qPrintable(all));
}

void TestLessonLoader::builtInFilesAreCompiledIn()
{
    const QStringList files = LessonLoader::builtInFiles();
    QVERIFY2(files.contains(QStringLiteral(":/lessons/00-showcase.json")), qPrintable(files.join(' ')));
    QVERIFY(files.contains(QStringLiteral(":/lessons/07-gravity.json")));
    QStringList sorted = files;
    sorted.sort();
    QCOMPARE(files, sorted);
    QCOMPARE(files.first(), QStringLiteral(":/lessons/00-showcase.json"));
}

void TestLessonLoader::everyBuiltInLessonLoads()
{
    const QStringList files = LessonLoader::builtInFiles();
    QVERIFY(!files.isEmpty());
    for (const QString& f : files) {
        const LoadResult r = LessonLoader::load(f);
        QVERIFY2(r.ok(), qPrintable(f + ": " + r.errors().join(" | ")));
        QVERIFY(r.errors().isEmpty());
        const Lesson& l = *r.lesson;
        QCOMPARE(l.source, f);
        QVERIFY(!l.id.isEmpty());
        QVERIFY(!l.title.isEmpty());
        QVERIFY2(l.challenges.size() >= 2 && l.challenges.size() <= 4, qPrintable(f));
        QVERIFY(!l.text.isEmpty());
        // The file name NN-… carries the stage.
        QCOMPARE(QFileInfo(f).fileName().left(2).toInt(), l.stage);
    }
}

void TestLessonLoader::builtInByIdAndStem()
{
    const LoadResult byId = LessonLoader::load(QStringLiteral("gravity"));
    QVERIFY2(byId.ok(), qPrintable(byId.errors().join(" | ")));
    QCOMPARE(byId.lesson->source, QStringLiteral(":/lessons/07-gravity.json"));
    QCOMPARE(byId.lesson->stage, 7);
    QVERIFY(byId.lesson->scene.settings.gravity.enabled);
    COMPARE_BITS(byId.lesson->scene.settings.gravity.g.y(), 980.0);

    const LoadResult byStem = LessonLoader::load(QStringLiteral("00-showcase"));
    QVERIFY2(byStem.ok(), qPrintable(byStem.errors().join(" | ")));
    QCOMPARE(byStem.lesson->id, QStringLiteral("showcase"));
    const sim::WorldSettings& s = byStem.lesson->scene.settings;
    QVERIFY(!s.gravity.enabled);
    QVERIFY(s.homing.enabled && s.pointer.enabled);
    COMPARE_ENUM(s.collisions.detection, sim::Detection::Sweep);
    COMPARE_ENUM(s.collisions.response, sim::Response::Impulse2D);

    const LoadResult missing = LessonLoader::load(QStringLiteral("no-such-lesson"));
    QVERIFY(!missing.ok());
    QCOMPARE(missing.errors().size(), 1);
    QVERIFY2(missing.errors().first().startsWith("no-such-lesson: no such file or built-in lesson; built-in lessons: "),
             qPrintable(missing.errors().first()));
    QVERIFY(missing.errors().first().contains("gravity"));
}

void TestLessonLoader::builtInLessonsRun()
{
    // Two seconds of each built-in lesson: the world accepts the scene, and
    // every ball stays finite, and inside the box when the box is closed and
    // the lesson is not about a wall bug (tests/test_lessons.cpp checks more).
    for (const QString& f : LessonLoader::builtInFiles()) {
        const LoadResult r = LessonLoader::load(f);
        QVERIFY2(r.ok(), qPrintable(r.errors().join(" | ")));
        const sim::Scene& scene = r.lesson->scene;
        sim::World world;
        const auto error = world.reset(scene);
        QVERIFY2(!error, error ? sim::toString(*error).c_str() : "");
        const int steps = static_cast<int>(std::lround(2.0 / scene.settings.time.dt));
        for (int k = 0; k < steps; ++k)
            world.step();
        QVERIFY2(world.balls().size() > 0, qPrintable(f));
        const sim::WallSettings& w = scene.settings.walls;
        const bool closed = w.left && w.right && w.top && w.bottom && !w.centreOnly &&
                            w.model != sim::WallModel::Reverse;
        const sim::BallState& b = world.balls();
        const double slack = 1e-9;
        for (int i = 0; i < b.size(); ++i) {
            QVERIFY2(b.position.col(i).allFinite() && b.velocity.col(i).allFinite(), qPrintable(f));
            if (!closed)
                continue;
            QVERIFY2(b.position(0, i) >= b.radius[i] - slack &&
                         b.position(0, i) <= scene.settings.box.width - b.radius[i] + slack &&
                         b.position(1, i) >= b.radius[i] - slack &&
                         b.position(1, i) <= scene.settings.box.height - b.radius[i] + slack,
                     qPrintable(QStringLiteral("%1: ball %2 at (%3, %4)").arg(f).arg(i).arg(b.position(0, i)).arg(
                         b.position(1, i))));
        }
    }
}

void TestLessonLoader::eachKeyLandsInItsMember()
{
    const QByteArray json = R"({
  "format": 1, "id": "every-key", "title": "Every key", "stage": 42,
  "text": "Some <b>text</b>", "challenges": ["one", "two"],
  "world": {"width": 640, "height": 480, "walls": ["left", "bottom"], "wall_model": "exact", "restitution": 0.75,
            "middle_wall": true, "centre_only": true},
  "time": {"integrator": "rk45", "dt": 0.004, "substeps": 3, "tolerance": 1e-7, "seed": 12345, "per_frame": true},
  "models": {
    "gravity": {"x": 1.5, "y": 900},
    "drag": {"law": "quadratic", "k": 0.002, "scale": "radius"},
    "wind": {"mode": "noise", "strength": 40, "scale": "mass", "smoothed_step": 0.25, "frequency": 2,
             "compare": "smoothed"},
    "random_accel": {"fixed": true, "strength": 75},
    "point": {"kind": "repel", "x": 10, "y": 20, "strength": 5e5, "max_accel": 1500, "scale": "radius"},
    "spring": {"x": 30, "y": 40, "k": 9},
    "mutual_gravity": {"G": -250, "softening": 3},
    "homing": {"strength": 6},
    "pointer": {"strength": 1e6, "max_accel": 2500},
    "speed_limit": {"max": 700},
    "collisions": {"detection": "grid", "response": "1d-elastic", "restitution": 0.5, "continuous": true,
                   "resting": false}
  },
  "balls": [{"x": 100, "y": 50, "vx": -3, "vy": 4, "r": 11, "mass": 2.5, "color": "#E05051",
             "pinned": true, "restitution": 0.25},
            {"x": 7, "y": 8}],
  "spawn": {"count": 20, "radius": [3, 9], "speed": 12, "seed": 99, "palette": ["#010203", "#a0b0c0"],
            "horizontal": true, "fully_inside": false, "per_step": 0.1, "max_count": 50},
  "controls": ["gravity", "drag"], "overlays": ["velocity"]
})";
    const LoadResult r = loadText(json);
    QVERIFY2(r.ok(), qPrintable(r.errors().join(" | ")));
    const Lesson& l = *r.lesson;
    QCOMPARE(l.id, QStringLiteral("every-key"));
    QCOMPARE(l.title, QStringLiteral("Every key"));
    QCOMPARE(l.stage, 42);
    QCOMPARE(l.text, QStringLiteral("Some <b>text</b>"));
    QCOMPARE(l.challenges, QStringList({"one", "two"}));
    QCOMPARE(l.controls, QStringList({"gravity", "drag"}));
    QCOMPARE(l.overlays, QStringList({"velocity"}));
    QCOMPARE(l.source, kSrc);

    const sim::WorldSettings& s = l.scene.settings;
    QCOMPARE(s.box.width, 640.0);
    QCOMPARE(s.box.height, 480.0);
    QVERIFY(s.walls.left && !s.walls.right && !s.walls.top && s.walls.bottom);
    COMPARE_ENUM(s.walls.model, sim::WallModel::Exact);
    QCOMPARE(s.walls.restitution, 0.75);
    QVERIFY(s.walls.middle && s.walls.centreOnly);
    QVERIFY(s.time.perFrame);
    COMPARE_ENUM(s.wind.compare, sim::WindMode::Smoothed);
    QVERIFY(s.randomAccel.enabled && s.randomAccel.fixed);
    QCOMPARE(s.randomAccel.strength, 75.0);
    COMPARE_ENUM(s.time.integrator, sim::IntegratorKind::Rk45);
    QCOMPARE(s.time.dt, 0.004);
    QCOMPARE(s.time.substeps, 3);
    QCOMPARE(s.time.tolerance, 1e-7);
    QCOMPARE(s.time.seed, std::uint64_t{12345});
    QVERIFY(s.gravity.enabled);
    QCOMPARE(s.gravity.g.x(), 1.5);
    QCOMPARE(s.gravity.g.y(), 900.0);
    QVERIFY(s.drag.enabled);
    COMPARE_ENUM(s.drag.law, sim::DragLaw::Quadratic);
    QCOMPARE(s.drag.k, 0.002);
    COMPARE_ENUM(s.drag.scale, sim::ForceScale::Radius);
    COMPARE_ENUM(s.wind.mode, sim::WindMode::Noise);
    QCOMPARE(s.wind.strength, 40.0);
    COMPARE_ENUM(s.wind.scale, sim::ForceScale::Mass);
    QCOMPARE(s.wind.smoothedStep, 0.25);
    QCOMPARE(s.wind.noiseFrequency, 2.0);
    QVERIFY(s.point.enabled);
    COMPARE_ENUM(s.point.kind, sim::PointKind::Repel);
    QCOMPARE(s.point.position.x(), 10.0);
    QCOMPARE(s.point.position.y(), 20.0);
    QCOMPARE(s.point.strength, 5e5);
    QCOMPARE(s.point.maxAccel, 1500.0);
    COMPARE_ENUM(s.point.scale, sim::ForceScale::Radius);
    QVERIFY(s.spring.enabled);
    QCOMPARE(s.spring.anchor.x(), 30.0);
    QCOMPARE(s.spring.anchor.y(), 40.0);
    QCOMPARE(s.spring.k, 9.0);
    QVERIFY(s.mutualGravity.enabled);
    QCOMPARE(s.mutualGravity.G, -250.0);
    QCOMPARE(s.mutualGravity.softening, 3.0);
    QVERIFY(s.homing.enabled);
    QCOMPARE(s.homing.strength, 6.0);
    QVERIFY(s.pointer.enabled);
    QCOMPARE(s.pointer.strength, 1e6);
    QCOMPARE(s.pointer.maxAccel, 2500.0);
    QVERIFY(s.speedLimit.enabled);
    QCOMPARE(s.speedLimit.max, 700.0);
    COMPARE_ENUM(s.collisions.detection, sim::Detection::Grid);
    COMPARE_ENUM(s.collisions.response, sim::Response::Elastic1D);
    QCOMPARE(s.collisions.restitution, 0.5);
    QVERIFY(s.collisions.continuous);
    QVERIFY(!s.collisions.resting);

    QCOMPARE(l.scene.balls.size(), std::size_t{2});
    const sim::Ball& b = l.scene.balls[0];
    QCOMPARE(b.position.x(), 100.0);
    QCOMPARE(b.position.y(), 50.0);
    QCOMPARE(b.velocity.x(), -3.0);
    QCOMPARE(b.velocity.y(), 4.0);
    QCOMPARE(b.radius, 11.0);
    QCOMPARE(b.mass, 2.5);
    QCOMPARE(b.color, sim::Rgb{0xe05051});
    QVERIFY(b.pinned);
    QCOMPARE(b.restitution, 0.25);
    // Absent ball keys keep the Ball defaults: at rest, r 10, sphere mass (0), default colour.
    const sim::Ball& c = l.scene.balls[1];
    const sim::Ball d;
    QCOMPARE(c.position.x(), 7.0);
    QCOMPARE(c.velocity.x(), 0.0);
    QCOMPARE(c.radius, d.radius);
    QCOMPARE(c.mass, 0.0);
    QCOMPARE(c.color, d.color);
    QVERIFY(!c.pinned);
    QCOMPARE(c.restitution, sim::kWorldRestitution); // absent: the world's

    const sim::SpawnSettings& sp = l.scene.spawn;
    QCOMPARE(sp.count, 20);
    QCOMPARE(sp.minRadius, 3.0);
    QCOMPARE(sp.maxRadius, 9.0);
    QCOMPARE(sp.minSpeed, 12.0); // one number means [12, 12]
    QCOMPARE(sp.maxSpeed, 12.0);
    QCOMPARE(sp.seed, std::uint64_t{99});
    QCOMPARE(sp.palette, (std::vector<sim::Rgb>{0x010203, 0xa0b0c0}));
    QVERIFY(sp.horizontal && !sp.fullyInside);
    QCOMPARE(sp.perStep, 0.1);
    QCOMPARE(sp.maxCount, 50);
}

void TestLessonLoader::absentModelsAreOff()
{
    const LoadResult r = loadText(minimal());
    QVERIFY2(r.ok(), qPrintable(r.errors().join(" | ")));
    const sim::WorldSettings& s = r.lesson->scene.settings;
    QVERIFY(!s.gravity.enabled);
    QVERIFY(!s.drag.enabled);
    COMPARE_ENUM(s.wind.mode, sim::WindMode::Off);
    QVERIFY(!s.point.enabled);
    QVERIFY(!s.spring.enabled);
    QVERIFY(!s.mutualGravity.enabled);
    QVERIFY(!s.homing.enabled);
    QVERIFY(!s.pointer.enabled);
    QVERIFY(!s.speedLimit.enabled);
    QVERIFY(!s.randomAccel.enabled);
    COMPARE_ENUM(s.wind.compare, sim::WindMode::Off);
    QVERIFY(!s.walls.middle && !s.walls.centreOnly && !s.time.perFrame);
    QVERIFY(r.lesson->scene.spawn.fullyInside && !r.lesson->scene.spawn.horizontal);
    QCOMPARE(r.lesson->scene.spawn.perStep, 0.0);
    COMPARE_ENUM(s.collisions.response, sim::Response::None);
    QCOMPARE(r.lesson->title, QStringLiteral("t")); // the title defaults to the id
    QVERIFY(r.lesson->scene.balls.empty());
    QCOMPARE(r.lesson->scene.spawn.count, 0);

    // A model object that is present is on, with the struct defaults for what it leaves out.
    const LoadResult on = loadText(minimal(R"("models": {"drag": {}, "wind": {}, "collisions": {}})"));
    QVERIFY2(on.ok(), qPrintable(on.errors().join(" | ")));
    const sim::WorldSettings& t = on.lesson->scene.settings;
    QVERIFY(t.drag.enabled);
    QCOMPARE(t.drag.k, sim::DragSettings{}.k);
    COMPARE_ENUM(t.wind.mode, sim::WindMode::Random);
    COMPARE_ENUM(t.collisions.response, sim::Response::Impulse2D);
}

void TestLessonLoader::presentModelWithEnabledFalseIsOff()
{
    const LoadResult r = loadText(minimal(R"("models": {"gravity": {"enabled": false, "y": 123}})"));
    QVERIFY2(r.ok(), qPrintable(r.errors().join(" | ")));
    QVERIFY(!r.lesson->scene.settings.gravity.enabled);
    QCOMPARE(r.lesson->scene.settings.gravity.g.y(), 123.0);
}

// A lesson lists the panels its words send students to ("tools"); a text,
// challenge or answer that names a panel the lesson does not list is
// refused, naming the field and the tool, so the stage view can offer all
// a lesson asks for. Predict questions offer the Predict panel by themselves.
// A challenge that asks for a change names a control its lesson lists, so
// the stage's sliders offer it; a sentence that only mentions the thing is
// no request.
void TestLessonLoader::challengesAskOnlyForListedControls()
{
    const QByteArray challenge = R"("challenges": ["Turn the bottom wall off and watch. Then set the collision restitution to 0.5."])";
    const LoadResult missing = loadText(minimal(challenge));
    QVERIFY(!missing.ok());
    const QString all = missing.errors().join('\n');
    QVERIFY2(all.contains(QStringLiteral("challenges.0: \"Turn the bottom wall\" asks for a control the lesson does not "
                                         "list; list \"walls\" in \"controls\"")),
             qPrintable(all));
    QVERIFY2(all.contains(QStringLiteral("\"set the collision restitution\" asks for a control")), qPrintable(all));
    QVERIFY2(all.contains(QStringLiteral("\"restitution\" or \"collisions\"")), qPrintable(all));
    const LoadResult listed = loadText(minimal(challenge + R"(, "controls": ["walls", "collisions"])"));
    QVERIFY2(listed.ok(), qPrintable(listed.errors().join('\n')));
    // Words that only talk about a wall or gravity ask for nothing.
    const LoadResult talk =
        loadText(minimal(R"("challenges": ["Bring the balls to the right wall. Why does gravity pull them down?"])"));
    QVERIFY2(talk.ok(), qPrintable(talk.errors().join('\n')));
    // A switch written as its code name is a request wherever it stands.
    const LoadResult code = loadText(minimal(R"("challenges": ["With per_frame off, what changes?"])"));
    QVERIFY(!code.ok());
    QVERIFY2(firstError(code).contains(QStringLiteral("list \"per_frame\" in \"controls\"")), qPrintable(firstError(code)));
}

void TestLessonLoader::toolsAreListedAndNamedOnlyWhenListed()
{
    const QByteArray challenge = R"("challenges": ["Time one orbit with the Stopwatch."])";
    const LoadResult missing = loadText(minimal(challenge));
    QVERIFY(!missing.ok());
    QVERIFY2(firstError(missing).contains(QStringLiteral("challenges.0: names the Stopwatch panel; list \"stopwatch\"")),
             qPrintable(firstError(missing)));
    const LoadResult listed = loadText(minimal(challenge + R"(, "tools": ["stopwatch"])"));
    QVERIFY2(listed.ok(), qPrintable(listed.errors().join('\n')));
    QCOMPARE(listed.lesson->tools, QStringList{QStringLiteral("stopwatch")});
    QCOMPARE(lessons::stageTools(*listed.lesson), QStringList{QStringLiteral("stopwatch")});
    // Written back only when listed, and read back the same.
    const QByteArray saved = saveLesson(*listed.lesson);
    QVERIFY(saved.contains(R"("tools": ["stopwatch"])"));
    QCOMPARE(loadText(saved).lesson->tools, listed.lesson->tools);
    QVERIFY(!saveLesson(*loadText(minimal()).lesson).contains("\"tools\""));
    // Markup does not hide a name; the text and the answers count too.
    const LoadResult bold = loadText(minimal(R"("text": "Open the <b>Force editor</b>.")"));
    QVERIFY2(!bold.ok() && firstError(bold).contains(QStringLiteral("text: names the Force editor panel")),
             qPrintable(firstError(bold)));
    // "Predict" alone is a verb, not the panel.
    QVERIFY(loadText(minimal(R"("challenges": ["Predict, and explain why."])")).ok());
    const LoadResult unknown = loadText(minimal(R"("tools": ["stopwatch", "ruler"])"));
    QVERIFY2(!unknown.ok() && firstError(unknown).contains(QStringLiteral("tools.1: \"ruler\" is not one of stopwatch")),
             qPrintable(firstError(unknown)));
}

void TestLessonLoader::badInput_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("error");

    QTest::newRow("syntax: missing comma, line and column")
        << QByteArray("{\n  \"format\": 1,\n  \"id\": \"t\"\n  \"title\": \"x\"\n}")
        << "t.json:4:3: syntax error: expected , or } here (a missing comma, or a { that is never closed)";
    QTest::newRow("syntax: column counts characters, not bytes")
        << QByteArray("{\"format\": 1, \"id\": \"t\", \"text\": \"é\" ,, }")
        << "t.json:1:39: syntax error: expected , or } here (a missing comma, or a { that is never closed)";
    QTest::newRow("syntax: number too large for a double")
        << QByteArray("{\"format\": 1,\n \"id\": \"t\",\n \"time\": {\"dt\": 1e999}}")
        << "t.json:3:17: syntax error: not a valid value (text needs \"double quotes\"; a number must fit a double, "
           "e.g. 1e999 does not)";
    QTest::newRow("syntax: empty file") << QByteArray("") << "t.json:1:1: syntax error: not a JSON value (text needs "
                                                             "\"double quotes\"; true, false and null are lower case; no "
                                                             "comma before } or ])";
    QTest::newRow("syntax: unquoted word")
        << QByteArray("{\"format\": 1, \"id\": \"t\",\n \"time\": {\"integrator\": rk4}}")
        << "t.json:2:25: syntax error: not a valid value (text needs \"double quotes\"; a number must fit a double, "
           "e.g. 1e999 does not)";
    QTest::newRow("syntax: text after the object")
        << QByteArray("{\"format\": 1, \"id\": \"t\"}\n}") << "t.json:2:1: syntax error: more text after the end of the lesson object";
    QTest::newRow("top level not an object")
        << QByteArray("[1, 2]") << "t.json: the lesson must be one JSON object { … }";
    QTest::newRow("bad enum lists the allowed values")
        << minimal(R"("models": {"wind": {"mode": "gust"}})")
        << R"(t.json:1:46: models.wind.mode: "gust" is not one of off, random, smoothed, noise, pointer)";
    QTest::newRow("bad integrator")
        << minimal(R"("time": {"integrator": "rk5"})")
        << R"(t.json:1:35: time.integrator: "rk5" is not one of euler, semi-implicit-euler, verlet, rk4, yoshida4, rk45, exact, ias15)";
    QTest::newRow("unknown key with suggestion")
        << minimal(R"("models": {"gravty": {"y": 1}})")
        << R"(t.json:1:37: models.gravty: unknown key "gravty"; did you mean "gravity"?)";
    QTest::newRow("unknown key without a close match lists the keys")
        << minimal(R"("world": {"colour": 1})")
        << R"(t.json:1:36: world.colour: unknown key "colour"; known keys here: width, height, wall_model, restitution, middle_wall, centre_only, walls)";
    QTest::newRow("unknown top-level key") << minimal(R"("titel": "x")")
                                           << R"(t.json:1:26: titel: unknown key "titel"; did you mean "title"?)";
    QTest::newRow("wrong type: string for a number")
        << minimal(R"("time": {"dt": "fast"})") << R"(t.json:1:35: time.dt: expected a number in (0, 1] s, got the string "fast")";
    QTest::newRow("wrong type: number for an object")
        << minimal(R"("models": 3)") << "t.json:1:26: models: expected an object { … }, got the number 3";
    QTest::newRow("wrong type: bool")
        << minimal(R"("models": {"collisions": {"continuous": 1}})")
        << "t.json:1:52: models.collisions.continuous: expected true or false, got the number 1";
    QTest::newRow("wrong type: resting")
        << minimal(R"("models": {"collisions": {"resting": "yes"}})")
        << "t.json:1:52: models.collisions.resting: expected true or false, got the string \"yes\"";
    QTest::newRow("wrong type: whole number") << minimal(R"("time": {"substeps": 1.5})")
                                              << "t.json:1:35: time.substeps: expected a whole number, got 1.5";
    QTest::newRow("out of range, open bound") << minimal(R"("time": {"dt": 0})")
                                              << "t.json:1:35: time.dt: 0 is outside (0, 1] s";
    QTest::newRow("out of range, closed bound") << minimal(R"("world": {"restitution": 1.5})")
                                                << "t.json:1:36: world.restitution: 1.5 is outside [0, 1]";
    QTest::newRow("out of range, integer") << minimal(R"("time": {"substeps": 1001})")
                                           << "t.json:1:35: time.substeps: 1001 is outside [1, 1000]";
    QTest::newRow("out of range, ball radius")
        << minimal(R"("balls": [{"x": 1, "y": 2, "r": -4}])") << "t.json:1:53: balls.0.r: -4 is outside [1e-06, 10000] px";
    // r³ underflows: the sphere's mass would be exactly 0 (it was accepted).
    QTest::newRow("ball radius whose mass underflows")
        << minimal(R"("balls": [{"x": 1, "y": 2, "r": 1e-110}])") << "t.json:1:53: balls.0.r: 1e-110 is outside [1e-06, 10000] px";
    QTest::newRow("ball charge out of range")
        << minimal(R"("balls": [{"x": 1, "y": 2, "q": -2e6}])")
        << "t.json:1:53: balls.0.q: -2000000 is outside [-1000000, 1000000] charge units";
    QTest::newRow("ball pinned not a switch")
        << minimal(R"("balls": [{"x": 1, "y": 2, "pinned": 1}])")
        << "t.json:1:53: balls.0.pinned: expected true or false, got the number 1";
    QTest::newRow("ball restitution out of range")
        << minimal(R"("balls": [{"x": 1, "y": 2, "restitution": 1.5}])")
        << "t.json:1:53: balls.0.restitution: 1.5 is outside [0, 1]";
    QTest::newRow("ball mass too small to invert safely")
        << minimal(R"("balls": [{"x": 1, "y": 2, "mass": 1e-300}])")
        << "t.json:1:53: balls.0.mass: 1e-300 is outside [1e-12, 1e+15] mass units";
    QTest::newRow("spawn radius whose mass underflows")
        << minimal(R"("spawn": {"count": 3, "radius": [1e-200, 5]})")
        << "t.json:1:59: spawn.radius.0: 1e-200 is outside [1e-06, 10000] px";
    QTest::newRow("missing ball position") << minimal(R"("balls": [{"x": 1}])")
                                           << "t.json:1:36: balls.0.y: missing; give the ball's centre y in px";
    QTest::newRow("misspelt colour name")
        << minimal(R"("balls": [{"x": 1, "y": 2, "color": "purpel"}])")
        << R"(t.json:1:53: balls.0.color: "purpel" is not a colour name; one of sky blue, light blue, blue, red, orange, yellow, green, purple, violet, pink, black, grey, gray, white, or "#rrggbb")";
    QTest::newRow("bad colour hex") << minimal(R"("balls": [{"x": 1, "y": 2, "color": "#e0505"}])")
                                    << R"(t.json:1:53: balls.0.color: expected a colour name (e.g. "red") or "#rrggbb" (e.g. "#e05050"), got the string "#e0505")";
    QTest::newRow("colour not a string") << minimal(R"("balls": [{"x": 1, "y": 2, "color": 5}])")
                                         << R"(t.json:1:53: balls.0.color: expected a colour name (e.g. "red") or "#rrggbb" (e.g. "#e05050"), got the number 5)";
    QTest::newRow("bad wall name") << minimal(R"("world": {"walls": ["left", "floor"]})")
                                   << R"(t.json:1:54: world.walls.1: "floor" is not one of left, right, top, bottom)";
    QTest::newRow("unknown overlay") << minimal(R"("overlays": ["velocity", "vectors"])")
                                     << R"(t.json:1:51: overlays.1: "vectors" is not one of grid, velocity, acceleration, readout, colliding, markers, vanes, trails, impact, broadphase, histogram, totals, forces, sources, centre-of-mass, momenta, apexes)";
    QTest::newRow("compare pane with an unknown key")
        << minimal(R"("compare": [{"label": "m", "set": {"world.nope": 1}}])") << "t.json:1:61: compare.0.set.world.nope: not a parameter key path (docs/parameters.md lists them)";
    QTest::newRow("compare pane with a bad wall model")
        << minimal(R"("compare": [{"label": "m", "set": {"world.wall_model": "bounce"}}])") << R"(t.json:1:61: compare.0.set.world.wall_model: the string "bounce" is not one of clamp, mirror, exact, reverse)";
    QTest::newRow("compare pane without a label") << minimal(R"("compare": [{"set": {}}])") << R"(t.json:1:38: compare.0.label: missing; give the pane's name, e.g. "mirror")";
    QTest::newRow("four compare panes")
        << minimal(R"("compare": [{"label": "a", "set": {}}, {"label": "b", "set": {}}, {"label": "c", "set": {}}, {"label": "d", "set": {}}])")
        << "t.json:1:26: compare: 4 panes is more than the limit of 3";
    QTest::newRow("question without claims")
        << minimal(R"("predict": [{"ask": "How high?", "claim": 0}])") << "t.json:1:59: predict.0.claim: the lesson has no claims to answer the question";
    QTest::newRow("question with one choice")
        << minimal(R"("claims": [{"says": "s", "measure": "speed", "at": 1, "near": 0, "within": 1}], "predict": [{"ask": "How fast?", "claim": 0, "choices": [{"label": "0", "value": 0}]}])")
        << "t.json:1:151: predict.0.choices: 1 choice; give 2 to 8";
    QTest::newRow("question about a claim that is not there")
        << minimal(R"("claims": [{"says": "s", "measure": "speed", "at": 1, "near": 0, "within": 1}], "predict": [{"ask": "How fast?", "claim": 1}])")
        << "t.json:1:139: predict.0.claim: 1 is outside [0, 0]";
    QTest::newRow("unknown control") << minimal(R"("controls": ["gravity", "gravity.y"])")
                                     << "t.json:1:50: controls.1: \"gravity.y\" is not one of " +
                                            LessonLoader::controlNames().join(", ");
    QTest::newRow("spawn min above max") << minimal(R"("spawn": {"radius": [9, 3]})")
                                         << "t.json:1:36: spawn.radius: the minimum 9 is larger than the maximum 3";
    QTest::newRow("reverse is a wall model") << minimal(R"("world": {"wall_model": "bounce"})")
                                             << R"(t.json:1:36: world.wall_model: "bounce" is not one of clamp, mirror, exact, reverse)";
    QTest::newRow("per_step above 1") << minimal(R"("spawn": {"per_step": 1.5})")
                                      << "t.json:1:36: spawn.per_step: 1.5 is outside [0, 1]";
    QTest::newRow("max_count fractional") << minimal(R"("spawn": {"max_count": 2.5})")
                                          << "t.json:1:36: spawn.max_count: expected a whole number, got 2.5";
    QTest::newRow("centre_only not a bool") << minimal(R"("world": {"centre_only": "yes"})")
                                            << R"(t.json:1:36: world.centre_only: expected true or false, got the string "yes")";
    QTest::newRow("random_accel strength") << minimal(R"("models": {"random_accel": {"strength": -1}})")
                                           << "t.json:1:54: models.random_accel.strength: -1 is outside [0, 10000000] px/s²";
    QTest::newRow("drag scale") << minimal(R"("models": {"drag": {"scale": "heavy"}})")
                                << R"(t.json:1:46: models.drag.scale: "heavy" is not one of none, radius, mass)";
    QTest::newRow("wind compare") << minimal(R"("models": {"wind": {"compare": "gusty"}})")
                                  << R"(t.json:1:46: models.wind.compare: "gusty" is not one of off, random, smoothed, noise, pointer)";
    QTest::newRow("misspelt per_frame") << minimal(R"("time": {"perframe": true})")
                                        << R"(t.json:1:35: time.perframe: unknown key "perframe"; did you mean "per_frame"?)";
    QTest::newRow("missing format") << QByteArray(R"({"id": "t"})") << "t.json: format: missing; give \"format\": 1";
    QTest::newRow("unsupported format") << QByteArray(R"({"format": 2, "id": "t"})")
                                        << "t.json:1:2: format: 2 is not a format this version reads; it reads format 1";
    QTest::newRow("bad id") << QByteArray(R"({"format": 1, "id": "a b"})")
                            << R"(t.json:1:15: id: "a b" is not a valid id; use 1 to 64 letters, digits, '-' or '_')";
    QTest::newRow("duplicate key")
        << QByteArray("{\"format\": 1,\n \"id\": \"t\",\n \"models\": {\"gravity\": {\"y\": 1, \"y\": 2}}}")
        << "t.json:3:33: models.gravity.y: duplicate key (first given on line 3); give each key once";
    QTest::newRow("duplicate key across lines, escaped spelling")
        << QByteArray("{\"format\": 1,\n \"id\": \"t\",\n \"\\u0069d\": \"u\"}")
        << "t.json:3:2: id: duplicate key (first given on line 2); give each key once";
    QTest::newRow("duplicate key inside an array element")
        << minimal(R"("balls": [{"x": 1, "y": 2}, {"x": 1, "x": 2, "y": 3}])")
        << "t.json:1:63: balls.1.x: duplicate key (first given on line 1); give each key once";
    QTest::newRow("non-UTF-8 bytes") << QByteArray("{\"format\": 1,\n \"id\": \"t\", \"text\": \"caf\xe9\"}")
                                     << "t.json:2:25: bytes that are not UTF-8 text; save the file as UTF-8";
    QTest::newRow("overlong UTF-8") << QByteArray("{\"format\": 1, \"id\": \"t\", \"text\": \"\xc0\xaf\"}")
                                    << "t.json:1:35: bytes that are not UTF-8 text; save the file as UTF-8";
    QTest::newRow("deep nesting") << minimal("\"text\": " + QByteArray(40, '[') + QByteArray(40, ']'))
                                  << "t.json:1:65: text" + QString(".0").repeated(31) + ": nested deeper than 32 levels";
    // Past Qt's own limit of 1024 levels the same place is named (before: no
    // key path, and the column where Qt gave up, 1:1058).
    QTest::newRow("nesting deeper than Qt's limit")
        << minimal("\"text\": " + QByteArray(1500, '[') + QByteArray(1500, ']'))
        << "t.json:1:65: text" + QString(".0").repeated(31) + ": nested deeper than 32 levels";
    QTest::newRow("spawn count over the limit") << minimal(R"("balls": [{"x": 1, "y": 1}], "spawn": {"count": 200000})")
                                                << "t.json:1:65: spawn.count: 200000 spawned + 1 listed balls is more than "
                                                   "the limit of 200000";
    QTest::newRow("seed not a whole number") << minimal(R"("time": {"seed": -1})")
                                             << "t.json:1:35: time.seed: expected a whole number in [0, 9007199254740992], "
                                                "or a string of digits up to 18446744073709551615, got the number -1";
}

void TestLessonLoader::badInput()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, error);
    const LoadResult r = loadText(json);
    QVERIFY(!r.ok());
    QCOMPARE(firstError(r), error);
    for (const QString& e : r.errors())
        QVERIFY2(!e.contains('\n'), qPrintable(e)); // one line each
}

// A lesson's words are input from a stranger: only the markup subset of
// lessons/lesson_markup.h loads, and a refusal names the field and the
// character. Before, <img src="/dev/zero"> validated and hung the window,
// and <a href="/etc/passwd"> showed that file in the lesson pane.
void TestLessonLoader::lessonTextIsASafeSubset_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("error"); // empty: loads

    auto text = [](const QByteArray& t) { return minimal("\"text\": \"" + t + "\""); };
    QTest::newRow("a picture by absolute path") << text(R"(<img src=\"/dev/zero\">)")
        << "t.json:1:26: text: character 1: <img src=\"/dev/zero\">: a picture comes only from the lesson's own folder, "
           "by a name such as \"pictures/orbit.png\" (no path, no URL)";
    QTest::newRow("a picture by file URL") << text(R"(ok <img src=\"file:///etc/x.png\">)")
        << "t.json:1:26: text: character 4: <img src=\"file:///etc/x.png\">: a picture comes only from the lesson's own "
           "folder, by a name such as \"pictures/orbit.png\" (no path, no URL)";
    QTest::newRow("a picture above the folder") << text(R"(<img src=\"../secret.png\">)")
        << "t.json:1:26: text: character 1: <img src=\"../secret.png\">: a picture comes only from the lesson's own "
           "folder, by a name such as \"pictures/orbit.png\" (no path, no URL)";
    QTest::newRow("a link to a local file") << text(R"(<a href=\"/etc/passwd\">Answers</a>)")
        << "t.json:1:26: text: character 1: <a href=\"/etc/passwd\">: a link may only go to a web page (https://…)";
    QTest::newRow("a style that loads a picture") << text(R"(<p style=\"background-image:url(/x.png)\">x</p>)")
        << "t.json:1:26: text: character 4: <p> takes no attributes (style=…)";
    QTest::newRow("a tag outside the subset") << text(R"(<p>one</p><table><tr><td>x</td></tr></table>)")
        << "t.json:1:26: text: character 11: <table> is not allowed in lesson text (allowed: <p> <br> <b> <i> <em> "
           "<strong> <u> <sub> <sup> <code> <ul> <ol> <li> <img src> <a href>)";
    QTest::newRow("a tag that never closes") << text(R"(<p>one <b)")
        << "t.json:1:26: text: character 8: <b has no closing >";
    QTest::newRow("a NUL character") << text(R"(a\u0000b)")
        << "t.json:1:26: text: character 2: a NUL character (U+0000), which is not text";
    QTest::newRow("half a surrogate pair") << text(R"(a\ud800b)")
        << "t.json:1:26: text: character 2: half of a surrogate pair (U+D800), which is no character";
    QTest::newRow("a text over the limit") << text(QByteArray(20001, 'x'))
        << "t.json:1:26: text: character 20001: 20001 characters is more than the limit of 20000";
    QTest::newRow("a picture in a challenge") << minimal(R"("challenges": ["fine", "<img src=\"/dev/zero\">"])")
        << "t.json:1:49: challenges.1: character 1: <img src=\"/dev/zero\">: a picture comes only from the lesson's own "
           "folder, by a name such as \"pictures/orbit.png\" (no path, no URL)";
    QTest::newRow("a NUL in the title") << minimal(R"("title": "a\u0000b")")
        << "t.json:1:26: title: character 2: a NUL character (U+0000), which is not text";
    // What the subset allows loads.
    QTest::newRow("a comparison is text") << text(R"(keep k·dt < 2 and x<0, then A & B)") << QString();
    QTest::newRow("the subset") << text(R"(<p><b>b</b> <i>i</i> v<sub>x</sub> r<sup>2</sup> &lt;&amp;&gt; &#8776;</p><ul><li>a</li></ul>)")
                                << QString();
    QTest::newRow("a picture of the folder and a web link")
        << text(R"(<img src=\"pictures/orbit.png\" alt=\"orbit\"> <a href=\"https://example.org/a?b=1\">more</a>)")
        << QString();
}

namespace {

// `json` loads when `error` is empty, else its first error is `error`.
void loadsOrRefusesWith(const QByteArray& json, const QString& error)
{
    const LoadResult r = loadText(json);
    if (error.isEmpty()) {
        QVERIFY2(r.ok(), qPrintable(r.errors().join(QLatin1Char('\n'))));
        return;
    }
    QVERIFY(!r.ok());
    QCOMPARE(firstError(r), error);
}

} // namespace

void TestLessonLoader::lessonTextIsASafeSubset()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, error);
    loadsOrRefusesWith(json, error);
}

// What the lesson pane shows keeps only the subset: anything else is shown
// as the characters it was written with, so nothing in it loads a file.
void TestLessonLoader::markupKeepsOnlyTheSubset()
{
    using lessons::markupToHtml;
    QCOMPARE(markupToHtml(QStringLiteral("<p>a <b>b</b> &lt; c</p>")).html, QStringLiteral("<p>a <b>b</b> &lt; c</p>"));
    QCOMPARE(markupToHtml(QStringLiteral("<p>x <span style=\"a\">y</span></p>")).html,
             QStringLiteral("<p>x &lt;span style=&quot;a&quot;&gt;y&lt;/span&gt;</p>"));
    // A picture by path and a link to a file keep their words, not their targets.
    const lessons::MarkupHtml html =
        markupToHtml(QStringLiteral("<p><img src=\"/dev/zero\" alt=\"z\"><a href=\"/etc/passwd\">answers</a></p>"));
    QCOMPARE(html.html, QStringLiteral("<p>[z]answers</p>"));
    QVERIFY(html.images.isEmpty());
    // A picture of the folder and a web link stay; pictures off gives the alt text.
    const QString good = QStringLiteral("<p><img src=\"a.png\" alt=\"A\"> <a href=\"https://example.org/\">w</a></p>");
    QCOMPARE(markupToHtml(good).images, QStringList{QStringLiteral("a.png")});
    QCOMPARE(markupToHtml(good).html, QStringLiteral("<p><img src=\"a.png\" alt=\"A\"> <a href=\"https://example.org/\">w</a></p>"));
    QCOMPARE(markupToHtml(good, false, false).html, QStringLiteral("<p>[A] w</p>"));
    // Plain text becomes paragraphs; a "<" in it is a character.
    QCOMPARE(markupToHtml(QStringLiteral("a < b\n\nc")).html, QStringLiteral("<p>a &lt; b</p><p>c</p>"));
    QCOMPARE(lessons::markupToPlainText(QStringLiteral("<b>Gravity</b> &amp; drag")), QStringLiteral("Gravity & drag"));
}

// Refused before any work, with the number that would be needed: before,
// a 97-byte lesson spawning 20,000 colliding balls in the 600 x 400 box took
// 49 s and 2.9 GB for four steps, a ball at (5000, 5000) was moved to
// (590, 390) without a word, and a claim at 3600 s with dt = 1e-8 s kept
// `check` busy for minutes.
void TestLessonLoader::scenesThatCannotBeAreRefused_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("error"); // empty: loads

    const QByteArray collide = R"("models": {"collisions": {}, "gravity": {}})";
    QTest::newRow("more colliding balls than the box holds")
        << minimal(R"("spawn": {"count": 20000}, )" + collide)
        << "t.json:1:36: spawn.count: 20000 colliding balls of radius 4 to 12 px would cover 18.2 times the area of the "
           "600 × 400 px box; colliding balls fill at most 91% of a box, so 999 of them fit at most (or make the box "
           "larger or the balls smaller)";
    QTest::newRow("as many balls that pass through each other") << minimal(R"("spawn": {"count": 20000})") << QString();
    QTest::newRow("the densest box that still loads") << minimal(R"("spawn": {"count": 999}, )" + collide) << QString();
    QTest::newRow("a ball beyond the right wall") << minimal(R"("balls": [{"x": 300, "y": 200}, {"x": 5000, "y": 50}])")
        << "t.json:1:59: balls.1.x: x = 5000 px puts the ball's centre outside the 600 × 400 px box (x from 0 to 600 "
           "px) while the right wall is on; put the ball inside, or switch that wall off";
    QTest::newRow("the same ball without walls")
        << minimal(R"("world": {"walls": []}, "balls": [{"x": 300, "y": 200}, {"x": 5000, "y": 50}])") << QString();
    QTest::newRow("a ball larger than the box") << minimal(R"("balls": [{"x": 300, "y": 200, "r": 10000}])")
        << "t.json:1:57: balls.0.r: a ball of radius 10000 px does not fit between the walls of the 600 × 400 px box "
           "(a radius of 200 px at most)";
    QTest::newRow("a claim that would run for hours")
        << minimal(R"("time": {"dt": 1e-8}, "balls": [{"x": 300, "y": 200}], "claims": [{"says": "x", "measure": "speed", "ball": 0, "at": 3600, "near": 0, "within": 1}])")
        << "t.json:1:137: claims.0.at: 3600 s at dt = 1e-08 s is 360,000,000,000 sub-steps, more than the 1,000,000 a "
           "claim may run; claim an earlier time or use a larger dt";
}

void TestLessonLoader::scenesThatCannotBeAreRefused()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, error);
    loadsOrRefusesWith(json, error);
}

void TestLessonLoader::everyProblemIsReported()
{
    const LoadResult r = loadText(minimal(
        R"("time": {"dt": -1, "substeps": "two"}, "models": {"wind": {"mode": "gust"}, "drag": {"k": 1e9}}, "balls": [{"x": 1, "y": 2, "r": 0}, 5])"));
    QVERIFY(!r.ok());
    const QStringList expected{
        "t.json:1:35: time.dt: -1 is outside (0, 1] s",
        R"(t.json:1:45: time.substeps: expected a whole number in [1, 1000], got the string "two")",
        "t.json:1:111: models.drag.k: 1000000000 is outside [0, 1000000] 1/s (linear) or 1/px (quadratic)",
        R"(t.json:1:85: models.wind.mode: "gust" is not one of off, random, smoothed, noise, pointer)",
        "t.json:1:150: balls.0.r: 0 is outside [1e-06, 10000] px",
        R"(t.json:1:159: balls.1: expected a ball object {"x": …, "y": …}, got the number 5)",
    };
    QCOMPARE(r.errors(), expected);
}

void TestLessonLoader::tooLargeFile()
{
    QByteArray big = minimal(R"("text": ")");
    big.chop(1);
    big += QByteArray(16 * 1024 * 1024, 'a') + "\"}";
    const LoadResult r = loadText(big);
    QVERIFY(!r.ok());
    QCOMPARE(r.errors(), QStringList{QStringLiteral("t.json: the file has %1 bytes, more than the limit of 16777216 "
                                                  "bytes (16 MiB)").arg(big.size())});

    // From disk the size is checked before reading.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath("big.json");
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    QVERIFY(f.resize(20 * 1024 * 1024));
    f.close();
    const LoadResult fromDisk = LessonLoader::loadFile(path);
    QCOMPARE(fromDisk.errors(),
             QStringList{path + ": the file has 20971520 bytes, more than the limit of 16777216 bytes (16 MiB)"});
}

void TestLessonLoader::tooManyBalls()
{
    QByteArray balls = "[";
    for (int i = 0; i < 200001; ++i)
        balls += i ? ",{}" : "{}";
    balls += "]";
    const LoadResult r = loadText(minimal("\"balls\": " + balls));
    QVERIFY(!r.ok());
    QCOMPARE(r.errors(), QStringList{"t.json:1:26: balls: 200001 balls is more than the limit of 200000"});

    // Many bad balls: the list stops at 100 lines and counts the rest.
    const LoadResult many = loadText(minimal("\"balls\": [" + QByteArray("{}").repeated(150).replace("}{", "},{") + "]"));
    QCOMPARE(many.errors().size(), 101);
    QCOMPARE(many.errors().last(), QStringLiteral("t.json: 200 more problems not listed"));
}

void TestLessonLoader::semanticCheckFromTheCore()
{
    // The exact integrator needs a constant acceleration: sim::validateSettings says so with the key path,
    // and the loader adds the file and where in it the key is written (line 2, column 10 below).
    const LoadResult r = loadText(minimal("\n\"time\": {\"integrator\": \"exact\"}, \"models\": {\"drag\": {\"k\": 0.1}}"));
    QVERIFY(!r.ok());
    QCOMPARE(r.problems.size(), 1);
    const sim::Error& e = r.problems.first();
    QCOMPARE(e.source, std::string("t.json"));
    QCOMPARE(e.keyPath, std::string("time.integrator"));
    QCOMPARE(e.line, 2);
    QCOMPARE(e.column, 10);
    QVERIFY2(e.message.starts_with("exact needs a constant acceleration"), e.message.c_str());
    QCOMPARE(r.errors(), QStringList{errorLine(e)});
    QVERIFY2(r.errors().first().startsWith("t.json:2:10: time.integrator: exact needs"), qPrintable(r.errors().first()));
}

void TestLessonLoader::overrides()
{
    // A number, a bare word, JSON text, a new model, an array element, an appended ball.
    const LoadResult r = LessonLoader::load(
        QStringLiteral("gravity"),
        {{"models.gravity.y", "0"},
         {"time.integrator", "rk4"},
         {"world.walls", R"(["left", "right"])"},
         {"models.drag.k", "0.2"},
         {"balls.0.vx", "5"},
         {"balls.4", R"({"x": 1, "y": 2, "r": 3})"},
         {"title", "\"Gravity, modified\""}});
    QVERIFY2(r.ok(), qPrintable(r.errors().join(" | ")));
    const sim::WorldSettings& s = r.lesson->scene.settings;
    QVERIFY(s.gravity.enabled);
    QCOMPARE(s.gravity.g.y(), 0.0);
    COMPARE_ENUM(s.time.integrator, sim::IntegratorKind::Rk4);
    QVERIFY(s.walls.left && s.walls.right && !s.walls.top && !s.walls.bottom);
    QVERIFY(s.drag.enabled);
    QCOMPARE(s.drag.k, 0.2);
    COMPARE_ENUM(s.drag.law, sim::DragLaw::Linear);
    QCOMPARE(r.lesson->scene.balls.size(), std::size_t{5});
    QCOMPARE(r.lesson->scene.balls[0].velocity.x(), 5.0);
    QCOMPARE(r.lesson->scene.balls[4].radius, 3.0);
    QCOMPARE(r.lesson->title, QStringLiteral("Gravity, modified"));

    // Later overrides win.
    const LoadResult twice = loadText(minimal(), {{"time.dt", "0.1"}, {"time.dt", "0.01"}});
    QVERIFY(twice.ok());
    QCOMPARE(twice.lesson->scene.settings.time.dt, 0.01);

    // Number forms JSON refuses but people type.
    const LoadResult forms = loadText(minimal(), {{"time.dt", ".5"}, {"models.gravity.y", "+9.5"}});
    QVERIFY2(forms.ok(), qPrintable(forms.errors().join(" | ")));
    QCOMPARE(forms.lesson->scene.settings.time.dt, 0.5);
    QCOMPARE(forms.lesson->scene.settings.gravity.g.y(), 9.5);
}

void TestLessonLoader::badOverrides_data()
{
    QTest::addColumn<QString>("keyPath");
    QTest::addColumn<QString>("value");
    QTest::addColumn<QString>("error");
    QTest::newRow("unknown model") << "models.gravty.y" << "1"
                                   << R"(--set models.gravty.y=1: models.gravty: unknown key "gravty"; did you mean "gravity"?)";
    QTest::newRow("unknown leaf") << "models.gravity.z" << "1"
                                  << R"(--set models.gravity.z=1: models.gravity.z: unknown key "z"; known keys here: enabled, x, y)";
    QTest::newRow("wrong type") << "time.dt" << "abc"
                                << R"(--set time.dt=abc: time.dt: expected a number in (0, 1] s, got the string "abc")";
    QTest::newRow("out of range") << "time.dt" << "5" << "--set time.dt=5: time.dt: 5 is outside (0, 1] s";
    QTest::newRow("nan") << "time.dt" << "nan"
                         << "--set time.dt=nan: time.dt: nan is not a finite number; NaN and infinity are not allowed";
    QTest::newRow("inf") << "models.gravity.y" << "-Infinity"
                         << "--set models.gravity.y=-Infinity: models.gravity.y: -Infinity is not a finite number; NaN "
                            "and infinity are not allowed";
    QTest::newRow("overflow") << "time.dt" << "1e999"
                              << "--set time.dt=1e999: time.dt: 1e999 is too large or too small for a double; infinity "
                                 "is not allowed";
    QTest::newRow("bad enum") << "models.wind.mode" << "gust"
                              << R"(--set models.wind.mode=gust: models.wind.mode: "gust" is not one of off, random, smoothed, noise, pointer)";
    QTest::newRow("index past the end") << "balls.9.x" << "1"
                                        << "--set balls.9.x=1: balls.9: index 9 is past the end (the array has 4 entries)";
    // The override made ball 4, so its missing y is the override's, not the
    // file's (before: ":/lessons/07-gravity.json:18:3: balls.4.y: missing").
    QTest::newRow("a ball the override made") << "balls.4.x" << "1"
                                              << "--set balls.4.x=1: balls.4.y: missing; give the ball's centre y in px";
    QTest::newRow("key into a number") << "models.gravity.y.z" << "1"
                                       << "--set models.gravity.y.z=1: models.gravity.y: is a number, so it has no key \"z\"";
    QTest::newRow("word into an array") << "balls.first" << "1"
                                        << "--set balls.first=1: balls.first: balls is an array; expected an index such "
                                           "as balls.0";
}

void TestLessonLoader::badOverrides()
{
    QFETCH(QString, keyPath);
    QFETCH(QString, value);
    QFETCH(QString, error);
    const LoadResult r = LessonLoader::load(QStringLiteral("gravity"), {{keyPath, value}});
    QVERIFY(!r.ok());
    QCOMPARE(r.errors(), QStringList{error});
}

void TestLessonLoader::parseOverride()
{
    QString error;
    const auto o = LessonLoader::parseOverride(QStringLiteral("models.gravity.y=0"), &error);
    QVERIFY(o);
    QCOMPARE(o->keyPath, QStringLiteral("models.gravity.y"));
    QCOMPARE(o->value, QStringLiteral("0"));
    const auto withEquals = LessonLoader::parseOverride(QStringLiteral("text=a=b"), &error);
    QVERIFY(withEquals);
    QCOMPARE(withEquals->value, QStringLiteral("a=b"));

    QVERIFY(!LessonLoader::parseOverride(QStringLiteral("novalue"), &error));
    QCOMPARE(error, QStringLiteral("expected KEY.PATH=VALUE, e.g. models.gravity.y=0"));
    QVERIFY(!LessonLoader::parseOverride(QStringLiteral("=3"), &error));
    QVERIFY(!LessonLoader::parseOverride(QStringLiteral("models..y=3"), &error));
    QCOMPARE(error, QStringLiteral("\"models..y\" is not a key path; write keys separated by dots, e.g. models.gravity.y"));
}

void TestLessonLoader::saveLoadRoundTripIsBitIdentical()
{
    // Every setting away from its default, with values whose decimal form is long.
    Lesson l;
    l.id = QStringLiteral("round-trip");
    l.title = QStringLiteral("Quotes \" and \\ backslashes, tabs\t, ünïcödé ✓");
    l.stage = 31;
    l.text = QStringLiteral("<p>Line one\nline two\r\n</p>\x01");
    l.challenges = {QStringLiteral("a"), QStringLiteral("b \"c\"")};
    l.controls = {QStringLiteral("gravity")};
    l.overlays = {QStringLiteral("readout"), QStringLiteral("velocity")};
    sim::WorldSettings& s = l.scene.settings;
    s.box = {0.1 + 0.2, 1.0 / 3.0 * 1000.0};
    s.walls = {false, true, false, true, sim::WallModel::Reverse, 0.1 + 0.7, true, true};
    s.time = {sim::IntegratorKind::Yoshida4, 1.0 / 97.0, 7, 3.3e-11, (std::uint64_t{1} << 60) + 12345, true};
    s.gravity = {true, sim::Vec2(-0.0001234567890123, 979.99999999999989)};
    s.drag = {false, sim::DragLaw::Quadratic, 2.0 / 3.0, sim::ForceScale::None}; // off but not default: kept with "enabled": false
    s.wind = {sim::WindMode::Off, 12.345678901234567, sim::ForceScale::Radius, 0.123456789, 0.7,
              sim::WindMode::Noise};
    s.randomAccel = {true, true, 1.0 / 3.0};
    s.point = {true, sim::PointKind::Repel, sim::Vec2(1e-300, -5e6), 1.2345e14, 1e9, sim::ForceScale::Mass};
    s.spring = {true, sim::Vec2(std::nextafter(300.0, 301.0), 0.1 * 3), 4.000000000000001};
    s.mutualGravity = {true, -1e12, 5e-324};
    s.homing = {true, 1e6};
    s.pointer = {false, 3e6, 0.0};
    s.speedLimit = {true, 1e9};
    s.collisions = {sim::Detection::Brute, sim::Response::Axis2D, 0.3, true};
    sim::Ball a;
    a.position = {0.1 + 0.2, -1e7}; // above the box, where no wall is (below it the bottom wall refuses it)
    a.velocity = {-1e7, 1.0 / 7.0};
    a.radius = 1e-3;
    a.mass = 1e15;
    a.charge = -1.0 / 3.0;
    a.color = 0x0a0b0c;
    a.pinned = true;
    a.restitution = 0.1 + 0.2;
    sim::Ball b;
    b.radius = 1e-4; // mass 0: the sphere mass, written without "mass"; colliding, so it must fit the tiny box
    l.scene.balls = {a, b};
    l.scene.spawn = {17,   0.5,   0.5 + 1e-12, 0.0, 1e7, ~std::uint64_t{0}, {0xffffff, 0x000000, 0x123456},
                     true, false, 0.1 + 0.2,   101}; // 101 colliding balls of 0.5 px fit the tiny box

    const QByteArray saved = saveLesson(l);
    const LoadResult r = loadText(saved);
    QVERIFY2(r.ok(), qPrintable(r.errors().join(" | ") + "\n" + saved));
    compareLessons(l, *r.lesson);
    QCOMPARE(saveLesson(*r.lesson), saved);
    QVERIFY(saved.contains("\"x\": 0.30000000000000004"));
    QVERIFY(saved.contains("\"drag\": {\"enabled\": false, \"law\": \"quadratic\""));
    QVERIFY2(saved.contains("\"scale\": \"none\"}"), saved.constData()); // drag's scale, the last of its keys
    QVERIFY(saved.contains("\"pointer\": {\"enabled\": false"));
    QVERIFY(saved.contains("\"random_accel\": {\"fixed\": true"));
    QVERIFY(saved.contains("\"wall_model\": \"reverse\""));
    QCOMPARE(saved.count("\"pinned\": true"), 1); // the free ball does not say so
    QCOMPARE(saved.count("\"restitution\": 0.30000000000000004"), 1); // nor does the ball with the world's e

    // Random acceleration switched off but changed is remembered as "enabled": false.
    l.scene.settings.randomAccel.enabled = false;
    const QByteArray off = saveLesson(l);
    QVERIFY(off.contains("\"random_accel\": {\"enabled\": false"));
    compareLessons(l, *loadText(off).lesson);

    // Defaults that are off stay out of the file.
    const QByteArray plain = saveLesson(*loadText(minimal()).lesson);
    QVERIFY2(plain.contains("\"models\": {}"), plain.constData());
    compareLessons(*loadText(minimal()).lesson, *loadText(plain).lesson);
}

void TestLessonLoader::builtInLessonsRoundTrip()
{
    for (const QString& f : LessonLoader::builtInFiles()) {
        const LoadResult first = LessonLoader::load(f);
        QVERIFY2(first.ok(), qPrintable(first.errors().join(" | ")));
        const QByteArray saved = saveLesson(*first.lesson);
        QTemporaryDir dir;
        const QString path = dir.filePath("saved.json");
        QFile out(path);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(saved);
        out.close();
        const LoadResult second = LessonLoader::load(path);
        QVERIFY2(second.ok(), qPrintable(second.errors().join(" | ")));
        QCOMPARE(second.lesson->source, path);
        compareLessons(*first.lesson, *second.lesson);
    }
}

// Every row of the parameter table through the two text paths: set to a value
// other than its default with --set KEY.PATH=VALUE on a minimal lesson, it
// lands in its field bit for bit; saved and loaded back, it is still there.
// (The four wall switches are a list in the file, "walls": […], which the
// overrides test sets.)
void TestLessonLoader::everyParameterRoundTrips()
{
    int checked = 0;
    for (const sim::Parameter& p : sim::parameters()) {
        if (p.key.substr(0, 12) == "world.walls.")
            continue;
        const double v = forcelab::test::anotherValue(p, sim::defaultValue(p));
        QString text;
        switch (p.type) {
        case sim::ParameterType::Boolean:
            text = v != 0.0 ? QStringLiteral("true") : QStringLiteral("false");
            break;
        case sim::ParameterType::Choice:
            text = QString::fromUtf8(p.choices()[static_cast<std::size_t>(v)].data());
            break;
        default:
            text = QString::number(v, 'g', 17);
        }
        const QString key = QString::fromUtf8(p.key.data(), static_cast<qsizetype>(p.key.size()));
        const LoadResult set = LessonLoader::loadBytes(minimal(), QStringLiteral("t.json"), {{key, text}});
        QVERIFY2(set.ok(), qPrintable(key + ": " + set.errors().join(" | ")));
        QVERIFY2(bits(p.get(set.lesson->scene.settings)) == bits(v), qPrintable(key));
        const LoadResult back = LessonLoader::loadBytes(saveLesson(*set.lesson), QStringLiteral("saved.json"));
        QVERIFY2(back.ok(), qPrintable(key + ": " + back.errors().join(" | ")));
        QVERIFY2(bits(p.get(back.lesson->scene.settings)) == bits(v), qPrintable(key));
        ++checked;
    }
    QCOMPARE(checked, static_cast<int>(sim::parameters().size()) - 4);
}

QTEST_GUILESS_MAIN(TestLessonLoader)
#include "test_lesson_loader.moc"
