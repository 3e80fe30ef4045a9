#include "SquirtControl.h"

#include "Document.h"
#include "Quantities.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>

namespace cuelab {

namespace {
constexpr double kGramsPerKg = 1000.0;
constexpr int kField = 1001;  // merge key of end-mass edits, clear of ShotPanel's fields
}  // namespace

SquirtControl::SquirtControl(Document* document, QWidget* parent) : QWidget(parent), document_(document)
{
    enabled_ = new QCheckBox(tr("Squirt"), this);
    enabled_->setObjectName(QStringLiteral("squirtEnabled"));
    enabled_->setToolTip(tr("Squirt: side english sends the cue ball off the cue line, away from the side of the english, "
                            "by an angle that grows as the tip's end mass grows (Alciatore TP A-31). Off: the ball leaves along the cue line."));
    endMass_ = makeSpinBox({0.5, 50.0, 1, 0.5, tr("g"),
                            tr("End mass of the cue tip in grams, the part of the shaft that moves with the tip during the hit "
                               "(about 5.7 g for a pool cue, a thirtieth of the ball; low-squirt shafts are lighter)")},
                           this);
    endMass_->setObjectName(QStringLiteral("squirtEndMass"));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(enabled_);
    layout->addWidget(endMass_, 1);
    connect(enabled_, &QCheckBox::toggled, this, [this] { commit(true); });
    connect(endMass_, &QDoubleSpinBox::valueChanged, this, [this] { commit(false); });
    connect(endMass_, &QDoubleSpinBox::editingFinished, document_, &Document::endMerge);
    connect(document_, &Document::setupChanged, this, &SquirtControl::refresh);
    refresh();
}

void SquirtControl::refresh()
{
    refreshing_ = true;
    const std::optional<CueStrike>& shot = document_->setup().shot;
    const bool on = shot && shot->endMass > 0.0;
    enabled_->setChecked(on);
    enabled_->setEnabled(shot.has_value());
    if (on) endMass_->setValue(shot->endMass * kGramsPerKg);
    else if (endMass_->value() == endMass_->minimum()) endMass_->setValue(5.7);  // m/30 for a pool ball
    endMass_->setEnabled(on);
    refreshing_ = false;
}

void SquirtControl::commit(bool fromSwitch)
{
    if (refreshing_) return;
    std::optional<CueStrike> shot = document_->setup().shot;
    if (!shot) return;
    shot->endMass = enabled_->isChecked() ? endMass_->value() / kGramsPerKg : 0.0;
    const QString text = fromSwitch ? (enabled_->isChecked() ? tr("Turn squirt on") : tr("Turn squirt off"))
                                    : tr("Change the end mass");
    if (!document_->setShot(shot, text, kField)) refresh();
}

}  // namespace cuelab
