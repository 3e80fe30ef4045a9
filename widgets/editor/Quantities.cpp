#include "Quantities.h"

#include "i18n/UiNumbers.h"

#include <QDoubleSpinBox>


namespace cuelab {

QString toQString(std::string_view text)
{
    return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

QString formatNumber(double value, int decimals)
{
    return uiNumber(value, decimals);  // in the interface's language: "0,293" in Hungarian
}

QString formatQuantity(double value, const QString& unit, int decimals)
{
    return unit.isEmpty() ? formatNumber(value, decimals)
                          : formatNumber(value, decimals) + QChar(0x2009) + unit;
}

QString formatVector(const Vec2& v, const QString& unit, int decimals)
{
    return QStringLiteral("(%1%2%3) %4").arg(formatNumber(v.x(), decimals), uiListSeparator(), formatNumber(v.y(), decimals), unit);
}

QString formatVector(const Vec3& v, const QString& unit, int decimals)
{
    const QString sep = uiListSeparator();
    return QStringLiteral("(%1%2%3%4%5) %6")
        .arg(formatNumber(v.x(), decimals), sep, formatNumber(v.y(), decimals), sep, formatNumber(v.z(), decimals), unit);
}

QDoubleSpinBox* makeSpinBox(const SpinBoxSpec& spec, QWidget* parent)
{
    auto* box = new QDoubleSpinBox(parent);
    box->setRange(spec.minimum, spec.maximum);
    box->setDecimals(spec.decimals);
    box->setSingleStep(spec.step);
    if (!spec.unit.isEmpty()) box->setSuffix(QChar(0x2009) + spec.unit);
    box->setToolTip(spec.toolTip);
    box->setKeyboardTracking(false);  // typing "0.25" is one edit, not "0", "0.", "0.2", "0.25"
    box->setAccelerated(true);
    box->setAlignment(Qt::AlignRight);
    return box;
}

}  // namespace cuelab
