// forcelab-cli trace and compare (issue #37 part 3), driven as a user would:
// students' traces are made by running the reference with a mistake switched
// on (or with one number changed), written to a temporary folder, and
// compare must name the step, the ball, the size and the mistake.

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include "cli_runner.h"

using forcelab::test::CliResult;
using forcelab::test::runCli;

class TestCliTrace : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void traceWritesEveryStepWithItsSettings();
    void theReferenceAgreesWithItself();
    void anUpdateOrderBugIsCaughtAtItsFirstStep();
    void oneChangedNumberIsFoundWhereItIs();
    void aUnitsPerFrameTraceIsDiagnosed();
    void theCourseBugsAreDiagnosed_data();
    void theCourseBugsAreDiagnosed();
    void aBadFileIsOneLineNamingFileAndField_data();
    void aBadFileIsOneLineNamingFileAndField();
    void aFileTooBigIsRefused();

private:
    QString write(const QString& name, const QByteArray& text);
    QByteArray trace(const QStringList& args);
    QTemporaryDir m_dir;
};

void TestCliTrace::initTestCase()
{
    QVERIFY(m_dir.isValid());
}

QString TestCliTrace::write(const QString& name, const QByteArray& text)
{
    const QString path = m_dir.filePath(name);
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(text) != text.size())
        qFatal("cannot write %s", qPrintable(path));
    return path;
}

QByteArray TestCliTrace::trace(const QStringList& args)
{
    const CliResult r = runCli(QStringList{"trace"} + args);
    if (r.exitCode != 0)
        qFatal("trace %s failed: %s", qPrintable(args.join(' ')), qPrintable(r.err));
    return r.out.toUtf8();
}

// Step 0 and every K-th step, one row per ball, with the columns the issue
// asks for and the settings in a '#' line; JSON has the same rows.
void TestCliTrace::traceWritesEveryStepWithItsSettings()
{
    const QStringList lines = QString::fromUtf8(trace({"gravity", "--steps", "10", "--every", "4"})).split('\n', Qt::SkipEmptyParts);
    QVERIFY(lines[0].startsWith("# forcelab-cli trace: lesson gravity; integrator semi-implicit-euler"));
    QVERIFY2(lines[0].contains("steps 10; every 4"), qPrintable(lines[0]));
    QCOMPARE(lines[1], QStringLiteral("step,t,ball,x,y,vx,vy,ax,ay,pair_tests,contacts,wind,random_x,random_y"));
    // gravity has 4 balls; steps 0, 4, 8 and the last, 10.
    QCOMPARE(lines.size(), 2 + 4 * 4);
    QStringList steps;
    for (int i = 2; i < lines.size(); i += 4)
        steps << lines[i].section(',', 0, 0);
    QCOMPARE(steps, (QStringList{"0", "4", "8", "10"}));
    // Ball 0 starts at rest at y = 60 under g = 980 px/s²: after one step of
    // 1/60 s semi-implicit Euler has vy = g dt and y = 60 + g dt².
    const QStringList one = QString::fromUtf8(trace({"gravity", "--steps", "1"})).split('\n')[6].split(',');
    QCOMPARE(one[0], QStringLiteral("1"));
    QCOMPARE(one[2], QStringLiteral("0"));
    QCOMPARE(one[4].toDouble(), 60.0 + 980.0 / 3600.0);
    QCOMPARE(one[6].toDouble(), 980.0 / 60.0);
    QCOMPARE(one[8].toDouble(), 980.0);

    const QJsonObject json = QJsonDocument::fromJson(trace({"gravity", "--steps", "10", "--json"})).object();
    QVERIFY(json.value("settings").toString().contains("lesson gravity"));
    const QJsonArray rows = json.value("rows").toArray();
    QCOMPARE(rows.size(), 11 * 4);
    for (const char* key : {"step", "t", "ball", "x", "y", "vx", "vy", "ax", "ay", "pair_tests", "contacts", "wind",
                            "random_x", "random_y"})
        QVERIFY2(rows[5].toObject().contains(QLatin1String(key)), key);

    const CliResult both = runCli({"trace", "gravity", "--steps", "3", "--csv", "--json"});
    QCOMPARE(both.exitCode, 2);
    const CliResult many = runCli({"trace", "gravity", "--steps", "1000001"});
    QCOMPARE(many.exitCode, 2);
    QVERIFY2(many.err.contains("--steps: expects a whole number from 0 to 1000000"), qPrintable(many.err));
}

