#include "PhysicsPanel.h"

#include "CushionModelParameters.h"
#include "resolve/CushionModel.h"

#include "Document.h"
#include "Quantities.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace cuelab {

namespace {
constexpr double kMsPerS = 1000.0;
}  // namespace

PhysicsPanel::PhysicsPanel(Document* document, QWidget* parent) : QWidget(parent), document_(document)
{
    tableKind_ = new QComboBox(this);
    tableKind_->setObjectName(QStringLiteral("tableKind"));
    for (TableKind kind : {TableKind::Pool9ft, TableKind::Pool8ft, TableKind::Pool7ft, TableKind::Snooker, TableKind::Carom}) {
        const Table t = makeTable(kind);
        tableKind_->addItem(QStringLiteral("%1 (%2 × %3 m)").arg(toQString(toString(kind)), formatNumber(t.length, 3), formatNumber(t.width, 3)),
                            static_cast<int>(kind));
    }
    tableKind_->setToolTip(tr("The table: playing surface between the cushion noses in metres, pockets and cushions of the preset. The balls keep their size and place; balls that would lie off the new cloth can be moved to the nearest free spots."));
    pockets_ = new QCheckBox(tr("Pockets"), this);
    pockets_->setToolTip(tr("Without pockets the rails are closed all round (a carom table never has pockets)"));
    gravity_ = makeSpinBox({0.1, 30.0, 3, 0.01, tr("m/s²"), tr("Gravitational acceleration g in m/s² (9.81 on Earth)")}, this);
    muSlide_ = makeSpinBox({0.0, 1.0, 3, 0.01, QString(), tr("Sliding friction between ball and cloth (dimensionless; 0.2, range 0.15-0.4, Alciatore)")}, this);
    muRoll_ = makeSpinBox({0.0, 0.1, 4, 0.001, QString(), tr("Rolling resistance of the cloth (dimensionless; 0.01, range 0.005-0.015)")}, this);
    muSpin_ = makeSpinBox({0.0, 0.1, 4, 0.001, QString(), tr("Spin friction about the vertical axis (dimensionless; 0.0127 slows side spin by about 10.9 rad/s²)")}, this);
    ballBallModel_ = new QComboBox(this);
    ballBallModel_->addItem(tr("Frictionless"), static_cast<int>(BallBallModel::Frictionless));
    ballBallModel_->addItem(tr("Frictional (throw)"), static_cast<int>(BallBallModel::Frictional));
    ballBallModel_->setToolTip(tr("Ball-ball collision model: frictionless (spins unchanged) or with a Coulomb-limited tangential impulse that throws the object ball"));
    ballBallRestitution_ = makeSpinBox({0.0, 1.0, 3, 0.01, QString(), tr("Ball-ball coefficient of restitution (dimensionless; 0.95, range 0.92-0.98)")}, this);
    ballBallFrictionKind_ = new QComboBox(this);
    ballBallFrictionKind_->addItem(tr("Fixed"), static_cast<int>(BallBallFriction::Fixed));
    ballBallFrictionKind_->addItem(tr("Speed-dependent (Alciatore)"), static_cast<int>(BallBallFriction::Alciatore));
    ballBallFrictionKind_->setToolTip(tr("Ball-ball friction: a fixed coefficient, or Alciatore's fit 0.00995 + 0.108 exp(-1.088 v) of the relative speed v in m/s"));
    ballBallFriction_ = makeSpinBox({0.0, 1.0, 3, 0.01, QString(), tr("Fixed ball-ball friction coefficient (dimensionless; 0.05)")}, this);
    cushionModel_ = new QComboBox(this);
    // The cushion models come from their registry (core/physics/resolve/CushionModel.h).
    for (const CushionModelEntry& m : cushionModels()) {
        cushionModel_->addItem(toQString(m.title), static_cast<int>(m.model));
        cushionModel_->setItemData(cushionModel_->count() - 1, toQString(m.summary), Qt::ToolTipRole);
    }
    cushionModel_->setToolTip(tr("Ball-cushion model: mirror, Han 2005, Mathavan 2010 or Stronge's compliant impact (docs/cushion-models.md)"));
    cushionRestitution_ = makeSpinBox({0.0, 1.0, 3, 0.01, QString(), tr("Ball-cushion coefficient of restitution (dimensionless; 0.85, range 0.6-0.9)")}, this);
    cushionFriction_ = makeSpinBox({0.0, 1.0, 3, 0.01, QString(), tr("Ball-cushion friction coefficient (dimensionless; 0.2)")}, this);
    frameDt_ = makeSpinBox({0.1, 1000.0, 3, 1.0, tr("ms"), tr("Frame timestep in milliseconds: one step of frame-by-frame playback (16.667 ms = 60 frames per second)")}, this);
    maxTime_ = makeSpinBox({0.1, 3600.0, 1, 10.0, tr("s"), tr("The simulation stops at this time in seconds at the latest")}, this);
    reset_ = new QPushButton(tr("Reset to Defaults"), this);
    reset_->setToolTip(tr("Set friction, restitution, models and gravity back to the defaults of the physics reference"));

    auto* table = new QGroupBox(tr("Table"), this);
    auto* tableForm = new QFormLayout(table);
    tableForm->addRow(tr("Kind"), tableKind_);
    tableForm->addRow(QString(), pockets_);
    auto* cloth = new QGroupBox(tr("Cloth"), this);
    auto* clothForm = new QFormLayout(cloth);
    clothForm->addRow(tr("μ slide"), muSlide_);
    clothForm->addRow(tr("μ roll"), muRoll_);
    clothForm->addRow(tr("μ spin"), muSpin_);
    clothForm->addRow(tr("Gravity"), gravity_);
    auto* balls = new QGroupBox(tr("Ball-ball"), this);
    auto* ballsForm = new QFormLayout(balls);
    ballsForm->addRow(tr("Model"), ballBallModel_);
    ballsForm->addRow(tr("Restitution"), ballBallRestitution_);
    ballsForm->addRow(tr("Friction"), ballBallFrictionKind_);
    ballsForm->addRow(tr("μ ball"), ballBallFriction_);
    auto* cushion = new QGroupBox(tr("Ball-cushion"), this);
    auto* cushionForm = new QFormLayout(cushion);
    cushionForm->addRow(tr("Model"), cushionModel_);
    cushionForm->addRow(tr("Restitution"), cushionRestitution_);
    cushionForm->addRow(tr("μ cushion"), cushionFriction_);
    cushionForm->addRow(new CushionModelParameters(document_, cushion));  // the chosen model's own parameters
    auto* time = new QGroupBox(tr("Time"), this);
    auto* timeForm = new QFormLayout(time);
    timeForm->addRow(tr("Frame step"), frameDt_);
    timeForm->addRow(tr("Stop at"), maxTime_);

    // In a narrow column (Edit at 800x600) a field goes under its label rather than past the dock's
    // edge, and a list box shows the start of its choice rather than widening the panel.
    for (QFormLayout* form : {tableForm, clothForm, ballsForm, cushionForm, timeForm}) form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    for (QComboBox* box : {tableKind_, ballBallModel_, ballBallFrictionKind_, cushionModel_}) {
        box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        box->setMinimumContentsLength(14);
    }

    auto* layout = new QVBoxLayout(this);
    for (QWidget* w : std::initializer_list<QWidget*>{table, cloth, balls, cushion, time}) layout->addWidget(w);
    layout->addWidget(reset_, 0, Qt::AlignRight);
    layout->addStretch(1);

    const auto physicsBox = [this](QDoubleSpinBox* box, Field field, const QString& text) {
        connect(box, &QDoubleSpinBox::valueChanged, this, [this, field, text] { commitPhysics(field, text); });
        connect(box, &QDoubleSpinBox::editingFinished, document_, &Document::endMerge);
    };
    physicsBox(gravity_, Gravity, tr("Change gravity"));
    physicsBox(muSlide_, MuSlide, tr("Change μ slide"));
    physicsBox(muRoll_, MuRoll, tr("Change μ roll"));
    physicsBox(muSpin_, MuSpin, tr("Change μ spin"));
    physicsBox(ballBallRestitution_, BallBallRestitution, tr("Change ball-ball restitution"));
    physicsBox(ballBallFriction_, BallBallFrictionValue, tr("Change ball-ball friction"));
    physicsBox(cushionRestitution_, CushionRestitution, tr("Change cushion restitution"));
    physicsBox(cushionFriction_, CushionFriction, tr("Change cushion friction"));
    connect(ballBallModel_, &QComboBox::activated, this, [this] { commitPhysics(BallBallModelField, tr("Change the ball-ball model")); });
    connect(ballBallFrictionKind_, &QComboBox::activated, this, [this] { commitPhysics(BallBallFrictionKind, tr("Change the ball-ball friction law")); });
    connect(cushionModel_, &QComboBox::activated, this, [this] { commitPhysics(CushionModel, tr("Change the cushion model")); });
    connect(frameDt_, &QDoubleSpinBox::valueChanged, this, [this] { commitSimulation(FrameDt, tr("Change the frame step")); });
    connect(maxTime_, &QDoubleSpinBox::valueChanged, this, [this] { commitSimulation(MaxTime, tr("Change the time limit")); });
    for (QDoubleSpinBox* box : {frameDt_, maxTime_}) connect(box, &QDoubleSpinBox::editingFinished, document_, &Document::endMerge);
    connect(tableKind_, &QComboBox::activated, this, [this] { commitTable(tr("Change the table")); });
    connect(pockets_, &QCheckBox::toggled, this, [this](bool on) { commitTable(on ? tr("Open the pockets") : tr("Close the pockets")); });
    connect(reset_, &QPushButton::clicked, document_, &Document::resetPhysics);

    connect(document_, &Document::setupChanged, this, &PhysicsPanel::refresh);
    refresh();
}

