// forcelab-cli render, driven as a process: the PNG has the requested size and
// the ball is drawn, in its colour, where the canvas's view puts it at time T.

#include "sim/world/world.h"
#include "ui/drawing/world_painter.h"

#include <QFile>
#include <QImage>
#include <QTemporaryDir>
#include <QTest>

#include "cli_runner.h"

#include <cstdlib>

namespace {

using forcelab::test::CliResult;
using forcelab::test::runCli;


// One large ball moving right at 100 px/s, no forces: at t = 0.5 s its centre
// is at (350, 200).
const char* kMoving = R"({
  "format": 1, "id": "moving", "title": "Moving", "stage": 2,
  "text": "A ball moves.", "challenges": [],
  "world": { "width": 600, "height": 400, "walls": [], "wall_model": "clamp", "restitution": 1.0 },
  "time": { "integrator": "semi-implicit-euler", "dt": 0.01, "substeps": 1, "tolerance": 1e-9, "seed": 1 },
  "models": {},
  "balls": [ {"x": 300, "y": 200, "vx": 100, "vy": 0, "r": 40, "mass": 1, "color": "#d04a20"} ],
  "controls": [], "overlays": []
})";

bool near(QRgb a, QRgb b)
{
    return std::abs(qRed(a) - qRed(b)) <= 2 && std::abs(qGreen(a) - qGreen(b)) <= 2 &&
           std::abs(qBlue(a) - qBlue(b)) <= 2;
}

} // namespace

class TestRender : public QObject {
    Q_OBJECT
private slots:
    void ballIsDrawnWhereItIs_data();
    void ballIsDrawnWhereItIs();
    void badInputExitsTwo();
};

void TestRender::ballIsDrawnWhereItIs_data()
{
    QTest::addColumn<QSize>("size");
    QTest::newRow("900x500") << QSize(900, 500);
    QTest::newRow("320x640") << QSize(320, 640);
}

void TestRender::ballIsDrawnWhereItIs()
{
    QFETCH(QSize, size);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString lesson = dir.filePath("moving.json");
    QFile f(lesson);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(kMoving);
    f.close();
    const QString png = dir.filePath("out.png");
    const CliResult r = runCli({"render", lesson, "--time", "0.5", "--out", png, "--size",
                             QStringLiteral("%1x%2").arg(size.width()).arg(size.height())});
    QCOMPARE(r.exitCode, 0);
    const QImage image(png);
    QVERIFY(!image.isNull());
    QCOMPARE(image.size(), size);

    // Where the canvas puts world point (350, 200) in this area.
    forcelab::sim::Scene scene;
    scene.settings.box = forcelab::sim::BoxSettings{600.0, 400.0};
    const forcelab::sim::World world(scene);
    const forcelab::ViewTransform view = forcelab::WorldPainter::view(world, QRectF(QPointF(0, 0), QSizeF(size)));
    const QPointF centre = view.toWidget(forcelab::sim::Vec2(350.0, 200.0));
    const double radius = view.toWidget(40.0);
    QVERIFY(radius > 8.0);
    const QRgb ball = qRgb(0xd0, 0x4a, 0x20);
    // Inside the ball (half its radius from the centre, in four directions) the
    // pixel is the ball's colour; where it started it is not.
    for (const QPointF d : {QPointF(0.5, 0), QPointF(-0.5, 0), QPointF(0, 0.5), QPointF(0, -0.5)}) {
        const QPoint at = (centre + d * radius).toPoint();
        QVERIFY2(near(image.pixel(at), ball),
                 qPrintable(QString("pixel (%1, %2) is %3").arg(at.x()).arg(at.y()).arg(image.pixel(at), 0, 16)));
    }
    const QPoint start = (view.toWidget(forcelab::sim::Vec2(300.0 - 30.0, 200.0))).toPoint();
    QVERIFY(!near(image.pixel(start), ball));
}

void TestRender::badInputExitsTwo()
{
    QCOMPARE(runCli({"render", "gravity", "--out", "/tmp/x.png"}).exitCode, 2);                  // no --time
    QCOMPARE(runCli({"render", "gravity", "--time", "1", "--out", "/tmp/x.png", "--size", "0x5"}).exitCode, 2);
    const CliResult r = runCli({"render", "no-such-lesson", "--time", "1", "--out", "/tmp/x.png"});
    QCOMPARE(r.exitCode, 2);
    QVERIFY(r.err.contains("no-such-lesson"));
}

QTEST_GUILESS_MAIN(TestRender)
#include "test_render.moc"
