#pragma once
// The 2-D map of the Analysis dock: one cell per shot of a two-parameter sweep (the tip-offset disk
// or any two keys), coloured by its outcome class, with axes, a legend with counts, the current
// shot marked, a tooltip per cell, and a click that asks to load the cell's shot.

#include "Map.h"
#include "Tolerance.h"

#include <QWidget>

#include <array>
#include <optional>
#include <vector>

namespace cuelab {

class OutcomeMap : public QWidget {
    Q_OBJECT
public:
    explicit OutcomeMap(QWidget* parent = nullptr);

    // A new, empty map: nx x ny cells over the given ranges (x varies fastest in the results).
    void reset(const analysis::Variation& x, const analysis::Variation& y, bool disk);
    void clear();  // no map at all
    // A result of the sweep (any order); index = iy * nx + ix.
    void addResult(const analysis::ShotResult& shot, const QString& tip);
    void setCurrent(double x, double y);  // the setup's own values (a cross)
    void setStale(bool stale);            // drawn faded: it belongs to an earlier setup

    bool isEmpty() const { return nx_ == 0; }
    int columns() const { return nx_; }
    int rows() const { return ny_; }
    int filled() const { return filled_; }
    std::array<int, analysis::kShotClassCount> counts() const { return counts_; }
    // The cell under a widget point, or -1; and a cell's centre in widget coordinates (for tests).
    int cellAt(const QPointF& point) const;
    QPointF cellCentre(int index) const;
    analysis::ShotClass classOf(int index) const { return classes_[static_cast<std::size_t>(index)]; }
    std::vector<double> valuesOf(int index) const;  // {x, y}

    static QColor colourOf(analysis::ShotClass c);

    QSize sizeHint() const override { return {360, 420}; }
    QSize minimumSizeHint() const override { return {190, 260}; }  // fits Coach's column at 800x600

signals:
    void cellClicked(double x, double y, int index);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    bool event(QEvent* event) override;  // tooltips

private:
    QRectF plotRect() const;

    std::optional<analysis::Variation> x_, y_;
    bool disk_ = false;
    int nx_ = 0, ny_ = 0;
    int filled_ = 0;
    bool stale_ = false;
    std::vector<analysis::ShotClass> classes_;
    std::vector<bool> known_;
    std::vector<QString> tips_;
    std::array<int, analysis::kShotClassCount> counts_{};
    std::optional<QPointF> current_;
};

}  // namespace cuelab
