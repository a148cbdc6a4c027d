// forcelab-cli sweep --quick, driven as a process: the CSV's columns and rows,
// the fitted orders against theory, the symplectic methods' bounded energy
// next to rk4's drift, the reference integrator's error, and the chart.

#include <QFile>
#include <QImage>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>

#include "cli_runner.h"

#include <cmath>
#include <map>

namespace {

using forcelab::test::CliResult;
using forcelab::test::runCli;


const QStringList kColumns{"problem",        "integrator",   "dt",      "tolerance",
                           "steps",          "force_evaluations", "position_error", "energy_error",
                           "wall_ms",        "ns_per_step_per_ball", "blew_up"};

// The quick sweep's problems and the integrators every one of them runs.
const QStringList kQuickProblems{"kepler-e0-10", "kepler-e0.5-10", "drag", "spring", "bounce", "two-balls"};
const QStringList kAllButExact{"euler", "semi-implicit-euler", "verlet", "rk4", "yoshida4", "rk45", "ias15"};

// The cells of the "Fitted order" table's row for a problem: one number per
// fixed-step integrator (euler, semi-implicit-euler, verlet, rk4, yoshida4),
// NaN where too few runs were in the asymptotic range.
QList<double> fittedOrders(const QString& table, const QString& problem)
{
    const qsizetype start = table.indexOf("Fitted order");
    const QStringList lines = table.mid(start).split('\n');
    for (const QString& line : lines) {
        if (!line.startsWith(problem + ' '))
            continue;
        QList<double> orders;
        static const QRegularExpression cell(R"((-?[0-9.]+|-) \((\d+) pts\))");
        auto it = cell.globalMatch(line);
        while (it.hasNext()) {
            const auto m = it.next();
            orders.append(m.captured(1) == "-" ? std::nan("") : m.captured(1).toDouble());
        }
        return orders;
    }
    return {};
}

} // namespace

class TestSweep : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void csvHasColumnsAndRows();
    void fittedOrdersMatchTheory();
    void symplecticEnergyStaysBounded();
    void referenceReachesMachinePrecision();
    void chartIsDrawn();
    void oneProblemChart();
    void unknownProblemIsRefused();

private:
    QTemporaryDir m_dir;
    CliResult m_run;
    QList<QStringList> m_rows; // CSV rows without the header
    QStringList m_header;
};

void TestSweep::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_run = runCli({"sweep", "--quick", "--csv", m_dir.filePath("sweep.csv"), "--png", m_dir.filePath("sweep.png")});
    QCOMPARE(m_run.exitCode, 0);
    QVERIFY(m_run.err.contains("sweep [")); // the progress bar
    QFile f(m_dir.filePath("sweep.csv"));
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QStringList lines = QString::fromUtf8(f.readAll()).split('\n', Qt::SkipEmptyParts);
    QVERIFY(lines.size() > 1);
    m_header = lines.front().split(',');
    for (qsizetype i = 1; i < lines.size(); ++i)
        m_rows.append(lines[i].split(','));
}

void TestSweep::csvHasColumnsAndRows()
{
    QCOMPARE(m_header, kColumns);
    std::map<std::pair<QString, QString>, int> runs;
    for (const QStringList& row : m_rows) {
        QCOMPARE(row.size(), kColumns.size());
        QVERIFY2(kQuickProblems.contains(row[0]), qPrintable(row[0]));
        ++runs[std::pair(row[0], row[1])];
        bool ok = false;
        QVERIFY(row[2].toDouble(&ok) > 0.0 && ok); // dt
        QVERIFY(row[4].toLongLong(&ok) > 0 && ok); // steps
        if (row[10] == "0") {
            QVERIFY(row[5].toLongLong(&ok) >= row[4].toLongLong() && ok); // at least one evaluation a step
            QVERIFY(row[6].toDouble(&ok) >= 0.0 && ok);
            QVERIFY(row[8].toDouble(&ok) >= 0.0 && ok);
        }
    }
    // Every problem by every integrator over at least three steps or
    // tolerances; exact only where the acceleration is constant.
    for (const QString& p : kQuickProblems) {
        for (const QString& i : kAllButExact)
            QVERIFY2((runs[std::pair(p, i)] >= 3), qPrintable(p + " " + i));
        const bool constant = p == "bounce" || p == "two-balls";
        QCOMPARE((runs[std::pair(p, QString("exact"))] > 0), constant);
    }
    // The table on stdout has a block per problem.
    for (const QString& p : kQuickProblems)
        QVERIFY(m_run.out.contains(p + ": "));
}

