#pragma once
// Squirt in the Shot dock: a switch and the cue tip's end mass (grams in the UI, kg in the file's
// shot.end_mass). Off = no end mass = no squirt, the ball leaves along the cue line (Alciatore
// TP A-31, core/physics/CueImpact.h). Each change is an undoable edit of the document's shot.

#include <QWidget>

class QCheckBox;
class QDoubleSpinBox;

namespace cuelab {

class Document;

class SquirtControl : public QWidget {
    Q_OBJECT
public:
    explicit SquirtControl(Document* document, QWidget* parent = nullptr);

private:
    void refresh();
    void commit(bool fromSwitch);

    Document* document_;
    QCheckBox* enabled_;
    QDoubleSpinBox* endMass_;  // g
    bool refreshing_ = false;
};

}  // namespace cuelab