void TestCliTrace::theReferenceAgreesWithItself()
{
    for (const QString& lesson : {QStringLiteral("gravity"), QStringLiteral("04-walls-and-radius"),
                                  QStringLiteral("10-random-acceleration")}) {
        const QString csv = write(lesson + "-ref.csv", trace({lesson, "--steps", "300"}));
        const CliResult r = runCli({"compare", lesson, csv});
        QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
        QVERIFY2(r.out.contains("agrees with") && r.out.contains("largest difference 0,"), qPrintable(r.out));
        const QString json = write(lesson + "-ref.json", trace({lesson, "--steps", "300", "--json"}));
        const CliResult j = runCli({"compare", lesson, json});
        QVERIFY2(j.exitCode == 0, qPrintable(j.out + j.err));
    }
}

// Explicit Euler moves with the old velocity: ball 0, at rest at the start,
// has not moved after step 1, where the lesson's semi-implicit step has moved
// it by g dt² = 980 / 3600 px. compare names step 1, ball 0, that size, and
// finds the whole file is the reference run with explicit Euler.
void TestCliTrace::anUpdateOrderBugIsCaughtAtItsFirstStep()
{
    const QString file = write("euler.csv", trace({"gravity", "--steps", "200", "--set", "time.integrator=euler"}));
    const CliResult r = runCli({"compare", "gravity", file});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.out.contains("departs from gravity at step 1, ball 0 (line 7): y is 60 where the reference has "
                            "60.2722222222, off by 0.272222 px"),
             qPrintable(r.out));
    QVERIFY2(r.out.contains("likely cause: update order: the numbers follow the reference with --set "
                            "time.integrator=euler to 0 over all 804 rows (to step 200)"),
             qPrintable(r.out));
    QVERIFY(r.out.contains("old velocity"));
}

// One number changed by 0.5 px at step 7: found there, with its size, and no
// known mistake is blamed for it.
void TestCliTrace::oneChangedNumberIsFoundWhereItIs()
{
    QStringList lines = QString::fromUtf8(trace({"gravity", "--steps", "20"})).split('\n');
    int changed = -1;
    for (int i = 0; i < lines.size(); ++i)
        if (lines[i].startsWith("7,") && lines[i].section(',', 2, 2) == "2") {
            QStringList f = lines[i].split(',');
            f[3] = QString::number(f[3].toDouble() + 0.5, 'g', 17);
            lines[i] = f.join(',');
            changed = i + 1;
        }
    QVERIFY(changed > 0);
    const QString file = write("one-changed.csv", lines.join('\n').toUtf8());
    const CliResult r = runCli({"compare", "gravity", file});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.out.contains(QStringLiteral("at step 7, ball 2 (line %1): x is 360.5 where the reference has 360, off "
                                           "by 0.5 px").arg(changed)),
             qPrintable(r.out));
    QVERIFY2(r.out.contains("cause: no known mistake explains it"), qPrintable(r.out));
    // A looser tolerance lets it through.
    QCOMPARE(runCli({"compare", "gravity", file, "--tolerance", "0.01"}).exitCode, 0);
}

// At dt = 0.01 s the per-frame bug moves by 1/60 s a step: diagnosed as units per frame.
void TestCliTrace::aUnitsPerFrameTraceIsDiagnosed()
{
    const QString file = write("per-frame.csv", trace({"gravity", "--steps", "100", "--set", "time.dt=0.01", "--set",
                                                       "time.per_frame=true"}));
    const CliResult r = runCli({"compare", "gravity", file, "--set", "time.dt=0.01"});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.out.contains("at step 1, ball 0"), qPrintable(r.out));
    QVERIFY2(r.out.contains("likely cause: units per frame: the numbers follow the reference with --set "
                            "time.per_frame=true to 0 over all"),
             qPrintable(r.out));
}

