// forcelab-cli run, driven as a user would: a process, its exit code, its
// output. Numbers are checked against closed forms.

#include <QDir>
#include <QFile>
#include <QProcessEnvironment>
#include <QRegularExpression>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include "cli_runner.h"

#include <cmath>

namespace {

using forcelab::test::CliResult;
using forcelab::test::runCli;


// One ball falling freely from (100, 50) with vx = 30, no walls, exact integrator.
const char* kFreeFall = R"({
  "format": 1, "id": "free-fall", "title": "Free fall", "stage": 7,
  "text": "A ball falls.", "challenges": [],
  "world": { "width": 600, "height": 400, "walls": [], "wall_model": "exact", "restitution": 1.0 },
  "time": { "integrator": "exact", "dt": 0.01, "substeps": 1, "tolerance": 1e-9, "seed": 1 },
  "models": { "gravity": {"x": 0, "y": 980} },
  "balls": [ {"x": 100, "y": 50, "vx": 30, "vy": 0, "r": 10, "mass": 2, "color": "#e05050"} ],
  "controls": [], "overlays": []
})";

} // namespace

class TestCli : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void jsonMatchesClosedForm();
    void stepsZeroPrintsInitialState();
    void optionsOverrideTheLesson();
    void builtInLessonRuns();
    void blowUpExitsThree();
    void shortSoakKeepsEnergy();
    void badInputExitsTwo_data();
    void badInputExitsTwo();
    void timeEndsWhereAsked_data();
    void timeEndsWhereAsked();
    void timeThatCannotRunIsRefused_data();
    void timeThatCannotRunIsRefused();
    void everyCommandHasHelp_data();
    void everyCommandHasHelp();
    void aFolderIsNamedAsOne();
    void aLinkLoopIsNamedAlikeByEveryCommand();
    void hostileLessons_data();
    void hostileLessons();
    void toleranceBelowRoundingIsSaid();
    void workbenchHelpNeedsNoDisplay();
    void pileSettlesToHexPacking();

private:
    QTemporaryDir m_dir;
    QString m_lesson;
};

void TestCli::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_lesson = m_dir.filePath("free-fall.json");
    QFile f(m_lesson);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(kFreeFall);
}

// After 100 steps of 0.01 s: y = 50 + ½ 980 t² = 540, x = 100 + 30 t = 130,
// kinetic energy ½ m v², potential −m g y, momentum m v.
void TestCli::jsonMatchesClosedForm()
{
    const CliResult r = runCli({"run", m_lesson, "--steps", "100", "--json"});
    QCOMPARE(r.exitCode, 0);
    QVERIFY2(r.err.isEmpty(), qPrintable(r.err));
    const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
    for (const char* key : {"lesson", "integrator", "dt", "steps", "time", "balls", "energy", "momentum",
                            "angular_momentum", "force_evaluations", "wall_hits", "contacts", "wall_ms"})
        QVERIFY2(o.contains(key), key);
    QCOMPARE(o["lesson"].toString(), QString("free-fall"));
    QCOMPARE(o["integrator"].toString(), QString("exact"));
    QCOMPARE(o["steps"].toInt(), 100);
    const double t = o["time"].toDouble();
    QVERIFY(std::abs(t - 1.0) < 1e-12);
    const QJsonObject ball = o["balls"].toArray().at(0).toObject();
    QVERIFY(std::abs(ball["x"].toDouble() - (100 + 30 * t)) < 1e-9);
    QVERIFY(std::abs(ball["y"].toDouble() - (50 + 0.5 * 980 * t * t)) < 1e-9);
    QVERIFY(std::abs(ball["vy"].toDouble() - 980 * t) < 1e-9);
    QCOMPARE(ball["mass"].toDouble(), 2.0);
    QCOMPARE(ball["r"].toDouble(), 10.0);
    const QJsonObject energy = o["energy"].toObject();
    const double v2 = 30.0 * 30.0 + (980 * t) * (980 * t);
    QVERIFY(std::abs(energy["kinetic"].toDouble() - 0.5 * 2 * v2) < 1e-6);
    QVERIFY(std::abs(energy["potential"].toDouble() - (-2 * 980 * ball["y"].toDouble())) < 1e-6);
    // Energy is conserved exactly by the exact integrator: total as at the start.
    QVERIFY(std::abs(energy["total"].toDouble() - (0.5 * 2 * 900 - 2 * 980 * 50)) < 1e-6);
    QVERIFY(std::abs(o["momentum"].toArray().at(1).toDouble() - 2 * 980 * t) < 1e-9);
    QCOMPARE(o["force_evaluations"].toInt(), 100);
    QCOMPARE(o["wall_hits"].toInt(), 0);
    QCOMPARE(o["contacts"].toInt(), 0);
    QVERIFY(o["wall_ms"].toDouble() >= 0.0);
}

