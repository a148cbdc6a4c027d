// The parameter table (sim/parameters.h) against the settings it describes:
// each row reads and writes its own field and no other, its default is
// allowed, its key and control are unique, and the world's validation refuses
// exactly what the row's range refuses.

#include "sim_test_util.h"

#include "sim/names.h"
#include "sim/parameter_reference.h"
#include "sim/parameters.h"
#include "sim/world.h"

#include <QFile>
#include <QTest>

#include <cmath>
#include <set>
#include <string>

using namespace forcelab::sim;
using forcelab::test::anotherValue;

namespace {

// Every row's value in a settings struct.
std::vector<double> allValues(const WorldSettings& s)
{
    std::vector<double> out;
    for (const Parameter& p : parameters())
        out.push_back(p.get(s));
    return out;
}

} // namespace

class TestParameters : public QObject {
    Q_OBJECT
private slots:
    void keysAndControlsAreUnique();
    void eachRowOwnsOneField();
    void defaultsAreAllowed();
    void validationFollowsTheRanges();
    void referenceIsUpToDate();
};

void TestParameters::keysAndControlsAreUnique()
{
    std::set<std::string_view> keys, controls;
    for (const Parameter& p : parameters()) {
        QVERIFY2(keys.insert(p.key).second, p.key.data());
        QVERIFY2(p.control.empty() || controls.insert(p.control).second, p.control.data());
        QVERIFY(findParameter(p.key) == &p);
        QVERIFY(!p.label.empty() && !p.help.empty());
        QVERIFY(p.get && p.set);
        QCOMPARE(p.type == ParameterType::Choice, p.choices != nullptr);
        if (p.type == ParameterType::Number || p.type == ParameterType::Integer) {
            QVERIFY2(p.lo < p.hi && p.sliderLo < p.sliderHi, p.key.data());
            QVERIFY2(p.sliderLo >= p.lo && p.sliderHi <= p.hi, p.key.data());
            QVERIFY2(p.scale == SliderScale::Linear || p.sliderLo > 0.0, p.key.data());
        }
    }
    qInfo("%zu parameters", parameters().size());
}

// Writing one row changes that row and no other: no two rows share a field,
// and no accessor writes somewhere else than it reads.
void TestParameters::eachRowOwnsOneField()
{
    const WorldSettings defaults;
    const std::vector<double> before = allValues(defaults);
    for (std::size_t i = 0; i < parameters().size(); ++i) {
        const Parameter& p = parameters()[i];
        WorldSettings s = defaults;
        const double v = anotherValue(p, before[i]);
        QVERIFY2(!checkValue(p, v), p.key.data());
        p.set(s, v);
        const std::vector<double> after = allValues(s);
        for (std::size_t j = 0; j < after.size(); ++j) {
            const double expected = j == i ? v : before[j];
            QVERIFY2(after[j] == expected, qPrintable(QString("writing %1 changed %2")
                                                          .arg(p.key.data())
                                                          .arg(parameters()[j].key.data())));
        }
    }
}

void TestParameters::defaultsAreAllowed()
{
    for (const Parameter& p : parameters()) {
        const auto problem = checkValue(p, defaultValue(p));
        QVERIFY2(!problem, qPrintable(QString("%1: %2").arg(p.key.data(), problem ? problem->c_str() : "")));
    }
    QVERIFY(!validateSettings(WorldSettings{}));
}

// Just outside each end of a number's range the world refuses the settings
// and names the row's key; at the end itself (when closed) it takes them.
void TestParameters::validationFollowsTheRanges()
{
    for (const Parameter& p : parameters()) {
        if (p.type != ParameterType::Number && p.type != ParameterType::Integer)
            continue;
        for (const auto& [end, open, outward] : {std::tuple{p.lo, p.loOpen, -1.0}, std::tuple{p.hi, p.hiOpen, 1.0}}) {
            const double step = p.type == ParameterType::Integer ? 1.0 : std::max(std::abs(end), 1.0) * 1e-9;
            WorldSettings s;
            p.set(s, end + outward * step);
            const auto refused = validateSettings(s);
            QVERIFY2(refused && refused->keyPath == p.key,
                     qPrintable(QString("%1 = %2: %3")
                                    .arg(p.key.data())
                                    .arg(end + outward * step)
                                    .arg(refused ? toString(*refused).c_str() : "accepted")));
            WorldSettings t;
            p.set(t, end);
            QCOMPARE(bool(validateSettings(t)), open);
        }
    }
}

// docs/parameters.md is what the table says today (regenerate it with
// `forcelab-cli params > docs/parameters.md`).
void TestParameters::referenceIsUpToDate()
{
    QFile file(QStringLiteral(FORCELAB_SOURCE_DIR "/docs/parameters.md"));
    QVERIFY2(file.open(QIODevice::ReadOnly), "docs/parameters.md is missing");
    const QByteArray onDisk = file.readAll();
    const std::string generated = parameterReference();
    QVERIFY2(onDisk == QByteArray::fromStdString(generated),
             "docs/parameters.md is out of date: run forcelab-cli params > docs/parameters.md");
    for (const Parameter& p : parameters()) {
        const std::string_view name = p.key.substr(p.key.rfind('.') + 1);
        QVERIFY(onDisk.contains('`' + QByteArray(name.data(), static_cast<qsizetype>(name.size())) + '`'));
    }
}

QTEST_APPLESS_MAIN(TestParameters)
#include "test_parameters.moc"
