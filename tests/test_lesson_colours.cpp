// The colour names of lesson texts hold (issue #36): a ball a text calls "the
// red ball" is drawn in the listed red in the plain and the projector theme,
// and no other ball is drawn in a colour the text names. The drawn colour is
// drawnBallColor, which the balls overlay paints each disc with.

#include "lessons/colour_names.h"
#include "lessons/lesson_loader.h"
#include "sim/world/ball_state.h"
#include "sim/world/scene.h"
#include "sim/world/world.h"
#include "ui/drawing/palette.h"
#include "ui/drawing/world_painter.h"

#include <QColor>
#include <QDir>
#include <QImage>
#include <QPainter>
#include <QRegularExpression>
#include <QTest>

#include <map>
#include <set>

using namespace forcelab;

namespace {

QString hex(sim::Rgb c)
{
    return QStringLiteral("#%1").arg(c & 0xffffffu, 6, 16, QLatin1Char('0'));
}

QString themeName(bool projector)
{
    return projector ? QStringLiteral("projector") : QStringLiteral("plain");
}

// Everything a class reads about the scene: the text, the challenges, the
// questions and their choices, and the teacher's notes; lower case, no markup.
QString readText(const Lesson& lesson)
{
    QStringList parts{lesson.text};
    parts << lesson.challenges << lesson.teacher.goal << lesson.teacher.misconceptions << lesson.teacher.answers;
    for (const Prediction& p : lesson.predict)
        parts << p.ask << p.choices;
    static const QRegularExpression tag(QStringLiteral("<[^>]*>"));
    return parts.join(QLatin1Char('\n')).replace(tag, QStringLiteral(" ")).toLower();
}

// The listed colours the text names, each with the first word it is named by.
// Whole words only ("redo", "bluish", "reddish" are not colours), and a name
// is taken out once matched, so "sky blue" is not also "blue".
std::map<sim::Rgb, QString> namedColours(QString text)
{
    std::map<sim::Rgb, QString> named;
    for (const QString& word : lessons::colourWords()) {
        QString pattern = QRegularExpression::escape(word);
        pattern.replace(QStringLiteral("\\ "), QStringLiteral("\\s+"));
        const QRegularExpression re(QStringLiteral("\\b") + pattern + QStringLiteral("\\b"));
        if (text.contains(re)) {
            named.emplace(*lessons::colourOfName(word), word);
            text.replace(re, QStringLiteral(" "));
        }
    }
    return named;
}

} // namespace

class TestLessonColours : public QObject {
    Q_OBJECT
private slots:
    void listedColoursAreDistinctAndDrawnAsListed();
    void namesReadAndWordsMatch();
    void shippedLessonsDrawTheColoursTheirTextsName();
    void paintedBallsHaveTheirDrawnColour();
};

