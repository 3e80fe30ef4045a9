#include "ExplainLanguage.h"

#include "i18n/DisplayNames.h"

#include <QCoreApplication>

namespace cuelab {

explain::Text::Lookup explainLanguage()
{
    return [](explain::Text::Kind kind, const std::string& source) -> std::string {
        switch (kind) {
        case explain::Text::Kind::Template:
            return QCoreApplication::translate(kExplainContext, source.c_str()).toStdString();
        case explain::Text::Kind::Element: return displayElementName(source).toStdString();
        case explain::Text::Kind::Name: return displayCoreName(source).toStdString();
        default: return source;
        }
    };
}

QString translated(const explain::Text& text) { return QString::fromStdString(text.in(explainLanguage())); }

}  // namespace cuelab
