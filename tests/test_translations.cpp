// The shipped languages hold every string of the program: lupdate reads
// ui/ and app/ now (the sources as they are, not the .ts files' idea of
// them) and every string it finds must have a finished translation in each
// shipped .ts file, with the same placeholders (%1 … %9, %n) as the English.
// So a new tr() string cannot slip into the program untranslated. The
// compiled .qm files are built in and translate.

#include "ui/window/language.h"
#include "ui/i18n/parameter_words.h"
#include "sim/world/parameters.h"
#include "sim/forces/force_models.h"
#include "ui/drawing/overlays/panel.h"

#include <QCoreApplication>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>
#include <QTranslator>
#include <QXmlStreamReader>

namespace {

struct Message {
    QString context;
    QString source;
    QString comment;
    QStringList translations; // one, or the numerus forms
    bool finished = false;
    QString key() const { return context + QChar(0x1f) + source + QChar(0x1f) + comment; }
};

QList<Message> readTs(const QString& path, QString* error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = path + QStringLiteral(": cannot open");
        return {};
    }
    QList<Message> out;
    QXmlStreamReader xml(&file);
    QString context;
    Message m;
    bool inMessage = false;
    while (!xml.atEnd()) {
        xml.readNext();
        if (xml.isStartElement()) {
            const auto name = xml.name();
            if (name == QLatin1String("name") && !inMessage)
                context = xml.readElementText();
            else if (name == QLatin1String("message")) {
                m = Message{context, {}, {}, {}, false};
                inMessage = true;
            } else if (name == QLatin1String("source"))
                m.source = xml.readElementText();
            else if (name == QLatin1String("comment"))
                m.comment = xml.readElementText();
            else if (name == QLatin1String("translation")) {
                const auto type = xml.attributes().value(QLatin1String("type"));
                m.finished = type.isEmpty();
                // A plain translation is text; a numerus one holds <numerusform>s.
                QString text;
                while (!xml.atEnd()) {
                    xml.readNext();
                    if (xml.isCharacters())
                        text += xml.text();
                    else if (xml.isStartElement() && xml.name() == QLatin1String("numerusform"))
                        m.translations << xml.readElementText();
                    else if (xml.isEndElement() && xml.name() == QLatin1String("translation"))
                        break;
                }
                if (m.translations.isEmpty())
                    m.translations << text;
            }
        } else if (xml.isEndElement() && xml.name() == QLatin1String("message")) {
            out << m;
            inMessage = false;
        }
    }
    if (xml.hasError())
        *error = QStringLiteral("%1:%2: %3").arg(path).arg(xml.lineNumber()).arg(xml.errorString());
    return out;
}

QSet<QString> placeholders(const QString& text)
{
    static const QRegularExpression pattern(QStringLiteral("%L?[1-9]|%n"));
    QSet<QString> found;
    for (auto it = pattern.globalMatch(text); it.hasNext();)
        found.insert(it.next().captured().remove(QLatin1Char('L')));
    return found;
}

} // namespace

class TestTranslations : public QObject {
    Q_OBJECT
private slots:
    void everyStringOfTheProgramIsTranslated();
    void theBuiltInTranslationsTranslate();
    void everyParameterLabelIsListedForTranslation();
};