// Every name has its own colour, each theme draws it exactly, and the colours
// are far enough apart to be told apart on a projector.
void TestLessonColours::listedColoursAreDistinctAndDrawnAsListed()
{
    const auto names = lessons::colourNames();
    QVERIFY(names.size() >= 10);
    std::set<QString> words;
    for (std::size_t i = 0; i < names.size(); ++i) {
        const sim::Rgb c = names[i].color;
        for (bool projector : {false, true})
            QVERIFY2(drawnBallColor(c, canvasColors(projector)) == c,
                     qPrintable(hex(c) + " drawn as " + hex(drawnBallColor(c, canvasColors(projector))) + " in the " +
                                themeName(projector) + " theme"));
        QCOMPARE(okabeItoColor(c), c);
        for (std::string_view w : names[i].words)
            if (!w.empty())
                QVERIFY2(words.insert(QString::fromUtf8(w.data(), qsizetype(w.size()))).second, w.data());
        for (std::size_t j = 0; j < i; ++j) {
            const QColor a = QColor::fromRgb(c), b = QColor::fromRgb(names[j].color);
            const int d = std::abs(a.red() - b.red()) + std::abs(a.green() - b.green()) + std::abs(a.blue() - b.blue());
            QVERIFY2(d >= 90, qPrintable(hex(c) + " and " + hex(names[j].color) + " are too alike"));
        }
    }
    // The colours a text names are the ones a class calls so: red is reddest
    // (red over green and blue), purple has more blue than green and red
    // between them, sky blue is lighter than blue.
    const QColor red = QColor::fromRgb(*lessons::colourOfName("red"));
    QVERIFY(red.red() > 2 * red.green() && red.red() > 2 * red.blue());
    QVERIFY(red.hsvHueF() < 0.02 || red.hsvHueF() > 0.97);
    const QColor purple = QColor::fromRgb(*lessons::colourOfName("purple"));
    QVERIFY(purple.hsvHueF() > 0.72 && purple.hsvHueF() < 0.83); // between violet and magenta
    QVERIFY(QColor::fromRgb(*lessons::colourOfName("sky blue")).lightnessF() >
            QColor::fromRgb(*lessons::colourOfName("blue")).lightnessF() + 0.15);
    // A student's own colours land on the listed colour a class would call them.
    QCOMPARE(okabeItoColor(0xff0000), *lessons::colourOfName("red"));
    QCOMPARE(okabeItoColor(0xa03030), *lessons::colourOfName("red"));
    QCOMPARE(okabeItoColor(0x3090d0), *lessons::colourOfName("sky blue"));
    QCOMPARE(okabeItoColor(0x1040a0), *lessons::colourOfName("blue"));
    QCOMPARE(okabeItoColor(0x9060d0), *lessons::colourOfName("purple"));
    QCOMPARE(okabeItoColor(0x50b050), *lessons::colourOfName("green"));
    QCOMPARE(okabeItoColor(0xe0a030), *lessons::colourOfName("orange"));
}

