#pragma once
// The program's languages: English (the source) and those with a
// translation built in (ui/i18n/forcelab_XX.ts, compiled to
// ":/i18n/forcelab_XX.qm"). Applying one installs the program's
// translator and Qt's own (standard dialogs' buttons) and makes number
// fields write and read numbers the language's way (1,5 in German); the
// choice is remembered in the settings.
#include <QList>
#include <QString>

namespace forcelab {

struct Language {
    QString code; ///< "en", "de"
    QString name; ///< in its own language: "English", "Deutsch"
};

/// English first, then every translation shipped, in a fixed order.
const QList<Language>& shippedLanguages();

/// Installs `code`'s translators (removing the previous ones). False, and
/// nothing changed, when `code` is not shipped or its file does not load.
bool applyLanguage(const QString& code);
/// The language applied now ("en" until another is).
QString currentLanguage();


/// The language the settings remember, or "en"; a value that is not a
/// shipped language gives "en" and `problem` says so (key and value).
QString rememberedLanguage(QString* problem = nullptr);
void rememberLanguage(const QString& code);

} // namespace forcelab