void PhysicsPanel::refresh()
{
    refreshing_ = true;
    const Setup& s = document_->setup();
    const PhysicsParams& p = s.physics;
    tableKind_->setCurrentIndex(tableKind_->findData(static_cast<int>(s.table.kind)));
    pockets_->setChecked(s.table.pockets && s.table.kind != TableKind::Carom);
    pockets_->setEnabled(s.table.kind != TableKind::Carom);
    gravity_->setValue(p.gravity);
    muSlide_->setValue(p.muSlide);
    muRoll_->setValue(p.muRoll);
    muSpin_->setValue(p.muSpin);
    ballBallModel_->setCurrentIndex(ballBallModel_->findData(static_cast<int>(p.ballBallModel)));
    ballBallRestitution_->setValue(p.ballBallRestitution);
    ballBallFrictionKind_->setCurrentIndex(ballBallFrictionKind_->findData(static_cast<int>(p.ballBallFrictionKind)));
    ballBallFriction_->setValue(p.ballBallFriction);
    cushionModel_->setCurrentIndex(cushionModel_->findData(static_cast<int>(p.ballCushionModel)));
    cushionRestitution_->setValue(p.cushionRestitution);
    cushionFriction_->setValue(p.cushionFriction);
    frameDt_->setValue(s.simulation.frameDt * kMsPerS);
    maxTime_->setValue(s.simulation.maxTime);
    // Friction settings only matter where the model uses them.
    const bool frictional = p.ballBallModel == BallBallModel::Frictional;
    ballBallFrictionKind_->setEnabled(frictional);
    ballBallFriction_->setEnabled(frictional && p.ballBallFrictionKind == BallBallFriction::Fixed);
    cushionFriction_->setEnabled(cushionModel(p.ballCushionModel).usesFriction);
    refreshing_ = false;
}