void TestCli::timeEndsWhereAsked_data()
{
    QTest::addColumn<QString>("time");
    QTest::addColumn<QString>("dt");
    QTest::addColumn<int>("steps");
    QTest::newRow("0.1 s at dt 0.04: two steps and one of 0.02") << "0.1" << "0.04" << 3;
    QTest::newRow("0.01 s at dt 0.04: one step of 0.01") << "0.01" << "0.04" << 1;
    QTest::newRow("0.3 s at dt 0.1: three steps, no sliver") << "0.3" << "0.1" << 3;
    QTest::newRow("1 s at dt 0.01") << "1" << "0.01" << 100;
    QTest::newRow("0 s") << "0" << "0.01" << 0;
}

// --time T ends at T, whatever dt is: the free fall's closed form at T,
// y = 50 + ½ g T², x = 100 + 30 T (the exact integrator is exact for any step,
// the shorter last one too). Before: 0.1 s at dt = 0.04 ended at 0.12 s and
// 0.01 s ran no step at all, both with exit 0. The lesson's own dt is what the
// report names.
void TestCli::timeEndsWhereAsked()
{
    QFETCH(QString, time);
    QFETCH(QString, dt);
    QFETCH(int, steps);
    const CliResult r = runCli({"run", m_lesson, "--time", time, "--dt", dt, "--json"});
    QCOMPARE(r.exitCode, 0);
    const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
    const double T = time.toDouble();
    QCOMPARE(o["steps"].toInt(), steps);
    QVERIFY2(std::abs(o["time"].toDouble() - T) <= 1e-12, qPrintable(QString::number(o["time"].toDouble(), 'g', 17)));
    QCOMPARE(o["dt"].toDouble(), dt.toDouble());
    const QJsonObject ball = o["balls"].toArray().at(0).toObject();
    QVERIFY(std::abs(ball["x"].toDouble() - (100 + 30 * T)) < 1e-9);
    QVERIFY(std::abs(ball["y"].toDouble() - (50 + 0.5 * 980 * T * T)) < 1e-9);
}

void TestCli::timeThatCannotRunIsRefused_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("message");
    // Before: exit 0 after 0 steps (T/dt beyond 2^63 went through an undefined
    // conversion to an integer).
    QTest::newRow("1e300 s") << QStringList{"--time", "1e300"}
                             << "forcelab-cli run: --time: 1e+300 s is 1e+302 steps of dt = 0.01 s, more than 1000000000";
    QTest::newRow("1 s at dt 1e-300") << QStringList{"--time", "1", "--dt", "1e-300"}
                                      << "steps of dt = 1e-300 s, more than 1000000000";
    QTest::newRow("negative") << QStringList{"--time", "-1"} << "--time: expects a number of seconds >= 0";
}

void TestCli::timeThatCannotRunIsRefused()
{
    QFETCH(QStringList, args);
    QFETCH(QString, message);
    const CliResult r = runCli(QStringList{"run", m_lesson} + args);
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
    QVERIFY(r.out.isEmpty());
}

void TestCli::everyCommandHasHelp_data()
{
    QTest::addColumn<QString>("command");
    QTest::addColumn<QStringList>("options"); // what its --help must name
    QTest::newRow("run") << "run" << QStringList{"--integrator", "--dt", "--set", "--steps", "--time", "--json", "LESSON"};
    QTest::newRow("check") << "check" << QStringList{"[LESSON...]"};
    QTest::newRow("validate") << "validate" << QStringList{"FILE..."};
    QTest::newRow("handbook") << "handbook" << QStringList{"--out"};
    QTest::newRow("bench") << "bench" << QStringList{"--quick", "--sizes", "--profile", "--no-peers"};
    QTest::newRow("sweep") << "sweep" << QStringList{"--problem", "--quick", "--csv", "--png"};
    QTest::newRow("render") << "render" << QStringList{"--time", "--out", "--size"};
    QTest::newRow("soak") << "soak" << QStringList{"--steps", "--balls"};
    QTest::newRow("pile") << "pile" << QStringList{"--balls", "--substeps", "--position-passes", "--correction"};
    QTest::newRow("trace") << "trace" << QStringList{"--steps", "--every", "--set", "--csv", "--json", "LESSON"};
    QTest::newRow("compare") << "compare" << QStringList{"--set", "--tolerance", "LESSON", "STUDENT.csv|json"};
    QTest::newRow("params") << "params" << QStringList{};
}

