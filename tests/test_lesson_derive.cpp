// A lesson made from a lesson and the scene on screen (lessons/lesson_derive.h):
// from every shipped lesson, with its scene as it starts and with one ball
// sped up, the saved file reopens with the same scene bit for bit, loads
// without a problem and every claim it keeps holds; the sentence check has
// nothing to say. Lesson 29 with a faster red ball drops the claims about
// the velocities after the hit and says what they measured.

#include "lessons/atomic_file.h"
#include "lessons/lesson_derive.h"
#include "lessons/lesson_loader.h"
#include "lessons/sentence_check.h"
#include "sim/world/parameters.h"

#include "cli_runner.h"

#include <QDir>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cstring>

using namespace forcelab;

namespace {

bool sameBits(double a, double b)
{
    return std::memcmp(&a, &b, sizeof a) == 0;
}

/// The first difference of two scenes, bit for bit; empty when there is none.
QString sceneDifference(const sim::Scene& a, const sim::Scene& b)
{
    for (const sim::Parameter& p : sim::parameters())
        if (p.get && !sameBits(p.get(a.settings), p.get(b.settings)))
            return QString::fromUtf8(p.key.data(), qsizetype(p.key.size()));
    if (a.settings.time.seed != b.settings.time.seed)
        return QStringLiteral("time.seed");
    const sim::CustomForceSettings &c = a.settings.custom, &d = b.settings.custom;
    if (c.enabled != d.enabled || c.acceleration != d.acceleration || c.fx != d.fx || c.fy != d.fy ||
        c.potential != d.potential || c.constants.size() != d.constants.size())
        return QStringLiteral("models.custom");
    for (std::size_t i = 0; i < c.constants.size(); ++i)
        if (c.constants[i].name != d.constants[i].name || !sameBits(c.constants[i].value, d.constants[i].value) ||
            !sameBits(c.constants[i].min, d.constants[i].min) || !sameBits(c.constants[i].max, d.constants[i].max))
            return QStringLiteral("models.custom.constants.%1").arg(i);
    if (a.balls.size() != b.balls.size())
        return QStringLiteral("the number of balls");
    for (std::size_t i = 0; i < a.balls.size(); ++i) {
        const sim::Ball &x = a.balls[i], &y = b.balls[i];
        if (!sameBits(x.position.x(), y.position.x()) || !sameBits(x.position.y(), y.position.y()) ||
            !sameBits(x.velocity.x(), y.velocity.x()) || !sameBits(x.velocity.y(), y.velocity.y()) ||
            !sameBits(x.radius, y.radius) || !sameBits(x.mass, y.mass) || !sameBits(x.charge, y.charge) ||
            x.color != y.color)
            return QStringLiteral("ball %1").arg(i);
    }
    const sim::SpawnSettings &s = a.spawn, &t = b.spawn;
    if (s.count != t.count || !sameBits(s.minRadius, t.minRadius) || !sameBits(s.maxRadius, t.maxRadius) ||
        !sameBits(s.minSpeed, t.minSpeed) || !sameBits(s.maxSpeed, t.maxSpeed) || s.seed != t.seed ||
        s.palette != t.palette || s.horizontal != t.horizontal || s.fullyInside != t.fullyInside ||
        !sameBits(s.perStep, t.perStep) || s.maxCount != t.maxCount)
        return QStringLiteral("spawn");
    return {};
}

/// The scene with its first ball twice as fast (or, with no listed ball,
/// the random balls up to twice as fast).
sim::Scene changed(sim::Scene scene)
{
    if (!scene.balls.empty()) {
        sim::Ball& b = scene.balls.front();
        b.velocity = b.velocity.norm() > 0.0 ? sim::Vec2(2.0 * b.velocity) : sim::Vec2(30.0, 0.0);
    } else {
        scene.spawn.maxSpeed = 2.0 * scene.spawn.maxSpeed + 10.0;
    }
    return scene;
}

Lesson loaded(const QString& path)
{
    const LoadResult r = LessonLoader::loadFile(path);
    if (!r.ok())
        qFatal("%s", qPrintable(r.errors().join(QLatin1Char('\n'))));
    return *r.lesson;
}

} // namespace

class TestLessonDerive : public QObject {
    Q_OBJECT
private slots:
    void derivedLessonsReopenAndHold_data();
    void derivedLessonsReopenAndHold();
    void lesson29WithAFasterBallDropsWhatNoLongerHolds();
    void lesson29WithLessBounceKeepsMomentum();
    void typedTextIsEscapedAndItsNumbersRefused();
    void idsAreValidAndNew();
    void progressCanStopIt();
};

