#include "AimControl.h"

#include "i18n/UiNumbers.h"

#include "Document.h"
#include "Quantities.h"

#include "Aim.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QSignalBlocker>

#include <limits>

namespace cuelab {

namespace {
constexpr int kField = 3;           // merge key: a heading edit, like ShotPanel's Heading field
constexpr double kMaxCut = 89.9;    // degrees; 90° is a graze that no longer touches
enum Side { Left = 0, Right = 1 };

const Ball* findBall(const Setup& setup, const std::string& id)
{
    for (const Ball& b : setup.balls)
        if (b.id == id) return &b;
    return nullptr;
}
}  // namespace

AimControl::AimControl(Document* document, QWidget* parent) : QWidget(parent), document_(document)
{
    object_ = new QComboBox(this);
    object_->setObjectName(QStringLiteral("aimObjectBall"));
    object_->setToolTip(tr("The object ball to aim at: the cut angle then sets the heading"));
    cut_ = makeSpinBox({0.0, kMaxCut, 1, 1.0, QStringLiteral("°"),
                        tr("Cut angle in degrees between the cue line and the line of centres at contact: 0° a full "
                           "(straight) hit, 30° a half-ball hit; the straight cue line, before squirt and swerve")},
                       this);
    cut_->setObjectName(QStringLiteral("aimCutAngle"));
    side_ = new QComboBox(this);
    side_->setObjectName(QStringLiteral("aimCutSide"));
    side_->addItem(tr("left"));
    side_->addItem(tr("right"));
    side_->setToolTip(tr("Which way the object ball is cut, seen along the cue line"));
    contact_ = new QLabel(this);
    contact_->setObjectName(QStringLiteral("aimFirstContact"));
    contact_->setWordWrap(true);
    contact_->setToolTip(tr("The struck ball's first contact in the simulated shot: the cut angle (degrees) between "
                            "its path and the line of centres, and the ball fraction 1 − sin(cut), 1 full, 0.5 half ball"));

    // Narrow docks (an 800 × 600 window): the lists shrink to a few characters, never pushing the
    // Shot dock into sideways scrolling.
    for (QComboBox* box : {object_, side_}) {
        box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        box->setMinimumContentsLength(3);
    }
    auto* grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    // Two rows, so that the Shot dock stays narrow: the ball, then the cut angle and its side.
    grid->addWidget(object_, 0, 0, 1, 2);
    grid->addWidget(cut_, 1, 0);
    grid->addWidget(side_, 1, 1);
    grid->addWidget(contact_, 2, 0, 1, 2);
    grid->setColumnStretch(0, 1);

    connect(object_, &QComboBox::activated, this, [this] { refresh(); });
    connect(cut_, &QDoubleSpinBox::valueChanged, this, [this] { commit(); });
    connect(side_, &QComboBox::activated, this, [this] {
        commit();
        document_->endMerge();
    });
    connect(cut_, &QDoubleSpinBox::editingFinished, document_, &Document::endMerge);
    connect(document_, &Document::setupChanged, this, &AimControl::refresh);
    connect(document_, &Document::resultChanged, this, &AimControl::refreshContact);
    refresh();
    refreshContact();
}

void AimControl::refresh()
{
    refreshing_ = true;
    const Setup& setup = document_->setup();
    const QSignalBlocker a(object_), b(cut_), c(side_);
    const QString chosen = object_->currentText();
    object_->clear();
    const std::string struck = setup.shot ? setup.shot->ball : std::string();
    for (const Ball& ball : setup.balls)
        if (ball.id != struck) object_->addItem(QString::fromStdString(ball.id));
    // Keep the chosen ball; else the first contact's; else the first in the list.
    int keep = object_->findText(chosen);
    if (keep < 0 && document_->result()) {
        int other = -1;
        if (aim::firstContact(*document_->result(), nullptr, &other) && other >= 0 &&
            other < static_cast<int>(document_->result()->balls.size()))
            keep = object_->findText(QString::fromStdString(document_->result()->balls[static_cast<std::size_t>(other)].id));
    }
    object_->setCurrentIndex(keep >= 0 ? keep : 0);
    const Ball* s = findBall(setup, struck);
    const Ball* o = findBall(setup, object_->currentText().toStdString());
    const bool on = setup.shot && s && o;
    for (QWidget* w : std::initializer_list<QWidget*>{object_, cut_, side_}) w->setEnabled(setup.shot.has_value() && object_->count() > 0);
    if (on) {
        const std::optional<aim::AimGeometry> g =
            aim::plannedContact(s->state.position, setup.shot->headingDeg, o->state.position, s->radius, o->radius);
        cut_->setSpecialValueText(QString());
        if (g) {
            cut_->setValue(g->cutAngleDeg);
            if (g->side != aim::CutSide::Straight) side_->setCurrentIndex(g->side == aim::CutSide::Left ? Left : Right);
        } else {
            // The cue line misses this ball: the field reads so until a cut is chosen.
            cut_->setSpecialValueText(tr("misses"));
            cut_->setValue(cut_->minimum());
        }
    }
    refreshing_ = false;
}

void AimControl::refreshContact()
{
    const auto result = document_->result();
    int other = -1;
    const std::optional<aim::AimGeometry> g = result ? aim::firstContact(*result, nullptr, &other) : std::nullopt;
    if (!g || other < 0) {
        contact_->setText(result && !result->events.empty() ? tr("First contact: none") : QString());
        return;
    }
    const QString side = g->side == aim::CutSide::Left ? tr("left") : g->side == aim::CutSide::Right ? tr("right") : tr("straight");
    contact_->setText(tr("First contact: %1, cut %2 %3, ball fraction %4")
                          .arg(QString::fromStdString(result->balls[static_cast<std::size_t>(other)].id),
                               uiNumber(g->cutAngleDeg, 1) + QStringLiteral("°"), side,
                               uiNumber(g->ballFraction, 2)));
}

void AimControl::commit()
{
    if (refreshing_) return;
    const Setup& setup = document_->setup();
    std::optional<CueStrike> shot = setup.shot;
    if (!shot) return;
    const Ball* s = findBall(setup, shot->ball);
    const Ball* o = findBall(setup, object_->currentText().toStdString());
    if (!s || !o) return;
    const double cut = cut_->value();
    const aim::CutSide side = cut == 0.0 ? aim::CutSide::Straight : side_->currentIndex() == Left ? aim::CutSide::Left : aim::CutSide::Right;
    const std::optional<double> heading = aim::headingForCut(s->state.position, o->state.position, s->radius, o->radius, cut, side);
    if (!heading) return refresh();
    shot->headingDeg = *heading;
    const QString text = tr("Aim at %1, cut %2 %3")
                             .arg(object_->currentText(), uiNumber(cut, 1) + QStringLiteral("°"),
                                  side == aim::CutSide::Straight ? tr("straight") : side_->currentText());
    if (!document_->setShot(shot, text, kField)) refresh();
}

}  // namespace cuelab