// COMMAND --help (and -h) prints that command's usage and options, from its
// QCommandLineParser, on stdout and exits 0; the top-level usage names the
// command with the same summary. An unknown option is one line on stderr
// naming it, with exit code 2.
void TestCli::everyCommandHasHelp()
{
    QFETCH(QString, command);
    QFETCH(QStringList, options);
    const CliResult all = runCli({"--help"});
    QCOMPARE(all.exitCode, 0);
    for (const char* flag : {"--help", "-h"}) {
        const CliResult r = runCli({command, flag});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.startsWith("Usage: forcelab-cli " + command), qPrintable(r.out + r.err));
        QVERIFY(r.err.isEmpty());
        for (const QString& option : options)
            QVERIFY2(r.out.contains(option), qPrintable(command + " --help lacks " + option));
        const QString summary = r.out.section('\n', 1, 1);
        QVERIFY2(all.out.contains(summary.left(40)), qPrintable(summary));
    }
    const CliResult bad = runCli({command, "--no-such-option"});
    QCOMPARE(bad.exitCode, 2);
    QVERIFY(bad.out.isEmpty());
    QCOMPARE(bad.err.count('\n'), 1);
    QVERIFY2(bad.err.startsWith("forcelab-cli " + command + ": Unknown option 'no-such-option'"), qPrintable(bad.err));
}

// A folder given where a lesson file belongs reads the same from run and
// validate (before: "no such file" from run, "is not a file" from validate).
void TestCli::aFolderIsNamedAsOne()
{
    const QString expected = m_dir.path() + ": is a folder, not a lesson file; give one of the .json files in it";
    for (const char* command : {"run", "validate"}) {
        const CliResult r = runCli({command, m_dir.path()});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.trimmed() == expected, qPrintable(r.err));
    }
}

// ias15 asked for 1e-15 on an orbit: it runs (before: exit 3 after a few
// steps), works to its rounding floor and says so on stderr and in the JSON;
// at its default tolerance it says nothing.
void TestCli::toleranceBelowRoundingIsSaid()
{
    const CliResult tight =
        runCli({"run", "orbit-energy-drift", "--integrator", "ias15", "--tolerance", "1e-15", "--time", "2", "--json"});
    QCOMPARE(tight.exitCode, 0);
    QVERIFY2(tight.err.startsWith("note: time.tolerance 1e-15 is below what rounding allows here"), qPrintable(tight.err));
    const double floor = QJsonDocument::fromJson(tight.out.toUtf8()).object()["tolerance_floor"].toDouble();
    QVERIFY(floor > 1e-15 && floor < 1e-9);
    const CliResult usual = runCli({"run", "orbit-energy-drift", "--integrator", "ias15", "--time", "2", "--json"});
    QCOMPARE(usual.exitCode, 0);
    QVERIFY(usual.err.isEmpty());
    QCOMPARE(QJsonDocument::fromJson(usual.out.toUtf8()).object()["tolerance_floor"].toDouble(), 0.0);
}