void PhysicsPanel::commitPhysics(Field field, const QString& text)
{
    if (refreshing_) return;
    // Only the edited field changes: the others keep their full precision, not the spin boxes' digits.
    PhysicsParams p = document_->setup().physics;
    switch (field) {
    case Gravity: p.gravity = gravity_->value(); break;
    case MuSlide: p.muSlide = muSlide_->value(); break;
    case MuRoll: p.muRoll = muRoll_->value(); break;
    case MuSpin: p.muSpin = muSpin_->value(); break;
    case BallBallModelField: p.ballBallModel = static_cast<BallBallModel>(ballBallModel_->currentData().toInt()); break;
    case BallBallRestitution: p.ballBallRestitution = ballBallRestitution_->value(); break;
    case BallBallFrictionKind:
        p.ballBallFrictionKind = static_cast<BallBallFriction>(ballBallFrictionKind_->currentData().toInt());
        break;
    case BallBallFrictionValue: p.ballBallFriction = ballBallFriction_->value(); break;
    case CushionModel: p.ballCushionModel = static_cast<BallCushionModel>(cushionModel_->currentData().toInt()); break;
    case CushionRestitution: p.cushionRestitution = cushionRestitution_->value(); break;
    case CushionFriction: p.cushionFriction = cushionFriction_->value(); break;
    case FrameDt:
    case MaxTime: return;
    }
    if (!document_->setPhysics(p, text, field)) refresh();
}

