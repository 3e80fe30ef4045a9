#include "UiNumbers.h"

#include <QLocale>

#include <cmath>

namespace cuelab {

namespace {

QLocale uiLocale()
{
    QLocale locale;
    locale.setNumberOptions(locale.numberOptions() | QLocale::OmitGroupSeparator);
    return locale;
}

}  // namespace

QString uiNumber(double value, int decimals)
{
    if (std::abs(value) < 0.5 * std::pow(10.0, -decimals)) value = 0.0;
    return uiLocale().toString(value, 'f', decimals);
}

QString uiSignificant(double value, int digits) { return uiLocale().toString(value, 'g', digits); }

QString uiListSeparator()
{
    return QLocale().decimalPoint() == QStringLiteral(",") ? QStringLiteral("; ") : QStringLiteral(", ");
}

}  // namespace cuelab