// The workbench itself, on a machine with no display: --help prints its
// options (before: Qt aborted, looking for a display), in the language asked for; a plain start says in
// one line why it cannot open a window; --screenshot draws offscreen.
void TestCli::workbenchHelpNeedsNoDisplay()
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"})
        env.remove(QString::fromLatin1(name));
    env.insert(QStringLiteral("XDG_CONFIG_HOME"), m_dir.path()); // no remembered language: English
    auto run = [&](const QStringList& args) {
        QProcess p;
        p.setProcessEnvironment(env);
        p.start(QStringLiteral(FORCELAB_APP_PATH), args);
        if (!p.waitForFinished(60000))
            qFatal("forcelab did not finish");
        return CliResult{p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1,
                         QString::fromUtf8(p.readAllStandardOutput()), QString::fromUtf8(p.readAllStandardError())};
    };
    const CliResult help = run({"--help"});
    QCOMPARE(help.exitCode, 0);
    QVERIFY2(help.out.startsWith("Usage: forcelab [options] [lesson]") && help.out.contains("--screenshot"),
             qPrintable(help.out + help.err));
    // In German: Qt's words and the program's own.
    const CliResult german = run({"--help", "--language", "de"});
    QCOMPARE(german.exitCode, 0);
    QVERIFY2(german.out.startsWith("Aufruf: forcelab") && german.out.contains("--screenshot") &&
                 !german.out.contains("Save a picture of the window") && !german.out.contains("A workbench for forces"),
             qPrintable(german.out + german.err));
    const CliResult plain = run({});
    QCOMPARE(plain.exitCode, 2);
    QVERIFY2(plain.err.startsWith("forcelab: there is no display"), qPrintable(plain.err));
    const QString picture = m_dir.filePath("offscreen.png");
    const CliResult shot = run({"--screenshot", picture, "--after", "0.2", "gravity"});
    QCOMPARE(shot.exitCode, 0);
    QFile png(picture);
    QVERIFY(png.open(QIODevice::ReadOnly));
    const QByteArray bytes = png.readAll();
    QVERIFY(bytes.startsWith("\x89PNG") && bytes.size() > 10000); // a real picture of the window
    // A lesson that does not load: one line naming it and exit code 2, not a
    // dialog waiting for a click (the run used to hang here).
    const QString missing = m_dir.filePath("no-such-lesson.json");
    const CliResult bad = run({"--screenshot", m_dir.filePath("bad.png"), "--after", "0.2", missing});
    QCOMPARE(bad.exitCode, 2);
    const QStringList said = bad.err.split(QLatin1Char('\n')).filter(QRegularExpression(QStringLiteral("^forcelab: ")));
    QVERIFY2(said.size() == 1 && said.first().contains(QStringLiteral("no-such-lesson.json")), qPrintable(bad.err));
    QVERIFY(!QFile::exists(m_dir.filePath("bad.png")));
}

void TestCli::stepsZeroPrintsInitialState()
{
    const CliResult r = runCli({"run", m_lesson, "--steps", "0", "--json"});
    QCOMPARE(r.exitCode, 0);
    const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
    QCOMPARE(o["steps"].toInt(), 0);
    QCOMPARE(o["time"].toDouble(), 0.0);
    const QJsonObject ball = o["balls"].toArray().at(0).toObject();
    QCOMPARE(ball["y"].toDouble(), 50.0);
    QCOMPARE(o["energy"].toObject()["kinetic"].toDouble(), 900.0);
    QCOMPARE(o["energy"].toObject()["potential"].toDouble(), -2.0 * 980 * 50);
}

void TestCli::optionsOverrideTheLesson()
{
    // No gravity: the ball moves in a straight line; --time picks the step count.
    const CliResult r = runCli({"run", m_lesson, "--set", "models.gravity.y=0", "--integrator", "rk4", "--dt", "0.02",
                             "--time", "2", "--json"});
    QCOMPARE(r.exitCode, 0);
    const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
    QCOMPARE(o["integrator"].toString(), QString("rk4"));
    QCOMPARE(o["dt"].toDouble(), 0.02);
    QCOMPARE(o["steps"].toInt(), 100);
    const QJsonObject ball = o["balls"].toArray().at(0).toObject();
    QVERIFY(std::abs(ball["x"].toDouble() - 160.0) < 1e-9);
    QCOMPARE(ball["y"].toDouble(), 50.0);
    QCOMPARE(o["force_evaluations"].toInt(), 400);
}

void TestCli::builtInLessonRuns()
{
    const CliResult r = runCli({"run", "gravity", "--steps", "60", "--json"});
    QCOMPARE(r.exitCode, 0);
    const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
    QCOMPARE(o["lesson"].toString(), QString("gravity"));
    QVERIFY(!o["balls"].toArray().isEmpty());
    const CliResult text = runCli({"run", "gravity", "--steps", "10"});
    QCOMPARE(text.exitCode, 0);
    QVERIFY(text.out.contains("10 steps"));
}

// A stiff spring at a large dt: the world stops before stepping and the CLI
// exits 3 with the reason on stderr.
void TestCli::blowUpExitsThree()
{
    const CliResult r = runCli({"run", m_lesson, "--integrator", "verlet", "--set", "models.gravity.y=0", "--set",
                             "models.spring.k=90000", "--steps", "10"});
    QCOMPARE(r.exitCode, 3);
    const QString err = r.err.trimmed();
    QVERIFY2(err.count('\n') == 0, qPrintable(err));
    QVERIFY2(err.contains("stopped after 0 steps: verlet is unstable for this spring at dt = 0.01 s"), qPrintable(err));
    // 2 / ω = 0.0066667 s, rounded down so that the advice is really stable.
    QVERIFY2(err.contains("Lower dt below 0.00666 s"), qPrintable(err));
}