void PhysicsPanel::commitTable(const QString& text)
{
    if (refreshing_) return;
    TableSpec table = document_->setup().table;
    const auto kind = static_cast<TableKind>(tableKind_->currentData().toInt());
    if (kind != table.kind) {
        // Another table: its own size and cushions, not the overrides of the old one.
        table = TableSpec{};
        table.kind = kind;
    }
    table.pockets = pockets_->isChecked() || kind == TableKind::Carom;
    // Balls that would stand off the new table (a smaller table, pockets opened under them): offer to
    // move them to the nearest legal spots rather than only refusing.
    const QStringList off = document_->ballsOffTable(table);
    if (!off.isEmpty()) {
        refresh();  // the panel shows the current table until the user decides
        if (askToMoveBalls(table, off) && document_->setTableMovingBalls(table, text)) return;
        refresh();
        return;
    }
    if (!document_->setTable(table, text)) refresh();
}

bool PhysicsPanel::askToMoveBalls(const TableSpec& table, const QStringList& ids)
{
    const Table t = makeTable(table);
    QStringList quoted;
    for (const QString& id : ids) quoted << QStringLiteral("\u201c%1\u201d").arg(id);
    QMessageBox box(QMessageBox::Question, tr("Balls Off the New Table"),
                    tr("On the %1 table (%2 × %3 m), %n ball(s) would lie off the cloth, in a pocket or on "
                       "another ball: %4.", nullptr, static_cast<int>(ids.size()))
                        .arg(toQString(toString(table.kind)), formatNumber(t.length, 3), formatNumber(t.width, 3),
                             quoted.join(QStringLiteral(", "))),
                    QMessageBox::Cancel, this);
    box.setObjectName(QStringLiteral("moveBallsQuestion"));
    box.setInformativeText(tr("Move them to the nearest free spots? The table change and the moves are one undo step."));
    QPushButton* move = box.addButton(tr("&Move Balls"), QMessageBox::AcceptRole);
    box.setDefaultButton(move);
    box.exec();
    return box.clickedButton() == move;
}

void PhysicsPanel::commitSimulation(Field field, const QString& text)
{
    if (refreshing_) return;
    SimulationSettings s = document_->setup().simulation;
    if (field == FrameDt) s.frameDt = frameDt_->value() / kMsPerS;
    if (field == MaxTime) s.maxTime = maxTime_->value();
    if (!document_->setSimulationSettings(s, text, field)) refresh();
}

}  // namespace cuelab