void TestTranslations::everyStringOfTheProgramIsTranslated()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString fresh = dir.filePath(QStringLiteral("fresh.ts"));
    // The sources and include paths CMake gives lupdate (qt_add_lupdate in
    // ui/CMakeLists.txt), made into lupdate's project file as its own target does.
    const QString project = dir.filePath(QStringLiteral("project.json"));
    QProcess cmake;
    cmake.start(QStringLiteral(FORCELAB_CMAKE),
                {QStringLiteral("-DIN_FILE=" FORCELAB_LUPDATE_PROJECT), QStringLiteral("-DOUT_FILE=") + project,
                 QStringLiteral("-P"), QStringLiteral(FORCELAB_LUPDATE_PROJECT_SCRIPT)});
    QVERIFY2(cmake.waitForFinished(60000) && cmake.exitCode() == 0, cmake.readAllStandardError().constData());
    QProcess lupdate;
    lupdate.start(QStringLiteral(FORCELAB_LUPDATE), {QStringLiteral("-silent"), QStringLiteral("-project"), project,
                                                    QStringLiteral("-no-obsolete"), QStringLiteral("-locations"),
                                                    QStringLiteral("none"), QStringLiteral("-ts"), fresh});
    QVERIFY2(lupdate.waitForFinished(300000), "lupdate did not finish in 5 minutes");
    QVERIFY2(lupdate.exitCode() == 0, lupdate.readAllStandardError().constData());
    QString error;
    const QList<Message> program = readTs(fresh, &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QVERIFY2(program.size() > 600, qPrintable(QString::number(program.size())));

    QStringList problems;
    // Every shipped language but English, the source.
    for (const forcelab::Language& language : forcelab::shippedLanguages()) {
        if (language.code == QLatin1String("en"))
            continue;
        const QByteArray codeBytes = language.code.toLatin1();
        const char* code = codeBytes.constData();
        const QString path = QStringLiteral(FORCELAB_SOURCE_DIR "/ui/i18n/forcelab_%1.ts").arg(language.code);
        const QList<Message> shipped = readTs(path, &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QHash<QString, Message> byKey;
        for (const Message& m : shipped)
            byKey.insert(m.key(), m);
        int missing = 0;
        for (const Message& m : program) {
            const auto it = byKey.constFind(m.key());
            QString why;
            if (it == byKey.cend())
                why = QStringLiteral("not in the file (run: cmake --build build --target update_translations)");
            else if (!it->finished || it->translations.join(QString()).trimmed().isEmpty())
                why = QStringLiteral("not translated");
            else
                for (const QString& t : it->translations)
                    if (placeholders(t) != placeholders(m.source) &&
                        !(placeholders(m.source).contains(QStringLiteral("%n")) &&
                          placeholders(t) + QSet<QString>{QStringLiteral("%n")} == placeholders(m.source)))
                        why = QStringLiteral("placeholders differ: \"%1\"").arg(t.left(80));
            if (!why.isEmpty()) {
                if (++missing <= 10)
                    problems << QStringLiteral("%1: %2 \"%3\": %4").arg(QLatin1String(code), m.context, m.source.left(80), why);
            }
        }
        if (missing > 10)
            problems << QStringLiteral("%1: … and %2 more").arg(QLatin1String(code)).arg(missing - 10);
        qInfo("%s: %lld strings of the program, %d not translated", code, static_cast<long long>(program.size()), missing);
    }
    QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
}

// The .qm files are built in: switching to German translates the View menu's
// title, and back to English gives the source again.
void TestTranslations::theBuiltInTranslationsTranslate()
{
    for (const forcelab::Language& language : forcelab::shippedLanguages()) {
        if (language.code == QLatin1String("en"))
            continue;
        QVERIFY2(forcelab::applyLanguage(language.code), qPrintable(language.code));
        QCOMPARE(forcelab::currentLanguage(), language.code);
        const QString view = QCoreApplication::translate("forcelab::MainWindow", "&View");
        QVERIFY2(!view.isEmpty() && view != QLatin1String("&View"), qPrintable(view));
    }
    QVERIFY(forcelab::applyLanguage(QStringLiteral("en")));
    QCOMPARE(QCoreApplication::translate("forcelab::MainWindow", "&View"), QStringLiteral("&View"));
    QVERIFY(!forcelab::applyLanguage(QStringLiteral("xx")));
    QCOMPARE(forcelab::currentLanguage(), QStringLiteral("en"));
}

// sim/'s parameter labels and help reach lupdate through ui/i18n/parameter_words.cpp:
// a parameter added to sim/world/parameters.cpp must be listed there.
void TestTranslations::everyParameterLabelIsListedForTranslation()
{
    const QStringList listed = forcelab::listedParameterLabels();
    const QStringList listedHelp = forcelab::listedParameterHelp();
    QStringList missing;
    for (const forcelab::sim::Parameter& p : forcelab::sim::parameters()) {
        const QString label = QString::fromUtf8(p.label.data(), static_cast<qsizetype>(p.label.size()));
        if (!listed.contains(label))
            missing << label;
        const QString help = QString::fromUtf8(p.help.data(), static_cast<qsizetype>(p.help.size()));
        // (each row's help is its tooltip)
        if (!help.isEmpty() && !listedHelp.contains(help))
            missing << help;
    }
    QVERIFY2(missing.isEmpty(), qPrintable(QStringLiteral("not in ui/i18n/parameter_words.cpp: ") + missing.join(QStringLiteral(", "))));
    // The force models' names, painted in the forces-by-source legend.
    const QStringList forces = forcelab::listedForceModelNames();
    for (const forcelab::sim::ForceModelInfo& m : forcelab::sim::forceModels())
        QVERIFY2(forces.contains(QString::fromUtf8(m.name.data(), qsizetype(m.name.size()))),
                 qPrintable(QStringLiteral("not in ui/drawing/overlays/panel.cpp: ") + QString::fromUtf8(m.name.data(), qsizetype(m.name.size()))));
    QVERIFY(forcelab::applyLanguage(QStringLiteral("de")));
    const QString drag = forcelab::parameterLabel(*forcelab::sim::findParameter("models.drag.k"));
    const QString dragHelp = forcelab::parameterHelp(*forcelab::sim::findParameter("models.drag.k"));
    QVERIFY(forcelab::applyLanguage(QStringLiteral("en")));
    QVERIFY2(!drag.isEmpty() && drag != QStringLiteral("Drag k"), qPrintable(drag));
    const auto* k = forcelab::sim::findParameter("models.drag.k");
    QVERIFY2(!dragHelp.isEmpty() && dragHelp != QString::fromUtf8(k->help.data(), qsizetype(k->help.size())), qPrintable(dragHelp));
}

QTEST_MAIN(TestTranslations)
#include "test_translations.moc"