// A short soak: 200 balls, 3000 steps, collisions with e = 1 and exact walls.
// It reports its largest energy change, which must stay at rounding level.
void TestCli::shortSoakKeepsEnergy()
{
    const CliResult r = runCli({"soak", "--steps", "3000", "--balls", "200"});
    QCOMPARE(r.exitCode, 0);
    const QString key = QStringLiteral("largest relative energy change (sampled every 1000 steps): ");
    const qsizetype at = r.out.indexOf(key);
    QVERIFY2(at >= 0, qPrintable(r.out));
    const double change = r.out.mid(at + key.size()).section('\n', 0, 0).toDouble();
    QVERIFY2(change < 1e-12, qPrintable(QString::number(change)));
    QVERIFY(r.out.contains("no NaN"));
}

// Two links that point at each other: run, check and validate all say what
// the system says about opening it (run and check used to say "no such file").
void TestCli::aLinkLoopIsNamedAlikeByEveryCommand()
{
    QTemporaryDir dir;
    const QString a = dir.filePath(QStringLiteral("a.json")), b = dir.filePath(QStringLiteral("b.json"));
    QVERIFY(QFile::link(b, a) && QFile::link(a, b));
    QStringList messages;
    for (const char* command : {"run", "check", "validate"}) {
        const CliResult r = runCli({QString::fromLatin1(command), a});
        QCOMPARE(r.exitCode, 2);
        messages << r.err.trimmed();
    }
    QVERIFY2(messages[0].startsWith(a + QStringLiteral(": cannot open")), qPrintable(messages[0]));
    QCOMPARE(messages[1], messages[0]);
    QCOMPARE(messages[2], messages[0]);
}

// The hostile-lesson corpus (tests/hostile/expected.tsv): each file a
// stranger might send, run as the table says, gives its exit code and its
// message, in time and without echoing a long value whole.
void TestCli::hostileLessons_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("message");
    const QDir dir(QStringLiteral(FORCELAB_HOSTILE_DIR));
    QFile table(dir.filePath(QStringLiteral("expected.tsv")));
    QVERIFY(table.open(QIODevice::ReadOnly | QIODevice::Text));
    int cases = 0;
    while (!table.atEnd()) {
        const QString line = QString::fromUtf8(table.readLine()).chopped(1);
        if (line.isEmpty() || line.startsWith(QLatin1Char('#')))
            continue;
        const QStringList cells = line.split(QLatin1Char('\t'));
        QVERIFY2(cells.size() == 3, qPrintable(line));
        QStringList args;
        const QStringList words = cells[0].split(QLatin1Char(' '), Qt::SkipEmptyParts);
        for (qsizetype i = 0; i < words.size(); ++i)
            args << (words[i] == QLatin1String("@") ? dir.filePath(words[++i]) : words[i]);
        QTest::newRow(qPrintable(cells[0])) << args << cells[1].toInt() << cells[2];
        ++cases;
    }
    QVERIFY(cases >= 30);
}

void TestCli::hostileLessons()
{
    QFETCH(QStringList, args);
    QFETCH(int, exitCode);
    QFETCH(QString, message);
    const CliResult r = runCli(args, 120000);
    QCOMPARE(r.exitCode, exitCode);
    const QString shown = exitCode == 0 ? r.out : r.err;
    QVERIFY2(shown.contains(message), qPrintable(shown.left(600)));
    for (const QString& line : (r.out + r.err).split(QLatin1Char('\n')))
        QVERIFY2(line.size() < 1000, qPrintable(line.left(200)));
}

