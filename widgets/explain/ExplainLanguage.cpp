#include "ExplainLanguage.h"

#include "i18n/DisplayNames.h"
#include "i18n/UiNumbers.h"

#include <QCoreApplication>
#include <QLocale>

namespace cuelab {

namespace {

// The core writes "0.5" and "0.5, 1.25"; the interface's language may write "0,5" and "0,5; 1,25"
// (UiNumbers.h), as every other number in the window.
std::string localNumber(const std::string& number)
{
    const QString point = QLocale().decimalPoint();
    if (point == QStringLiteral(".")) return number;
    QString s = QString::fromStdString(number);
    s.replace(QStringLiteral(", "), uiListSeparator());
    s.replace(QLatin1Char('.'), point);
    return s.toStdString();
}

}  // namespace

explain::Text::Lookup explainLanguage()
{
    return [](explain::Text::Kind kind, const std::string& source) -> std::string {
        switch (kind) {
        case explain::Text::Kind::Template:
            return QCoreApplication::translate(kExplainContext, source.c_str()).toStdString();
        case explain::Text::Kind::Element: return displayElementName(source).toStdString();
        case explain::Text::Kind::Name: return displayCoreName(source).toStdString();
        case explain::Text::Kind::Number: return localNumber(source);
        default: return source;
        }
    };
}

QString translated(const explain::Text& text) { return QString::fromStdString(text.in(explainLanguage())); }

}  // namespace cuelab
