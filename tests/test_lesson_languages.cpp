// A lesson in several languages (lessons/lesson_languages.h): a file's
// "languages" load field for field, show in place of its own words and fall
// back to them; a translation with other counts or other numbers is refused
// with one line naming the file and the field; the sentence check reads a
// translation in its own number format; save -> load keeps every language;
// and every built-in lesson speaks every shipped language (German and
// Spanish), with every sentence that has a number backed by its own quote
// of a claim.

#include "lessons/lesson_languages.h"
#include "lessons/lesson_loader.h"
#include "lessons/sentence_check.h"
#include "ui/window/language.h"

#include <QtTest>

using namespace forcelab;

namespace {

const QString kSrc = QStringLiteral("t.json");

/// A small lesson with one claim, one not_measured entry, one challenge and
/// its answer, and `languages` spliced in.
QByteArray lessonWith(const QByteArray& languages)
{
    return R"({"format": 1, "id": "t", "title": "Drop",
  "text": "<p>The ball falls 330 px. With e = 0.8 it rises 211 px.</p>",
  "challenges": ["Set e to 0.5."],
  "world": {"width": 600, "height": 400, "walls": ["bottom"]},
  "models": {"gravity": {"y": 980}},
  "balls": [{"x": 300, "y": 40, "vx": 0, "vy": 0, "r": 10}],
  "claims": [{"says": "it rises 211 px", "measure": "apex", "ball": 0, "n": 1, "at": 10, "near": 211, "within_percent": 50}],
  "not_measured": [{"says": "Set e to 0.5.", "because": "instruction"},
                   {"says": "The ball falls 330 px.", "because": "unmeasured", "why": "330 px from 40 to 370"}],
  "teacher": {"goal": "Restitution keeps a share of the speed.", "answers": ["It bounces back, not as high."]})" +
           (languages.isEmpty() ? QByteArray() : ",\n  \"languages\": " + languages) + "}";
}

const QByteArray kGerman = R"({"de": {"title": "Fall",
  "text": "<p>Die Kugel fällt 330 px. Mit e = 0,8 steigt sie 211 px hoch.</p>",
  "challenges": ["Stelle e auf 0,5."],
  "teacher": {"goal": "Die Stoßzahl behält einen Teil der Geschwindigkeit.", "answers": ["Der Sprung ist niedriger."]},
  "claims": ["steigt sie 211 px hoch"],
  "not_measured": [{"says": "Stelle e auf 0,5."}, {"says": "Die Kugel fällt 330 px.", "why": "330 px von 40 bis 370"}]}})";

} // namespace

class TestLessonLanguages : public QObject {
    Q_OBJECT

private slots:
    void aTranslationShowsInPlaceOfTheLessonsWords()
    {
        const LoadResult r = LessonLoader::loadBytes(lessonWith(kGerman), kSrc);
        QVERIFY2(r.ok(), qPrintable(r.errors().join('\n')));
        const Lesson& own = *r.lesson;
        QCOMPARE(own.language, QStringLiteral("en"));
        QCOMPARE(own.languages.keys(), QStringList{QStringLiteral("de")});

        const Lesson de = lessons::shownIn(own, QStringLiteral("de"));
        QCOMPARE(de.language, QStringLiteral("de"));
        QCOMPARE(de.title, QStringLiteral("Fall"));
        QCOMPARE(de.challenges, QStringList{QStringLiteral("Stelle e auf 0,5.")});
        QCOMPARE(de.claims[0].text, std::string("steigt sie 211 px hoch"));
        QCOMPARE(de.notMeasured[1].why, QStringLiteral("330 px von 40 bis 370"));
        QCOMPARE(de.teacher.answers, QStringList{QStringLiteral("Der Sprung ist niedriger.")});
        // The English words wait under "en", the German ones are no longer listed.
        QCOMPARE(de.languages.keys(), QStringList{QStringLiteral("en")});
        // The claim itself (what it measures and the value) is the lesson's.
        QCOMPARE(de.claims[0].measure, own.claims[0].measure);
        QCOMPARE(de.claims[0].value, own.claims[0].value);

        // Back to English gives the lesson as loaded.
        const Lesson back = lessons::shownIn(de, QStringLiteral("en"));
        QCOMPARE(back.title, own.title);
        QCOMPARE(back.text, own.text);
        QCOMPARE(back.claims[0].text, own.claims[0].text);
        QVERIFY(back.languages == own.languages);

        // A language the lesson lacks: its own words, in its own language.
        const Lesson fr = lessons::shownIn(de, QStringLiteral("fr"));
        QCOMPARE(fr.language, QStringLiteral("en"));
        QCOMPARE(fr.title, QStringLiteral("Drop"));
    }

    void saveWritesTheFilesOwnWordsWhateverIsShown()
    {
        const LoadResult r = LessonLoader::loadBytes(lessonWith(kGerman), kSrc);
        QVERIFY(r.ok());
        const QByteArray saved = saveLesson(lessons::shownIn(*r.lesson, QStringLiteral("de")));
        const LoadResult again = LessonLoader::loadBytes(saved, kSrc);
        QVERIFY2(again.ok(), qPrintable(again.errors().join('\n') + "\n" + QString::fromUtf8(saved)));
        QCOMPARE(again.lesson->language, QStringLiteral("en"));
        QCOMPARE(again.lesson->title, QStringLiteral("Drop"));
        QVERIFY(again.lesson->languages == r.lesson->languages);
        QVERIFY(!saved.contains("\"language\":")); // an English file says nothing about it, as before
    }