void TestCli::badInputExitsTwo_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("message"); // a part of the one-line error
    QTest::newRow("unknown integrator") << QStringList{"run", "@L", "--integrator", "leapfrog"}
                                        << "--integrator: \"leapfrog\" is not one of euler, semi-implicit-euler";
    QTest::newRow("dt not a number") << QStringList{"run", "@L", "--dt", "fast"} << "--dt: expects a number";
    QTest::newRow("dt NaN") << QStringList{"run", "@L", "--dt", "nan"} << "--dt: expects a number";
    QTest::newRow("exact with drag") << QStringList{"run", "@L", "--set", "models.drag.k=1"}
                                     << "time.integrator: exact needs a constant acceleration";
    QTest::newRow("dt zero") << QStringList{"run", "@L", "--dt", "0"} << "time.dt: 0 is outside (0, 1]";
    QTest::newRow("bad --set") << QStringList{"run", "@L", "--set", "models.gravity.y"} << "--set";
    QTest::newRow("unknown key") << QStringList{"run", "@L", "--set", "models.gravty.y=1"} << "gravity";
    QTest::newRow("negative steps") << QStringList{"run", "@L", "--steps", "-3"} << "--steps";
    QTest::newRow("no lesson") << QStringList{"run"} << "needs a lesson";
    QTest::newRow("missing file") << QStringList{"run", "/nonexistent/lesson.json"} << "lesson.json";
    QTest::newRow("unknown option") << QStringList{"run", "@L", "--fast"} << "Unknown option 'fast'";
    QTest::newRow("unknown command") << QStringList{"walk"} << "walk";
    QTest::newRow("pile of no balls") << QStringList{"pile", "--balls", "0"}
                                      << "forcelab-cli pile: --balls: expected a whole number in [1, 1e+06], got '0'";
    QTest::newRow("pile correction NaN") << QStringList{"pile", "--correction", "nan"} << "--correction: expected a number";
    QTest::newRow("pile half a pass") << QStringList{"pile", "--position-passes", "2.5"} << "--position-passes";
    // A stranger's 100,000-character argument is shown by its start and length.
    const QString longText(100000, QLatin1Char('9'));
    QTest::newRow("long --set key") << QStringList{"run", "@L", "--set", longText + "=3"} << "(100000 characters)";
    QTest::newRow("long --set value") << QStringList{"run", "@L", "--set", "models.gravity.y=" + longText + "x"}
                                      << "(100001 characters)";
    QTest::newRow("long --dt") << QStringList{"run", "@L", "--dt", longText + "x"} << "(100001 characters)";
    QTest::newRow("long bench --runs") << QStringList{"bench", "--runs", longText + "x"} << "(100001 characters)";
}

void TestCli::badInputExitsTwo()
{
    QFETCH(QStringList, args);
    QFETCH(QString, message);
    args.replaceInStrings("@L", m_lesson);
    const CliResult r = runCli(args);
    QCOMPARE(r.exitCode, 2);
    QVERIFY(r.out.isEmpty());
    const QString err = r.err.trimmed();
    QVERIFY2(!err.isEmpty() && err.count('\n') == 0, qPrintable(err.left(400))); // exactly one line
    QVERIFY2(err.size() < 1000, qPrintable(err.left(400))); // a long argument is not echoed whole
    QVERIFY2(err.contains(message), qPrintable(err));
}

// `pile` follows 300 balls of the peer scene for 4 s. They settle into
// touching rows: the box is √(300 π 5² / 0.3) = 280.2 px wide, so rows of 28
// and 27 balls alternate, 8.66 px (10 · √3/2) apart, from 5 px above the
// floor. Ten full rows hold 275 balls and the eleventh the other 25, so the
// mean centre height of that hexagonal packing is 14,360 / 300 = 47.9 px.
// A pile cannot pack tighter without overlapping, and one with a few gaps
// stands a little higher: the last row must lie within [-1%, +3%] of it,
// and the pile must be slower at the end than after one second.
void TestCli::pileSettlesToHexPacking()
{
    const CliResult r = runCli({"pile", "--balls", "300", "--seconds", "4", "--every", "1"});
    QCOMPARE(r.exitCode, 0);
    QVERIFY(r.err.isEmpty());
    QStringList rows;
    for (const QString& line : r.out.split('\n', Qt::SkipEmptyParts))
        if (line.trimmed().front().isDigit())
            rows << line;
    QCOMPARE(rows.size(), 4);
    auto column = [](const QString& row, int k) { return row.split(' ', Qt::SkipEmptyParts).at(k).toDouble(); };
    QCOMPARE(column(rows.last(), 0), 4.0);
    const double hex = (28 * (5 * 5 + 8.660254 * (0 + 2 + 4 + 6 + 8)) + 27 * (5 * 5 + 8.660254 * (1 + 3 + 5 + 7 + 9)) +
                        25 * (5 + 8.660254 * 10)) /
                       300.0;
    const double height = column(rows.last(), 6);
    QVERIFY2(height > 0.99 * hex && height < 1.03 * hex, qPrintable(QString("height %1, hex packing %2").arg(height).arg(hex)));
    QVERIFY2(column(rows.last(), 3) < column(rows.first(), 3), qPrintable(r.out));
}

QTEST_GUILESS_MAIN(TestCli)
#include "test_cli.moc"
