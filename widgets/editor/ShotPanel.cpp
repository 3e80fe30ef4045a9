#include "ShotPanel.h"

#include "AimControl.h"
#include "GameControl.h"
#include "LaunchReadout.h"
#include "SquirtControl.h"

#include "Document.h"
#include "Quantities.h"
#include "TipOffsetWidget.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QBoxLayout>
#include <QEvent>
#include <QHBoxLayout>
#include <QSignalBlocker>
#include <QSlider>

#include <cmath>

namespace cuelab {

namespace {
constexpr double kSliderSpeedStep = 0.01;  // m/s per slider step
constexpr double kMaxCueSpeed = 12.0;      // m/s, a hard break is about 11 m/s (Alciatore)
}  // namespace

ShotPanel::ShotPanel(Document* document, QWidget* parent) : QWidget(parent), document_(document)
{
    enabled_ = new QCheckBox(tr("Strike a ball at t = 0"), this);
    enabled_->setToolTip(tr("Without a strike the balls move only with the velocities and spins they are set up with."));
    ball_ = new QComboBox(this);
    ball_->setToolTip(tr("The ball the cue strikes"));

    speed_ = makeSpinBox({0.0, kMaxCueSpeed, 2, 0.1, tr("m/s"), tr("Cue speed V0 in m/s just before the tip meets the ball")}, this);
    speedSlider_ = new QSlider(Qt::Horizontal, this);
    speedSlider_->setRange(0, static_cast<int>(kMaxCueSpeed / kSliderSpeedStep));
    speedSlider_->setToolTip(speed_->toolTip());
    heading_ = makeSpinBox({-360.0, 360.0, 2, 1.0, QStringLiteral("°"), tr("Heading of the cue in degrees: 0 = along +x (towards the foot rail), counter-clockwise positive")}, this);
    heading_->setWrapping(true);
    headingSlider_ = new QSlider(Qt::Horizontal, this);
    headingSlider_->setRange(-1800, 1800);  // tenths of a degree
    headingSlider_->setToolTip(heading_->toolTip());
    elevation_ = makeSpinBox({0.0, 89.0, 1, 1.0, QStringLiteral("°"), tr("Elevation of the cue above the cloth in degrees (masse and jump shots)")}, this);
    side_ = makeSpinBox({-TipOffsetWidget::kMaxOffset, TipOffsetWidget::kMaxOffset, 2, 0.05, QStringLiteral("R"), tr("Side offset of the tip as a fraction of the ball radius R: + = right of centre (right english)")}, this);
    height_ = makeSpinBox({-TipOffsetWidget::kMaxOffset, TipOffsetWidget::kMaxOffset, 2, 0.05, QStringLiteral("R"), tr("Height offset of the tip as a fraction of the ball radius R: + = above centre (follow), 0.4 R = natural roll")}, this);
    tip_ = new TipOffsetWidget(this);
    cueMass_ = makeSpinBox({0.1, 2.0, 3, 0.01, tr("kg"), tr("Mass of the cue in kg (a typical cue: 0.567 kg, 20 oz)")}, this);

    auto* form = new QFormLayout(this);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    form->addRow(enabled_);
    form->addRow(tr("Ball"), ball_);
    auto* speedRow = new QHBoxLayout;
    speedRow->addWidget(speedSlider_, 1);
    speedRow->addWidget(speed_);
    form->addRow(tr("Speed"), speedRow);
    form->addRow(QString(), new LaunchReadout(document_, this));  // the ball's speed and spin after the strike
    auto* headingRow = new QHBoxLayout;
    headingRow->addWidget(headingSlider_, 1);
    headingRow->addWidget(heading_);
    form->addRow(tr("Heading"), headingRow);
    form->addRow(tr("Aim at"), new AimControl(document_, this));  // the heading as a cut of an object ball
    form->addRow(tr("Elevation"), elevation_);
    tipRow_ = new QBoxLayout(QBoxLayout::LeftToRight);
    auto* tipNumbers = new QFormLayout;
    tipNumbers->addRow(tr("Side"), side_);
    tipNumbers->addRow(tr("Height"), height_);
    tipRow_->addWidget(tip_, 1);
    tipRow_->addLayout(tipNumbers);
    form->addRow(tr("Tip"), tipRow_);
    form->addRow(tr("Cue mass"), cueMass_);
    form->addRow(tr("End mass"), new SquirtControl(document_, this));  // squirt (shot.end_mass)
    form->addRow(tr("Game"), new GameControl(document_, this));  // the rules that judge the shot (setup's game)

    connect(enabled_, &QCheckBox::toggled, this, [this] { commit(Enabled, enabled_->isChecked() ? tr("Add the cue strike") : tr("Remove the cue strike")); });
    connect(ball_, &QComboBox::activated, this, [this] { commit(BallField, tr("Strike ball %1").arg(ball_->currentText())); });
    connect(speed_, &QDoubleSpinBox::valueChanged, this, [this] { commit(Speed, tr("Change the cue speed")); });
    connect(speedSlider_, &QSlider::valueChanged, this, [this](int v) {
        speed_->setValue(v * kSliderSpeedStep);  // commits through the spin box
    });
    connect(heading_, &QDoubleSpinBox::valueChanged, this, [this] { commit(Heading, tr("Change the heading")); });
    connect(headingSlider_, &QSlider::valueChanged, this, [this](int v) { heading_->setValue(v / 10.0); });
    connect(elevation_, &QDoubleSpinBox::valueChanged, this, [this] { commit(Elevation, tr("Change the cue elevation")); });
    connect(side_, &QDoubleSpinBox::valueChanged, this, [this] { commit(Tip, tr("Move the cue tip")); });
    connect(height_, &QDoubleSpinBox::valueChanged, this, [this] { commit(Tip, tr("Move the cue tip")); });
    connect(tip_, &TipOffsetWidget::offsetEdited, this, [this](const QPointF& o) {
        const QSignalBlocker a(side_), b(height_);
        side_->setValue(o.x());
        height_->setValue(o.y());
        commit(Tip, tr("Move the cue tip"));
    });
    connect(cueMass_, &QDoubleSpinBox::valueChanged, this, [this] { commit(CueMass, tr("Change the cue mass")); });
    // A drag or a run of arrow clicks is one undo step; letting go ends it.
    for (QSlider* s : {speedSlider_, headingSlider_}) connect(s, &QSlider::sliderReleased, document_, &Document::endMerge);
    for (QDoubleSpinBox* s : {speed_, heading_, elevation_, side_, height_, cueMass_})
        connect(s, &QDoubleSpinBox::editingFinished, document_, &Document::endMerge);
    connect(tip_, &TipOffsetWidget::editingFinished, document_, &Document::endMerge);

    connect(document_, &Document::setupChanged, this, &ShotPanel::refresh);
    refresh();
    // The width with the picker beside its fields; the window's side column gets it when it has room
    // (app/window/DockLayout reads "preferredDockWidth").
    sideBySideWidth_ = minimumSizeHint().width();
    setProperty("preferredDockWidth", sideBySideWidth_);
}

void ShotPanel::refresh()
{
    refreshing_ = true;
    const Setup& setup = document_->setup();
    const CueStrike shot = setup.shot.value_or(CueStrike{});
    {
        const QSignalBlocker blockers[] = {QSignalBlocker(enabled_), QSignalBlocker(ball_), QSignalBlocker(speed_),
                                           QSignalBlocker(speedSlider_), QSignalBlocker(heading_),
                                           QSignalBlocker(headingSlider_), QSignalBlocker(elevation_),
                                           QSignalBlocker(side_), QSignalBlocker(height_), QSignalBlocker(cueMass_)};
        enabled_->setChecked(setup.shot.has_value());
        enabled_->setEnabled(!setup.balls.empty());
        ball_->clear();
        for (const Ball& b : setup.balls) ball_->addItem(QString::fromStdString(b.id));
        ball_->setCurrentText(QString::fromStdString(shot.ball));
        speed_->setValue(shot.speed);
        speedSlider_->setValue(static_cast<int>(std::lround(shot.speed / kSliderSpeedStep)));
        heading_->setValue(shot.headingDeg);
        headingSlider_->setValue(static_cast<int>(std::lround(std::remainder(shot.headingDeg, 360.0) * 10.0)));
        elevation_->setValue(shot.elevationDeg);
        side_->setValue(shot.side);
        height_->setValue(shot.height);
        cueMass_->setValue(shot.cueMass);
    }
    tip_->setOffset(QPointF(shot.side, shot.height));
    const bool on = setup.shot.has_value();
    for (QWidget* w : std::initializer_list<QWidget*>{ball_, speed_, speedSlider_, heading_, headingSlider_, elevation_, side_, height_, tip_, cueMass_})
        w->setEnabled(on);
    refreshing_ = false;
}

void ShotPanel::commit(Field field, const QString& text)
{
    if (refreshing_) return;
    const Setup& setup = document_->setup();
    std::optional<CueStrike> shot = setup.shot;
    if (field == Enabled) {
        shot.reset();
        if (enabled_->isChecked() && !setup.balls.empty()) {
            shot = CueStrike{};
            shot->ball = setup.balls.front().id;
        }
    } else if (shot) {
        // Only the edited field changes: the others keep their full precision.
        switch (field) {
        case BallField: shot->ball = ball_->currentText().toStdString(); break;
        case Speed: shot->speed = speed_->value(); break;
        case Heading: shot->headingDeg = heading_->value(); break;
        case Elevation: shot->elevationDeg = elevation_->value(); break;
        case Tip:
            shot->side = side_->value();
            shot->height = height_->value();
            break;
        case CueMass: shot->cueMass = cueMass_->value(); break;
        case Enabled: break;
        }
    }
    if (!document_->setShot(shot, text, field)) refresh();  // refused: show the setup as it is
}

bool ShotPanel::tipStacked() const { return tipRow_->direction() == QBoxLayout::TopToBottom; }

void ShotPanel::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    // In a dock the panel sits in a scroll area: its viewport's width is what the panel may take.
    if (QWidget* viewport = parentWidget()) {
        viewport->removeEventFilter(this);
        viewport->installEventFilter(this);
        fitTipRow(viewport->width());
    }
}

bool ShotPanel::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == parentWidget() && event->type() == QEvent::Resize) fitTipRow(parentWidget()->width());
    return QWidget::eventFilter(watched, event);
}

void ShotPanel::fitTipRow(int available)
{
    const QBoxLayout::Direction want = available < sideBySideWidth_ ? QBoxLayout::TopToBottom : QBoxLayout::LeftToRight;
    if (tipRow_->direction() != want) {
        tipRow_->setDirection(want);
        updateGeometry();
    }
}

}  // namespace cuelab
