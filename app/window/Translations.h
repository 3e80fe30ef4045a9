#pragma once
// The language of the window. English is the source language and needs no file; every other
// language is a Qt Linguist translation, resources/translations/cuelab_<language>.ts, compiled by
// lrelease at build time and embedded under :/i18n (app/CMakeLists.txt). At start the window
// follows the system's locale (QLocale::system(): LANGUAGE, LC_ALL, LC_MESSAGES, LANG), or the
// language given by `cuelab --language`; Qt's own strings (standard buttons and dialogs) follow
// from Qt's qtbase_<language>.qm when the system has it (Debian: qt6-translations-l10n).

#include <QLocale>
#include <QString>
#include <QStringList>

namespace cuelab {

// The locale whose language the interface shows: `requested` ("hu", "hu_HU", "en", "C") when not
// empty, else the system's.
QLocale interfaceLocale(const QString& requested);

// Installs the translations for `locale`'s languages (the first of QLocale::uiLanguages() that has
// one) and Qt's own for the same language, replacing those an earlier call installed. Returns the
// language shown: "hu", or "en" when no translation matched (English, the default). The default
// locale (QLocale::setDefault) follows the language shown, so that the numbers the window shows do
// too ("0,293 s" in Hungarian: widgets/i18n/UiNumbers.h).
QString installTranslations(const QLocale& locale);

// The language the last installTranslations() call installed: "hu", or "en" (also before any call).
QString installedLanguage();

// The languages with a built-in translation, besides English: {"hu"}.
QStringList translatedLanguages();

}  // namespace cuelab
