#pragma once
// One 1-D tolerance bar of the Analysis dock: the scanned range of a parameter left to right, each
// grid value coloured by whether the shot met the goal, the refined success window as a band with
// its edges, the current value as a line, the window in words above it ("Heading: from 39.84° to
// 40.23°, ±0.19°"; the goal is said once, above the bars) and the scale under it: the scanned
// range's ends and the current value, with the unit.

#include "Tolerance.h"

#include <QWidget>

#include <optional>

namespace cuelab {

class ToleranceBar : public QWidget {
    Q_OBJECT
public:
    ToleranceBar(QString label, QWidget* parent = nullptr);

    void setScan(const analysis::ToleranceScan& scan);
    void setPending(const QString& text);  // "scanning…", "not scanned" (drops the scan)
    bool hasScan() const { return scan_.has_value(); }
    const std::optional<analysis::ToleranceScan>& scan() const { return scan_; }
    QString text() const { return text_; }  // the window in words, as shown

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    QString label_;
    QString text_;
    std::optional<analysis::ToleranceScan> scan_;
};

// Decimals that show a window of this key sensibly (degrees to 0.01, speeds to 0.001 m/s, ...).
int decimalsFor(const std::string& key);
// A value of the key with its unit, as the bars and the table write it ("39.84°", "2.000 m/s").
QString valueText(const std::string& key, double value);

}  // namespace cuelab
