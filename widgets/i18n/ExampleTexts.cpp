#include "i18n/ExampleTexts.h"

#include <QCoreApplication>

namespace cuelab {

QString translatedExampleText(const std::string& english)
{
    if (english.empty()) return QString();
    return QCoreApplication::translate("cuelab::examples", english.c_str());
}

void translateExample(Setup& setup)
{
    setup.name = translatedExampleText(setup.name).toStdString();
    setup.notes = translatedExampleText(setup.notes).toStdString();
}

}  // namespace cuelab
