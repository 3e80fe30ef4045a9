#pragma once
// How the editor shows and edits physical quantities: numbers with their SI unit, vectors in
// parentheses, spin boxes that carry the unit as a suffix and explain it in the tooltip.

#include "Types.h"

#include <QString>

#include <string_view>

class QDoubleSpinBox;
class QWidget;

namespace cuelab {

QString toQString(std::string_view text);  // the core's names ("rolling", "ball-ball") for the UI
QString formatNumber(double value, int decimals);
QString formatQuantity(double value, const QString& unit, int decimals);       // "1.234 m/s"
QString formatVector(const Vec2& v, const QString& unit, int decimals);        // "(1.234, 0.500) m"
QString formatVector(const Vec3& v, const QString& unit, int decimals);

struct SpinBoxSpec {
    double minimum = 0.0;
    double maximum = 1.0;
    int decimals = 3;
    double step = 0.01;
    QString unit;      // shown as a suffix when not empty
    QString toolTip;   // what it is, with its unit
};

QDoubleSpinBox* makeSpinBox(const SpinBoxSpec& spec, QWidget* parent);

}  // namespace cuelab