    void aFileInAnotherLanguageFallsBackToItself()
    {
        // A German teacher's own lesson: German words, no translation.
        QByteArray json = lessonWith({});
        json.replace(R"("id": "t",)", R"("id": "t", "language": "de",)");
        json.replace("e = 0.8", "e = 0,8");
        json.replace("\"Set e to 0.5.\"", "\"Set e to 0,5.\"");
        const LoadResult r = LessonLoader::loadBytes(json, kSrc);
        QVERIFY2(r.ok(), qPrintable(r.errors().join('\n')));
        QCOMPARE(r.lesson->fileLanguage, QStringLiteral("de"));
        const Lesson en = lessons::shownIn(*r.lesson, QStringLiteral("en"));
        QCOMPARE(en.language, QStringLiteral("de"));
        // Its sentences are read with decimal commas: "0,5" is one number.
        const QStringList problems = lessons::checkSentences(*r.lesson).problems;
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join('\n')));
        QVERIFY(saveLesson(*r.lesson).contains("\"language\": \"de\""));
    }

    void aTranslationOfAnotherShapeIsOneLineNamingTheField()
    {
        QByteArray bad = kGerman;
        bad.replace(R"("challenges": ["Stelle e auf 0,5."],)", R"("challenges": ["Stelle e auf 0,5.", "Noch eine."],)");
        const LoadResult r = LessonLoader::loadBytes(lessonWith(bad), kSrc);
        QVERIFY(!r.ok());
        QCOMPARE(r.errors().size(), 1);
        QVERIFY2(r.errors()[0].contains("t.json") && r.errors()[0].contains("languages.de.challenges") &&
                     r.errors()[0].contains("2 entries; the lesson has 1"),
                 qPrintable(r.errors()[0]));
    }

    void aTranslationWithOtherNumbersIsRefused()
    {
        QByteArray bad = kGerman;
        bad.replace("Mit e = 0,8", "Mit e = 0,9");
        const LoadResult r = LessonLoader::loadBytes(lessonWith(bad), kSrc);
        QVERIFY(!r.ok());
        QCOMPARE(r.errors().size(), 1);
        QVERIFY2(r.errors()[0].contains("languages.de.text") && r.errors()[0].contains("0.9") &&
                     r.errors()[0].contains("0.8"),
                 qPrintable(r.errors()[0]));
        // An English decimal point in a German text is another number too.
        bad = kGerman;
        bad.replace("Mit e = 0,8", "Mit e = 0.8");
        QVERIFY(!LessonLoader::loadBytes(lessonWith(bad), kSrc).ok());
    }

    void badLanguageCodesAreRefused()
    {
        for (const QByteArray& code : {QByteArray("../x"), QByteArray("DE"), QByteArray("en")}) {
            QByteArray json = lessonWith("{\"" + code + "\": {}}");
            const LoadResult r = LessonLoader::loadBytes(json, kSrc);
            QVERIFY2(!r.ok(), code.constData());
            QVERIFY2(r.errors().join('\n').contains("languages." + QString::fromUtf8(code)),
                     qPrintable(r.errors().join('\n')));
        }
    }

    void numbersAreReadTheLanguagesWay()
    {
        const std::vector<double> want{0.8, 1200.0};
        QCOMPARE(lessons::numbersOf(QStringLiteral("0.8 and 1,200 px, in 2D with RK4"), QStringLiteral("en")), want);
        QCOMPARE(lessons::numbersOf(QStringLiteral("0,8 und 1.200 px, in 2D mit RK4"), QStringLiteral("de")), want);
        QCOMPARE(lessons::numbersOf(QStringLiteral("0,8 y 1200 px"), QStringLiteral("es")), want);
    }

    void aTranslatedSentenceWithANumberNeedsItsOwnQuote()
    {
        // Split as the English is not, "Mit e = 0,8." stands alone, and the
        // claim's quote does not lie in it.
        QByteArray bad = kGerman;
        bad.replace("Mit e = 0,8 steigt sie 211 px hoch.", "Mit e = 0,8. Steigt sie 211 px hoch.");
        bad.replace(R"("claims": ["steigt sie 211 px hoch"])", R"("claims": ["Steigt sie 211 px hoch"])");
        const LoadResult r = LessonLoader::loadBytes(lessonWith(bad), kSrc);
        QVERIFY2(r.ok(), qPrintable(r.errors().join('\n')));
        const QStringList problems = lessons::checkSentences(lessons::shownIn(*r.lesson, QStringLiteral("de"))).problems;
        QCOMPARE(problems.size(), 1);
        QVERIFY2(problems[0].contains("\"Mit e = 0,8.\"") && problems[0].contains("\"0,8\""),
                 qPrintable(problems[0]));
        // The English is untouched by the German's problem.
        QVERIFY(lessons::checkSentences(*r.lesson).problems.isEmpty());
    }

    void everyBuiltInLessonSpeaksEveryShippedLanguage()
    {
        // The program's languages besides English (View → Language).
        QStringList shipped;
        for (const Language& l : shippedLanguages())
            if (l.code != QLatin1String("en"))
                shipped << l.code;
        shipped.sort();
        QVERIFY(!shipped.isEmpty());
        for (const QString& file : LessonLoader::builtInFiles()) {
            const LoadResult r = LessonLoader::load(file);
            QVERIFY2(r.ok(), qPrintable(r.errors().join('\n')));
            QCOMPARE(r.lesson->languages.keys(), shipped);
            for (const QString& code : r.lesson->languages.keys()) {
                const Lesson shown = lessons::shownIn(*r.lesson, code);
                const QStringList problems = lessons::checkSentences(shown).problems;
                QVERIFY2(problems.isEmpty(), qPrintable(file + " [" + code + "]: " + problems.join('\n')));
                QVERIFY2(shown.text != r.lesson->text, qPrintable(file + " [" + code + "]: the text is the English"));
            }
        }
    }
};

QTEST_GUILESS_MAIN(TestLessonLanguages)
#include "test_lesson_languages.moc"