void TestLessonDerive::derivedLessonsReopenAndHold_data()
{
    QTest::addColumn<QString>("path");
    QTest::addColumn<bool>("change");
    const QDir dir(QStringLiteral(FORCELAB_LESSON_DIR));
    const QStringList files = dir.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name);
    QVERIFY(files.size() >= 40);
    for (const QString& f : files) {
        QTest::newRow(qPrintable(f + QStringLiteral(" as it starts"))) << dir.filePath(f) << false;
        QTest::newRow(qPrintable(f + QStringLiteral(" with a faster ball"))) << dir.filePath(f) << true;
    }
}

void TestLessonDerive::derivedLessonsReopenAndHold()
{
    QFETCH(QString, path);
    QFETCH(bool, change);
    const Lesson from = loaded(path);
    const sim::Scene scene = change ? changed(from.scene) : from.scene;

    lessons::DeriveChoices choices = lessons::defaultDeriveChoices(from);
    choices.keepTeacherNotes = true;
    const lessons::DerivedLesson derived = lessons::deriveLesson(from, scene, choices);
    QVERIFY2(derived.ok(), qPrintable(derived.problems.join(QLatin1Char('\n'))));
    QCOMPARE(derived.lesson.claims.size() + derived.droppedClaims.size(), from.claims.size());
    QCOMPARE(derived.lesson.predict.size() + derived.droppedPredictions.size(), from.predict.size());
    if (!change)
        for (const lessons::DroppedClaim& d : derived.droppedClaims)
            QVERIFY2(!d.failed, qPrintable(d.says + QStringLiteral(": ") + d.why)); // they held before

    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString file = dir.filePath(QStringLiteral("derived.json"));
    QString why;
    QVERIFY2(lessons::writeFileAtomically(file, saveLesson(derived.lesson), &why), qPrintable(why));
    const Lesson back = loaded(file); // `forcelab-cli validate` reads it so

    QCOMPARE(sceneDifference(back.scene, scene), QString());
    QCOMPARE(back.title, QStringLiteral("Based on %1").arg(from.title));
    QVERIFY(back.id != from.id);
    QCOMPARE(back.stage, lessons::kDerivedStage);
    QVERIFY(back.challenges.isEmpty());
    QVERIFY(back.teacher.answers.isEmpty());
    QCOMPARE(back.claims, derived.lesson.claims);
    QVERIFY(back.text.contains(lessons::creditSentence(from).toHtmlEscaped()));
    // What `forcelab-cli check` runs: every claim holds, every sentence with a number is backed.
    for (const sim::Claim& claim : back.claims) {
        const sim::ClaimResult r = sim::checkClaim(back.scene, claim);
        QVERIFY2(r.holds, qPrintable(QString::fromStdString(sim::describe(claim, r))));
    }
    const lessons::SentenceReport report = lessons::checkSentences(back);
    QVERIFY2(report.problems.isEmpty(), qPrintable(report.problems.join(QLatin1Char('\n'))));
    for (const Prediction& p : back.predict)
        QVERIFY(p.claim >= 0 && std::size_t(p.claim) < back.claims.size());
}

