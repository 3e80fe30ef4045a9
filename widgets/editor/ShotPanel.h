#pragma once
// The Shot dock: the cue strike at t = 0 (which ball, cue speed, heading, elevation, tip offset,
// cue mass). Slider drags and tip drags merge into one undo step each.

#include <QWidget>

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

private:
    enum Field { Enabled, BallField, Speed, Heading, Elevation, Tip, CueMass };
    void refresh();
    void commit(Field field, const QString& text);

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
    bool refreshing_ = false;
};

}  // namespace cuelab
