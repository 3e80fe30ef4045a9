#include "Translations.h"

#include <QCoreApplication>
#include <QDir>
#include <QLibraryInfo>
#include <QTranslator>

#include <memory>

namespace cuelab {

namespace {

const QString kDirectory = QStringLiteral(":/i18n");

// The translators this file installed, so that a later call replaces them.
std::unique_ptr<QTranslator>& ownTranslator()
{
    static std::unique_ptr<QTranslator> translator;
    return translator;
}

std::unique_ptr<QTranslator>& qtTranslator()
{
    static std::unique_ptr<QTranslator> translator;
    return translator;
}

// The language installTranslations() last returned.
QString& shownLanguage()
{
    static QString language = QStringLiteral("en");
    return language;
}

void uninstall(std::unique_ptr<QTranslator>& translator)
{
    if (!translator) return;
    QCoreApplication::removeTranslator(translator.get());
    translator.reset();
}

}  // namespace

QLocale interfaceLocale(const QString& requested)
{
    return requested.isEmpty() ? QLocale::system() : QLocale(requested);
}

QString installTranslations(const QLocale& locale)
{
    uninstall(ownTranslator());
    uninstall(qtTranslator());
    auto own = std::make_unique<QTranslator>();
    // Tries every language of the locale in its order of preference: cuelab_hu_HU.qm, cuelab_hu.qm, ...
    shownLanguage() = QStringLiteral("en");
    if (!own->load(locale, QStringLiteral("cuelab"), QStringLiteral("_"), kDirectory) || own->isEmpty()) {
        // English text, English numbers (a German system without a German translation: "0.293 s").
        const bool english = locale.language() == QLocale::English || locale.language() == QLocale::C;
        QLocale::setDefault(english ? locale : QLocale(QLocale::English));
        return shownLanguage();
    }
    const QLocale shown(own->language().isEmpty() ? locale.name() : own->language());  // "hu_HU", from the .ts
    // The numbers the window shows (widgets/i18n/UiNumbers.h) and the spin boxes follow the language
    // shown: "0,293 s" beside Hungarian text. Files and the command line never use QLocale().
    QLocale::setDefault(locale.language() == shown.language() ? locale : shown);
    QCoreApplication::installTranslator(own.get());
    ownTranslator() = std::move(own);

    // Qt's own strings in the same language, when the system has them; English otherwise.
    auto qt = std::make_unique<QTranslator>();
    if (qt->load(shown, QStringLiteral("qtbase"), QStringLiteral("_"), QLibraryInfo::path(QLibraryInfo::TranslationsPath))) {
        QCoreApplication::installTranslator(qt.get());
        qtTranslator() = std::move(qt);
    }
    shownLanguage() = QLocale::languageToCode(shown.language());
    return shownLanguage();
}

QString installedLanguage()
{
    return shownLanguage();
}

QStringList translatedLanguages()
{
    QStringList languages;
    const QStringList files = QDir(kDirectory).entryList({QStringLiteral("cuelab_*.qm")}, QDir::Files, QDir::Name);
    for (const QString& file : files)  // cuelab_hu.qm, cuelab_pt_BR.qm
        languages << file.mid(QStringLiteral("cuelab_").size()).chopped(3).section(QLatin1Char('_'), 0, 0);
    languages.removeDuplicates();
    return languages;
}

}  // namespace cuelab
