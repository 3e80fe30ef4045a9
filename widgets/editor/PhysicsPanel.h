#pragma once
// The Physics dock: cloth friction, the collision models and their coefficients, gravity and the
// frame timestep, with a reset to the defaults of PHYSICS.md.

#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QPushButton;

namespace cuelab {

struct TableSpec;

class Document;

class PhysicsPanel : public QWidget {
    Q_OBJECT
public:
    explicit PhysicsPanel(Document* document, QWidget* parent = nullptr);

private:
    enum Field {
        Gravity, MuSlide, MuRoll, MuSpin, BallBallModelField, BallBallRestitution, BallBallFrictionKind,
        BallBallFrictionValue, CushionModel, CushionRestitution, CushionFriction, FrameDt, MaxTime
    };
    void refresh();
    void commitPhysics(Field field, const QString& text);
    void commitSimulation(Field field, const QString& text);
    void commitTable(const QString& text);
    bool askToMoveBalls(const TableSpec& table, const QStringList& ids);  // true: move them

    Document* document_;
    QComboBox* tableKind_;
    QCheckBox* pockets_;
    QDoubleSpinBox* gravity_;
    QDoubleSpinBox* muSlide_;
    QDoubleSpinBox* muRoll_;
    QDoubleSpinBox* muSpin_;
    QComboBox* ballBallModel_;
    QDoubleSpinBox* ballBallRestitution_;
    QComboBox* ballBallFrictionKind_;
    QDoubleSpinBox* ballBallFriction_;
    QComboBox* cushionModel_;
    QDoubleSpinBox* cushionRestitution_;
    QDoubleSpinBox* cushionFriction_;
    QDoubleSpinBox* frameDt_;
    QDoubleSpinBox* maxTime_;
    QPushButton* reset_;
    bool refreshing_ = false;
};

}  // namespace cuelab
