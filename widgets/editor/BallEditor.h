#pragma once
// Every property of the selected ball at t = 0: its id, position, velocity, spin, radius and mass.
// Each edit is one undo step on the document, checked by the one validator (core/setup); a refused
// value is put back and the reason shown under the fields, naming the ball by its id.

#include <QWidget>

#include <array>

class QDoubleSpinBox;
class QGroupBox;
class QLabel;
class QLineEdit;

namespace cuelab {

class Document;
enum class BallProperty;  // (int, as in Document.h; written without ": int" so that lupdate can read this file)

class BallEditor : public QWidget {
    Q_OBJECT
public:
    explicit BallEditor(Document* document, QWidget* parent = nullptr);

    int ball() const { return ball_; }
    QLineEdit* idEdit() const { return id_; }
    // The spin box of a numeric property (X, Y, Vx, Vy, Wx, Wy, Wz, Radius, Mass).
    QDoubleSpinBox* spinBox(BallProperty property) const;
    QLabel* problemLabel() const { return problem_; }

public slots:
    void setBall(int index);  // -1 = none: the fields are disabled

private:
    void refresh();
    void commit(BallProperty property);
    void showProblem(const QString& message);

    Document* document_;
    int ball_ = -1;
    QGroupBox* box_;
    QLineEdit* id_;
    std::array<QDoubleSpinBox*, 9> numbers_{};  // X .. Mass, in BallProperty order after Id
    QLabel* problem_;
    bool refreshing_ = false;
    bool committing_ = false;
};

}  // namespace cuelab
