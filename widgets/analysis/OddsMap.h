#pragma once
// A map of success odds over two parameters (the Analysis dock's odds section): one cell per grid
// point of a sweep with execution noise (core/analysis ShotOdds.h), coloured on a continuous scale
// from 0 % to 100 % shown beside it; the cell with the best odds is ringed, the current shot is a
// cross, the cell under the mouse is read out below the map, and a click asks to load a cell's shot.

#include "Odds.h"
#include "Sweep.h"

#include <QWidget>

#include <optional>
#include <vector>

namespace cuelab {

class OddsMap : public QWidget {
    Q_OBJECT
public:
    explicit OddsMap(QWidget* parent = nullptr);

    // A new, empty map of nx x ny cells (x varies fastest: cell index = iy * nx + ix).
    void reset(const analysis::Variation& x, const analysis::Variation& y);
    void clear();
    // The odds of cell `index`; nullopt: the cell's own values make the setup illegal.
    void setCell(long long index, const std::optional<analysis::OddsResult>& odds);
    void setCurrent(double x, double y);

    bool isEmpty() const { return nx_ == 0; }
    int columns() const { return nx_; }
    int rows() const { return ny_; }
    int filled() const { return filled_; }
    int bestCell() const { return best_; }  // -1 while no cell has odds
    std::optional<analysis::OddsResult> oddsOf(int index) const;
    std::vector<double> valuesOf(int index) const;  // {x, y}
    int cellAt(const QPointF& point) const;
    QPointF cellCentre(int index) const;
    // What the readout line says about a cell: "shot.heading 40.1 °, shot.speed 1.2 m/s: 72 % (68–76 %)".
    QString readout(int index) const;
    QString readoutText() const { return readout_; }

    // The colour of a probability on the scale (dark blue 0 % ... yellow 100 %, perceptually even).
    static QColor colourOf(double probability);

    QSize sizeHint() const override { return {360, 400}; }
    QSize minimumSizeHint() const override { return {190, 260}; }  // fits Coach's column at 800x600

signals:
    void cellClicked(int index);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void leaveEvent(QEvent* event) override;

private:
    QRectF plotRect() const;
    QRectF scaleRect() const;

    std::optional<analysis::Variation> x_, y_;
    int nx_ = 0, ny_ = 0, filled_ = 0, best_ = -1, hovered_ = -1;
    std::vector<std::optional<analysis::OddsResult>> odds_;
    std::vector<char> known_;
    std::optional<QPointF> current_;
    QString readout_;
};

}  // namespace cuelab
