#pragma once
// The Shot dock: the cue strike at t = 0 (which ball, cue speed, heading, elevation, tip offset,
// cue mass). Slider drags and tip drags merge into one undo step each. In a narrow dock (a small
// window) the tip picker stands above its Side and Height fields instead of beside them, so that
// every field stays whole without sideways scrolling.

#include <QWidget>

class QBoxLayout;
class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QSlider;

namespace cuelab {

class Document;
class TipOffsetWidget;

class ShotPanel : public QWidget {
    Q_OBJECT
public:
    explicit ShotPanel(Document* document, QWidget* parent = nullptr);

    TipOffsetWidget* tipOffsetWidget() const { return tip_; }
    bool tipStacked() const;  // the tip picker above its fields (a narrow dock)

protected:
    void showEvent(QShowEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    enum Field { Enabled, BallField, Speed, Heading, Elevation, Tip, CueMass };
    void refresh();
    void commit(Field field, const QString& text);
    void fitTipRow(int available);  // px the panel may take (its scroll area's viewport)

    Document* document_;
    QCheckBox* enabled_;
    QComboBox* ball_;
    QDoubleSpinBox* speed_;
    QSlider* speedSlider_;
    QDoubleSpinBox* heading_;
    QSlider* headingSlider_;
    QDoubleSpinBox* elevation_;
    QDoubleSpinBox* side_;
    QDoubleSpinBox* height_;
    TipOffsetWidget* tip_;
    QDoubleSpinBox* cueMass_;
    QBoxLayout* tipRow_ = nullptr;
    int sideBySideWidth_ = 0;  // px the panel needs with the picker beside its fields
    bool refreshing_ = false;
};

}  // namespace cuelab