void TestCliTrace::theCourseBugsAreDiagnosed_data()
{
    QTest::addColumn<QString>("lesson");
    QTest::addColumn<QString>("set");
    QTest::addColumn<QString>("cause");
    QTest::newRow("centre only") << "04-walls-and-radius" << "world.centre_only=true" << "wall rule";
    QTest::newRow("un-centred") << "10-random-acceleration" << "models.random_accel.uncentred=true"
                                << "un-centred random numbers";
    QTest::newRow("un-normalised") << "16-repulsion" << "models.point.unnormalised=true" << "un-normalised repulsion";
}

void TestCliTrace::theCourseBugsAreDiagnosed()
{
    QFETCH(QString, lesson);
    QFETCH(QString, set);
    QFETCH(QString, cause);
    const QString file = write(lesson + "-bug.csv", trace({lesson, "--steps", "300", "--set", set}));
    const CliResult r = runCli({"compare", lesson, file});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.out.contains("likely cause: " + cause + ": the numbers follow the reference with --set " + set +
                            " to 0 over all"),
             qPrintable(r.out));
}

void TestCliTrace::aBadFileIsOneLineNamingFileAndField_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QString>("message"); // after the file's path
    QTest::newRow("not a number") << "nan.csv" << QByteArray("step,ball,x,y\n0,0,120,60\n0,1,abc,72\n")
                                  << ":3: x: 'abc' is not a finite number";
    QTest::newRow("NaN") << "nan2.csv" << QByteArray("step,ball,x,y\n0,0,NaN,60\n") << ":2: x: 'NaN' is not a finite number";
    QTest::newRow("no y") << "noy.csv" << QByteArray("# a comment\nstep,ball,x\n0,0,1\n")
                          << ":2: the header has no column 'y'";
    QTest::newRow("short row") << "short.csv" << QByteArray("step,ball,x,y\n0,0,120\n")
                               << ":2: expected 4 fields as in the header, found 3";
    QTest::newRow("half a step") << "half.csv" << QByteArray("step,ball,x,y\n0.5,0,120,60\n")
                                 << ":2: step: '0.5' is not a whole number from 0 to 1000000";
    QTest::newRow("no ball 9") << "ball9.csv" << QByteArray("step,ball,x,y\n0,9,120,60\n")
                               << ": line 2: ball 9 is not in the reference at step 0 (it has 4 balls";
    QTest::newRow("json x") << "x.json" << QByteArray(R"({"rows": [{"step": 0, "ball": 0, "x": "a", "y": 1}]})")
                            << ": rows[0].x: expected a number";
    QTest::newRow("json y") << "y.json" << QByteArray(R"([{"step": 0, "ball": 0, "x": 1}])")
                            << ": rows[0].y: missing";
    QTest::newRow("json cut") << "cut.json" << QByteArray("{\"rows\": [\n{\"step\": 0,\n") << ":3: not JSON:";
}

void TestCliTrace::aBadFileIsOneLineNamingFileAndField()
{
    QFETCH(QString, name);
    QFETCH(QByteArray, text);
    QFETCH(QString, message);
    const QString file = write(name, text);
    const CliResult r = runCli({"compare", "gravity", file});
    QCOMPARE(r.exitCode, 2);
    QVERIFY(r.out.isEmpty());
    QCOMPARE(r.err.count('\n'), 1);
    QVERIFY2(r.err.startsWith(file + message), qPrintable(r.err));
}

// 64 MiB is the limit: one byte more is refused before it is read.
void TestCliTrace::aFileTooBigIsRefused()
{
    const QString path = m_dir.filePath("big.csv");
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    QVERIFY(f.resize(64LL * 1024 * 1024 + 1));
    f.close();
    const CliResult r = runCli({"compare", "gravity", path});
    QCOMPARE(r.exitCode, 2);
    QCOMPARE(r.err, path + ": 67108865 bytes; a trace may have at most 67108864 (64 MiB)\n");
    QVERIFY(QFile::remove(path));
}

QTEST_GUILESS_MAIN(TestCliTrace)
#include "test_cli_trace.moc"