void TestLessonDerive::lesson29WithAFasterBallDropsWhatNoLongerHolds()
{
    const Lesson from = loaded(QStringLiteral(FORCELAB_LESSON_DIR "/29-the-line-of-impact.json"));
    QCOMPARE(from.claims.size(), std::size_t(17));
    sim::Scene scene = from.scene;
    QCOMPARE(scene.balls[0].velocity.x(), 40.0);
    scene.balls[0].velocity = sim::Vec2(80.0, 0.0); // the red ball twice as fast

    lessons::DeriveChoices choices = lessons::defaultDeriveChoices(from);
    choices.title = QStringLiteral("A faster red ball");
    const lessons::DerivedLesson derived = lessons::deriveLesson(from, scene, choices);
    QVERIFY2(derived.ok(), qPrintable(derived.problems.join(QLatin1Char('\n'))));

    // The blue ball's velocity after the hit doubles with the red one's:
    // claim 0 said 25.2 px/s and now measures 51.2 px/s. Before 6 s a ball
    // now also reaches a wall, so momentum is no longer kept either: every
    // claim about the text fails; those about challenges and answers are
    // dropped with them, since the new lesson has neither.
    QCOMPARE(derived.lesson.claims.size(), std::size_t(0));
    QCOMPARE(derived.droppedClaims.size(), std::size_t(17));
    for (const lessons::DroppedClaim& d : derived.droppedClaims)
        QVERIFY2(d.failed == (d.index < 8), qPrintable(QStringLiteral("%1: %2").arg(d.index).arg(d.why)));
    QCOMPARE(derived.droppedClaims[0].says, QStringLiteral("the readouts show about (25.2, 19.3) px/s for blue"));
    QCOMPARE(derived.droppedClaims[0].why, QStringLiteral("measured 51.2 px/s, stated 25.2 px/s ± 0.05 px/s"));
    QCOMPARE(derived.droppedClaims[14].why,
             QStringLiteral("its sentence is in answer 3, which the new lesson does not keep"));
    // The one question was answered by claim 0.
    QVERIFY(derived.lesson.predict.empty());
    QCOMPARE(derived.droppedPredictions.size(), std::size_t(1));
    QCOMPARE(derived.droppedPredictions[0].ask, from.predict[0].ask);
    QVERIFY(derived.droppedPredictions[0].why.contains(QStringLiteral("measured 51.2 px/s")));
    const QString summary = lessons::deriveSummary(derived);
    QVERIFY2(summary.startsWith(QStringLiteral("Kept 0 of 17 claims and 0 of 1 questions. Dropped claims: "
                                               "“the readouts show about (25.2, 19.3) px/s for blue” (measured 51.2 "
                                               "px/s, stated 25.2 px/s ± 0.05 px/s);")),
             qPrintable(summary));
    QVERIFY2(summary.contains(QStringLiteral("Dropped questions: “%1”").arg(from.predict[0].ask)), qPrintable(summary));

    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString file = dir.filePath(QStringLiteral("faster-red.json"));
    QString why;
    QVERIFY2(lessons::writeFileAtomically(file, saveLesson(derived.lesson), &why), qPrintable(why));
    const test::CliResult check = test::runCli({QStringLiteral("check"), file});
    QVERIFY2(check.exitCode == 0, qPrintable(check.out + check.err));
}

void TestLessonDerive::lesson29WithLessBounceKeepsMomentum()
{
    const Lesson from = loaded(QStringLiteral(FORCELAB_LESSON_DIR "/29-the-line-of-impact.json"));
    sim::Scene scene = from.scene;
    scene.settings.collisions.restitution = 0.5;

    lessons::DeriveChoices choices = lessons::defaultDeriveChoices(from);
    choices.title = QStringLiteral("Less bounce");
    choices.text = QStringLiteral("The balls give back less of their closing speed now.\n\n"
                                  "Watch the angle <between> the paths & the arrows.");
    choices.ids = {QStringLiteral("the-line-of-impact"), QStringLiteral("less-bounce")};
    choices.keepTeacherNotes = true;
    const lessons::DerivedLesson derived = lessons::deriveLesson(from, scene, choices);
    QVERIFY2(derived.ok(), qPrintable(derived.problems.join(QLatin1Char('\n'))));
    QCOMPARE(derived.lesson.id, QStringLiteral("less-bounce")); // never the old id

    // Momentum is kept in every collision, whatever e: claims 4 and 5 stay,
    // and so do 15 and 16, about e = 0.5, in the kept misconception.
    QCOMPARE(derived.lesson.claims.size(), std::size_t(4));
    QCOMPARE(derived.lesson.claims[0], from.claims[4]);
    QCOMPARE(derived.lesson.claims[1], from.claims[5]);
    QCOMPARE(derived.lesson.claims[2], from.claims[15]);
    QCOMPARE(derived.lesson.claims[3], from.claims[16]);
    QCOMPARE(derived.lesson.teacher.misconceptions, from.teacher.misconceptions);
    QCOMPARE(derived.lesson.teacher.goal, from.teacher.goal);
    QVERIFY(derived.lesson.teacher.answers.isEmpty());
    QVERIFY(derived.droppedNotes.isEmpty());
    QVERIFY(derived.droppedClaims[0].failed);
    QVERIFY(derived.droppedClaims[0].why.startsWith(QStringLiteral("measured ")));

    // The file passes `forcelab-cli validate` and `forcelab-cli check`.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString file = dir.filePath(QStringLiteral("less-bounce.json"));
    QString why;
    QVERIFY2(lessons::writeFileAtomically(file, saveLesson(derived.lesson), &why), qPrintable(why));
    const test::CliResult validate = test::runCli({QStringLiteral("validate"), file});
    QVERIFY2(validate.exitCode == 0, qPrintable(validate.out + validate.err));
    const test::CliResult check = test::runCli({QStringLiteral("check"), file});
    QVERIFY2(check.exitCode == 0, qPrintable(check.out + check.err));
    QVERIFY2(check.out.contains(QStringLiteral("4 claims in 1 of 1 lesson: all hold")), qPrintable(check.out));
    const Lesson back = loaded(file);
    QCOMPARE(back.title, QStringLiteral("Less bounce"));
    const QStringList sentences = lessons::splitSentences(back.text);
    QCOMPARE(sentences.value(1), QStringLiteral("Watch the angle <between> the paths & the arrows."));
    QCOMPARE(sentences.value(3), QStringLiteral("An impulse j = −(1 + e) v_n / (1/m₁ + 1/m₂) changes their velocities: "
                                                "v₁ − (j/m₁) n and v₂ + (j/m₂) n."));
}