// The spring is a linear problem with one error term, so the slopes are clean
// for all five; on the circular orbit verlet and yoshida4 are clean too (rk4
// and semi-implicit Euler have a second term there: see docs/accuracy.md).
void TestSweep::fittedOrdersMatchTheory()
{
    const QString table = m_run.out;
    const QList<double> theory{1.0, 1.0, 2.0, 4.0, 4.0};
    const QList<double> spring = fittedOrders(table, "spring");
    QCOMPARE(spring.size(), 5);
    for (int i = 0; i < 5; ++i)
        QVERIFY2(std::abs(spring[i] - theory[i]) <= 0.1, qPrintable(QString("spring %1: %2").arg(i).arg(spring[i])));
    const QList<double> kepler = fittedOrders(table, "kepler-e0-10");
    QCOMPARE(kepler.size(), 5);
    QVERIFY2(std::abs(kepler[2] - 2.0) <= 0.1, qPrintable(QString::number(kepler[2])));
    QVERIFY2(std::abs(kepler[4] - 4.0) <= 0.1, qPrintable(QString::number(kepler[4])));
}

// "Energy over long runs": growth = (max |dE/E| up to 100 orbits) / (up to 10).
void TestSweep::symplecticEnergyStaysBounded()
{
    const QString table = m_run.out;
    const qsizetype start = table.indexOf("Energy over long runs");
    QVERIFY(start >= 0);
    std::map<QString, double> growth;
    for (const QString& line : table.mid(start).split('\n')) {
        static const QRegularExpression row(R"(^(\S+)\s+([0-9.e+-]+)\s+([0-9.e+-]+)\s+([0-9.]+)x$)");
        const auto m = row.match(line);
        if (m.hasMatch())
            growth[m.captured(1)] = m.captured(4).toDouble();
    }
    for (const char* symplectic : {"semi-implicit-euler", "verlet", "yoshida4"}) {
        QVERIFY2(growth.count(symplectic), symplectic);
        QVERIFY2(growth[symplectic] <= 1.2, qPrintable(QString("%1 %2").arg(symplectic).arg(growth[symplectic])));
    }
    // rk4 drifts: ten times the orbits, about ten times the error.
    QVERIFY(growth.count("rk4"));
    QVERIFY2(growth["rk4"] >= 7.0 && growth["rk4"] <= 13.0, qPrintable(QString::number(growth["rk4"])));
}

// ias15 at its default tolerance on the Kepler problems: energy to 1e-12
// relative at every sample, position to 1e-11 of the orbit's size.
void TestSweep::referenceReachesMachinePrecision()
{
    int checked = 0;
    for (const QStringList& row : m_rows) {
        if (row[1] != "ias15" || row[3].toDouble() != 1e-9 || !row[0].startsWith("kepler"))
            continue;
        QCOMPARE(row[10], QString("0"));
        QVERIFY2(row[7].toDouble() <= 1e-12, qPrintable(row.join(',')));
        QVERIFY2(row[6].toDouble() <= 1e-9, qPrintable(row.join(','))); // px, on a 100 px orbit
        ++checked;
    }
    QVERIFY(checked >= 4);
}

// Six panels (two columns, three rows), each with a line per integrator in
// its own colour.
void TestSweep::chartIsDrawn()
{
    QVERIFY(m_run.out.contains("chart written to"));
    const QImage image(m_dir.filePath("sweep.png"));
    QVERIFY(!image.isNull());
    QCOMPARE(image.size(), QSize(2 * 760, 3 * 480));
    QSet<QRgb> colours;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            colours.insert(image.pixel(x, y) & 0xffffff);
    for (QRgb c : {0xd62728u, 0xff7f0eu, 0x2ca02cu, 0x1f77b4u, 0x9467bdu, 0x8c564bu, 0x111111u})
        QVERIFY2(colours.contains(c), qPrintable(QString::number(c, 16)));
}

void TestSweep::oneProblemChart()
{
    const QString png = m_dir.filePath("one.png");
    const CliResult r = runCli({"sweep", "--quick", "--problem", "spring", "--png", png});
    QCOMPARE(r.exitCode, 0);
    QVERIFY(r.out.contains("spring: "));
    QVERIFY(!r.out.contains("kepler-e0-10: "));
    const QImage image(png);
    QCOMPARE(image.size(), QSize(760, 480));
    QVERIFY(QFile(png).size() > 1000);
}

void TestSweep::unknownProblemIsRefused()
{
    const CliResult r = runCli({"sweep", "--problem", "pendulum"});
    QCOMPARE(r.exitCode, 2);
    QVERIFY(r.err.contains("\"pendulum\" is not one of kepler-e0-10"));
    QVERIFY(r.out.isEmpty());
}

QTEST_GUILESS_MAIN(TestSweep)
#include "test_sweep.moc"