void TestLessonColours::namesReadAndWordsMatch()
{
    QCOMPARE(lessons::colourOfName("Sky  Blue"), lessons::colourOfName("light blue"));
    QCOMPARE(lessons::colourOfName("gray"), lessons::colourOfName("grey"));
    QVERIFY(!lessons::colourOfName("purpel"));
    QVERIFY(!lessons::colourOfName("#e05050"));
    QCOMPARE(lessons::nameOfColour(*lessons::colourOfName("violet")), QStringLiteral("purple"));
    QVERIFY(lessons::nameOfColour(0x123456).isEmpty());
    const auto named = namedColours(QStringLiteral("redo the bluish, reddish run; the sky blue ball and the\nred one"));
    QCOMPARE(named.size(), std::size_t{2});
    QVERIFY(named.count(*lessons::colourOfName("sky blue")) && named.count(*lessons::colourOfName("red")));
    // A lesson may name its colours; they load as the listed colours and save as names.
    const QByteArray json = R"({"format": 1, "id": "t", "title": "t", "text": "t", "world": {"width": 100, "height": 100},
        "balls": [{"x": 10, "y": 10, "color": "purple"}, {"x": 50, "y": 50, "color": "#3090d0"}]})";
    const LoadResult r = LessonLoader::loadBytes(json, QStringLiteral("t.json"));
    QVERIFY2(r.ok(), qPrintable(r.errors().join('\n')));
    QCOMPARE(r.lesson->scene.balls.at(0).color, *lessons::colourOfName("purple"));
    QCOMPARE(r.lesson->scene.balls.at(1).color, sim::Rgb{0x3090d0});
    const QByteArray saved = saveLesson(*r.lesson);
    QVERIFY2(saved.contains(R"("color": "purple")") && saved.contains(R"("color": "#3090d0")"), saved.constData());
}

// For every colour word of a shipped lesson's text: some ball is drawn in
// that colour in both themes, every ball drawn in it has it as its own colour
// (so the plain theme shows the same), and no ball of another colour is
// merged with it. Balls the plain theme shows in different colours keep
// different colours on the projector.
void TestLessonColours::shippedLessonsDrawTheColoursTheirTextsName()
{
    const QDir dir(QStringLiteral(FORCELAB_LESSON_DIR));
    const QStringList files = dir.entryList({"*.json"}, QDir::Files, QDir::Name);
    QVERIFY(files.size() >= 40);
    QStringList problems;
    int namedLessons = 0;
    for (const QString& name : files) {
        const LoadResult r = LessonLoader::loadFile(dir.filePath(name));
        QVERIFY2(r.ok(), qPrintable(r.errors().join('\n')));
        const Lesson& lesson = *r.lesson;
        const sim::BallState balls = sim::buildBalls(lesson.scene);
        const auto named = namedColours(readText(lesson));
        namedLessons += !named.empty();
        for (bool projector : {false, true}) {
            const CanvasColors colors = canvasColors(projector);
            for (const auto& [colour, word] : named) {
                bool drawn = false;
                for (std::size_t i = 0; i < balls.color.size(); ++i) {
                    const sim::Rgb own = balls.color[i] & 0xffffffu;
                    if (drawnBallColor(own, colors) != colour)
                        continue;
                    drawn = true;
                    if (own != colour)
                        problems << QStringLiteral("%1: ball %2 (%3) is drawn %4, the text's \"%5\", in the %6 theme")
                                        .arg(name).arg(i).arg(hex(own), hex(colour), word, themeName(projector));
                }
                if (!drawn)
                    problems << QStringLiteral("%1: the text says \"%2\" but no ball is drawn %3 in the %4 theme")
                                    .arg(name, word, hex(colour), themeName(projector));
            }
        }
        // The projector must not merge colours the plain theme tells apart.
        std::map<sim::Rgb, sim::Rgb> ownOfDrawn;
        const CanvasColors projector = canvasColors(true);
        for (const sim::Ball& b : lesson.scene.balls) {
            const sim::Rgb own = b.color & 0xffffffu;
            const auto [at, inserted] = ownOfDrawn.emplace(drawnBallColor(own, projector), own);
            if (!inserted && at->second != own)
                problems << QStringLiteral("%1: balls of %2 and %3 are both drawn %4 in the projector theme")
                                .arg(name, hex(at->second), hex(own), hex(at->first));
        }
    }
    QVERIFY(namedLessons >= 10); // the texts were read
    for (const QString& p : problems)
        qWarning("%s", qPrintable(p));
    QVERIFY2(problems.isEmpty(), qPrintable(QStringLiteral("%1 problems, listed above").arg(problems.size())));
}

// The canvas paints each ball's centre in drawnBallColor, in both themes, for
// the lessons the teacher found wrong and one of "#rrggbb" colours: the
// check above is the one the picture makes.
void TestLessonColours::paintedBallsHaveTheirDrawnColour()
{
    const QDir dir(QStringLiteral(FORCELAB_LESSON_DIR));
    // 01's balls are "#rrggbb" colours, which the projector theme changes.
    for (const QString& name : {QStringLiteral("01-balls-on-a-canvas.json"), QStringLiteral("07-gravity.json"),
                                QStringLiteral("08-losing-energy.json"), QStringLiteral("27-elastic-collisions-in-1d.json")}) {
        const LoadResult r = LessonLoader::loadFile(dir.filePath(name));
        QVERIFY2(r.ok(), qPrintable(r.errors().join('\n')));
        const sim::World world(r.lesson->scene);
        for (bool projector : {false, true}) {
            const CanvasColors colors = canvasColors(projector);
            PaintOptions options;
            options.colors = &colors;
            QImage image(1024, 768, QImage::Format_RGB32);
            const QRectF area(QPointF(0, 0), QSizeF(image.size()));
            {
                QPainter p(&image);
                WorldPainter painter;
                painter.paint(p, area, world, options, 1.0);
            }
            const ViewTransform view = WorldPainter::view(world, area, options);
            const sim::BallState& balls = world.balls();
            for (int i = 0; i < balls.size(); ++i) {
                const QPoint centre = view.toWidget(sim::Vec2(balls.position.col(i))).toPoint();
                const sim::Rgb want = drawnBallColor(balls.color[static_cast<std::size_t>(i)], colors);
                const sim::Rgb got = image.pixel(centre) & 0xffffffu;
                QVERIFY2(got == want, qPrintable(QStringLiteral("%1 ball %2 in the %3 theme: centre %4, want %5")
                                                     .arg(name).arg(i).arg(themeName(projector), hex(got), hex(want))));
            }
        }
    }
}

QTEST_MAIN(TestLessonColours)
#include "test_lesson_colours.moc"