void TestLessonDerive::typedTextIsEscapedAndItsNumbersRefused()
{
    QCOMPARE(lessons::plainToMarkup(QStringLiteral("a < b & c\nnext line\n\n  second ")),
             QStringLiteral("<p>a &lt; b &amp; c<br>next line</p><p>second</p>"));
    const Lesson from = loaded(QStringLiteral(FORCELAB_LESSON_DIR "/19-two-bodies-in-orbit.json"));
    // The credit sentence names "Two bodies", another lesson: it may stay.
    QVERIFY(lessons::unmeasuredSentences(from, lessons::creditSentence(from)).isEmpty());
    const QStringList refused = lessons::unmeasuredSentences(
        from, lessons::creditSentence(from) + QStringLiteral(" The orbit takes 3 s. It is slow."));
    QCOMPARE(refused, QStringList{QStringLiteral("The orbit takes 3 s.")});
    lessons::DeriveChoices choices = lessons::defaultDeriveChoices(from);
    choices.text += QStringLiteral(" The orbit takes 3 s.");
    const lessons::DerivedLesson derived = lessons::deriveLesson(from, from.scene, choices);
    QVERIFY(!derived.ok());
    QVERIFY2(derived.problems.value(0).contains(QStringLiteral("“The orbit takes 3 s.”")),
             qPrintable(derived.problems.join(QLatin1Char('\n'))));
}

void TestLessonDerive::idsAreValidAndNew()
{
    const QString old = QStringLiteral("gravity");
    QCOMPARE(lessons::deriveId({QStringLiteral("my file"), QStringLiteral("gravity")}, QStringLiteral("Gravity"), old),
             QStringLiteral("gravity-saved"));
    QCOMPARE(lessons::deriveId({}, QStringLiteral("Based on Gravity: a <faster> drop!"), old),
             QStringLiteral("based-on-gravity-a-faster-drop"));
    QCOMPARE(lessons::deriveId({QStringLiteral("drop_2")}, QStringLiteral("x"), old), QStringLiteral("drop_2"));
    QCOMPARE(lessons::deriveId({}, QStringLiteral("Überall"), old), QStringLiteral("berall"));
    QCOMPARE(lessons::deriveId({}, QStringLiteral("???"), old), QStringLiteral("saved-scene"));
    QCOMPARE(lessons::deriveId({}, QString(80, QLatin1Char('a')), old).size(), 64);
}

void TestLessonDerive::progressCanStopIt()
{
    const Lesson from = loaded(QStringLiteral(FORCELAB_LESSON_DIR "/29-the-line-of-impact.json"));
    std::vector<double> seen;
    const lessons::DerivedLesson stopped =
        lessons::deriveLesson(from, from.scene, lessons::defaultDeriveChoices(from), [&](double done) {
            seen.push_back(done);
            return done < 0.1;
        });
    QVERIFY(stopped.cancelled);
    QVERIFY(!stopped.ok());
    QVERIFY(!seen.empty() && seen.back() >= 0.1 && seen.back() < 0.2); // claim 1 of 17 was running
    QVERIFY(std::is_sorted(seen.begin(), seen.end()));

    seen.clear();
    const lessons::DerivedLesson whole =
        lessons::deriveLesson(from, from.scene, lessons::defaultDeriveChoices(from), [&](double done) {
            seen.push_back(done);
            return true;
        });
    QVERIFY(whole.ok() && !whole.cancelled);
    QVERIFY(std::is_sorted(seen.begin(), seen.end()));
    QVERIFY(seen.back() <= 1.0);
}

QTEST_GUILESS_MAIN(TestLessonDerive)
#include "test_lesson_derive.moc"
