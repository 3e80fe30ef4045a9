#pragma once
// The chart of the Plots dock with its interaction: a cursor line dragged with the left button to
// scrub, wheel zoom (time axis; Ctrl: value axis), Shift- or middle-drag to pan, double-click to
// show everything, and event markers that name their event on hover and select it on click.

#include <QChartView>

#include <vector>

class QLineSeries;
class QScatterSeries;
class QValueAxis;

namespace cuelab {

class PlotsChartView : public QChartView {
    Q_OBJECT
public:
    explicit PlotsChartView(QWidget* parent = nullptr);

    QValueAxis* timeAxis() const { return timeAxis_; }
    QValueAxis* valueAxis() const { return valueAxis_; }

    // The full ranges, shown by resetZoom().
    void setFullRange(double t0, double t1, double v0, double v1);
    void resetZoom();

    void setCursorTime(double t);
    double cursorTime() const { return cursor_; }

    // Markers: one per event at (time, value), with its index and its name for the tooltip.
    struct Marker {
        double time = 0.0;
        double value = 0.0;
        int event = -1;
        QString name;
    };
    void setMarkers(std::vector<Marker> markers);
    const std::vector<Marker>& markers() const { return markers_; }
    void setHighlightedEvent(int event);

    // Where a time falls on the widget (x pixel), for tests that drag the cursor.
    QPointF positionOf(double t, double v) const;

signals:
    void cursorDragged(double t);
    void markerClicked(int event);

protected:
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    void updateCursorLine();
    int markerAt(const QPointF& widgetPos) const;  // event index, -1 if none near
    double timeAt(const QPointF& widgetPos) const;

    QValueAxis* timeAxis_ = nullptr;
    QValueAxis* valueAxis_ = nullptr;
    QLineSeries* cursorLine_ = nullptr;
    QScatterSeries* markerSeries_ = nullptr;
    QScatterSeries* highlightSeries_ = nullptr;
    std::vector<Marker> markers_;
    double fullT0_ = 0.0, fullT1_ = 1.0, fullV0_ = 0.0, fullV1_ = 1.0;
    double cursor_ = 0.0;
    enum class Drag { None, Cursor, Pan } drag_ = Drag::None;
    QPointF lastPos_;
};

}  // namespace cuelab
