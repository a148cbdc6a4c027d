#include "ui/window/language.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QSettings>
#include <QTranslator>

#include <memory>

namespace forcelab {

namespace {

const QString kLanguageKey = QStringLiteral("language");

struct Installed {
    QString code = QStringLiteral("en");
    std::unique_ptr<QTranslator> program;
    std::unique_ptr<QTranslator> qt;
};

Installed& installed()
{
    static Installed state;
    return state;
}

} // namespace

const QList<Language>& shippedLanguages()
{
    static const QList<Language> languages{
        {QStringLiteral("en"), QStringLiteral("English")},
        {QStringLiteral("de"), QStringLiteral("Deutsch")},
        {QStringLiteral("es"), QStringLiteral("Español")},
    };
    return languages;
}

bool applyLanguage(const QString& code)
{
    bool shipped = false;
    for (const Language& l : shippedLanguages())
        shipped = shipped || l.code == code;
    if (!shipped)
        return false;
    std::unique_ptr<QTranslator> program;
    std::unique_ptr<QTranslator> qt;
    if (code != QLatin1String("en")) {
        program = std::make_unique<QTranslator>();
        if (!program->load(QStringLiteral(":/i18n/forcelab_%1.qm").arg(code)))
            return false;
        // Qt's own words (Yes, Cancel, …) where Debian's qt6-translations-l10n put them; without them the
        // standard buttons stay English, nothing else changes.
        qt = std::make_unique<QTranslator>();
        if (!qt->load(QStringLiteral("qtbase_%1").arg(code), QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
            qt.reset();
    }
    Installed& now = installed();
    if (now.program)
        QCoreApplication::removeTranslator(now.program.get());
    if (now.qt)
        QCoreApplication::removeTranslator(now.qt.get());
    now.program = std::move(program);
    now.qt = std::move(qt);
    if (now.program)
        QCoreApplication::installTranslator(now.program.get());
    if (now.qt)
        QCoreApplication::installTranslator(now.qt.get());
    now.code = code;
    // Number fields follow the language: 1,5 in German, 1.5 in
    // English, never with thousands separators (a typed number is one group
    // of digits). Lesson files, traces and the command line keep their one
    // format: they are read with the C locale or from_chars, not this one.
    QLocale locale = code == QLatin1String("de")   ? QLocale(QLocale::German, QLocale::Germany)
                     : code == QLatin1String("es") ? QLocale(QLocale::Spanish, QLocale::Spain)
                                                   : QLocale::c();
    locale.setNumberOptions(QLocale::OmitGroupSeparator | QLocale::RejectGroupSeparator);
    QLocale::setDefault(locale);
    return true;
}

QString currentLanguage()
{
    return installed().code;
}

QString rememberedLanguage(QString* problem)
{
    const QString value = QSettings().value(kLanguageKey, QStringLiteral("en")).toString();
    for (const Language& l : shippedLanguages())
        if (l.code == value)
            return value;
    if (problem)
        *problem = QStringLiteral("%1: %2: \"%3\" is not a language of this program; using English")
                       .arg(QSettings().fileName(), kLanguageKey, value.left(40));
    return QStringLiteral("en");
}

void rememberLanguage(const QString& code)
{
    QSettings().setValue(kLanguageKey, code);
}

} // namespace forcelab
