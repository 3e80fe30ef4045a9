#pragma once
// Aiming relative to an object ball in the Shot dock (issue 22): "aim at the 1, cut 30° left". The
// object ball, the cut angle and its side set the shot's heading through core/aim (headingForCut: the
// straight cue line from the struck ball that meets the object ball at that cut), one undoable edit
// that merges while the cut's arrows are held, like the heading's own field. When the heading changes
// otherwise, the fields show the cut the straight cue line makes with the chosen ball (or that it
// misses). Below them, what the simulation made of it: the struck ball's first contact, its cut angle
// and ball fraction (aim::firstContact), which swerve, squirt and cushions may move away from the plan.

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;

namespace cuelab {

class Document;

class AimControl : public QWidget {
    Q_OBJECT
public:
    explicit AimControl(Document* document, QWidget* parent = nullptr);

    QComboBox* objectBall() const { return object_; }
    QDoubleSpinBox* cutAngle() const { return cut_; }
    QComboBox* cutSide() const { return side_; }
    QLabel* firstContact() const { return contact_; }

private:
    void refresh();         // the fields from the setup's heading
    void refreshContact();  // the simulated first contact
    void commit();

    Document* document_;
    QComboBox* object_;
    QDoubleSpinBox* cut_;
    QComboBox* side_;
    QLabel* contact_;
    bool refreshing_ = false;
};

}  // namespace cuelab
