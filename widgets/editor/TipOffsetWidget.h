#pragma once
// The cue ball's face as the player sees it: click or drag to place the cue tip. The offset is a
// fraction of the ball radius, + = right of centre (side) and above centre (height), as in the
// setup file's "side" and "height".

#include <QPointF>
#include <QWidget>

namespace cuelab {

class TipOffsetWidget : public QWidget {
    Q_OBJECT
public:
    explicit TipOffsetWidget(QWidget* parent = nullptr);

    // The offset, each component a fraction of the radius; its length is at most kMaxOffset.
    QPointF offset() const { return offset_; }
    void setOffset(const QPointF& sideHeight);  // does not emit

    // Beyond about half the radius the tip slips off the ball: a miscue (Alciatore, TP A-30
    // discussion; the usual practical limit is 0.5 R). The widget allows a little more for study.
    static constexpr double kMiscueLimit = 0.5;
    static constexpr double kMaxOffset = 0.7;

    QSize sizeHint() const override { return {130, 130}; }
    QSize minimumSizeHint() const override { return {90, 90}; }
    bool hasHeightForWidth() const override { return true; }
    int heightForWidth(int w) const override { return w; }

signals:
    void offsetEdited(const QPointF& sideHeight);  // while the user clicks or drags
    void editingFinished();                        // the mouse button is released

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;

private:
    QRectF ballRect() const;
    QPointF offsetAt(const QPointF& widgetPos) const;

    QPointF offset_;  // (side, height) / R
};

}  // namespace cuelab
