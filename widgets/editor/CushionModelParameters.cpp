#include "CushionModelParameters.h"

#include "Document.h"
#include "Quantities.h"
#include "resolve/CushionModel.h"

#include <QDoubleSpinBox>
#include <QFormLayout>

#include <cmath>

namespace cuelab {

namespace {
// Merge keys of these edits, clear of PhysicsPanel's fields (a drag of one box is one undo step).
constexpr int kFirstField = 1000;
}  // namespace

CushionModelParameters::CushionModelParameters(Document* document, QWidget* parent)
    : QWidget(parent), document_(document), form_(new QFormLayout(this))
{
    form_->setContentsMargins(0, 0, 0, 0);
    form_->setRowWrapPolicy(QFormLayout::WrapLongRows);  // as PhysicsPanel's forms
    connect(document_, &Document::setupChanged, this, &CushionModelParameters::rebuild);
    rebuild();
}

void CushionModelParameters::rebuild()
{
    refreshing_ = true;
    const PhysicsParams& p = document_->setup().physics;
    const CushionModelEntry& model = cushionModel(p.ballCushionModel);
    if (shownModel_ != static_cast<int>(model.model)) {
        while (form_->rowCount() > 0) form_->removeRow(0);
        boxes_.clear();
        shownModel_ = static_cast<int>(model.model);
        for (const CushionModelParameter& q : model.parameters) {
            // Exclusive bounds: the box stops one displayed step inside them.
            const double inset = std::pow(10.0, -q.decimals);
            QDoubleSpinBox* box = makeSpinBox({q.min + (q.minExclusive ? inset : 0.0), q.max - (q.maxExclusive ? inset : 0.0),
                                               q.decimals, q.step, QString(), toQString(q.description)},
                                              this);
            box->setObjectName(QStringLiteral("cushionParameter_") + toQString(q.key));
            // A whole number of integration steps costs time in proportion (Mathavan 2010's `steps`;
            // measured with `cuelab-bench --cushions`, docs/cushion-models.md).
            if (q.integer)
                box->setToolTip(box->toolTip() + QLatin1Char('\n') +
                                tr("Cost grows in proportion: about 0.1 ms of computing per cushion hit at 1000 steps, "
                                   "about 0.1 s at 1000000, in every shot of a sweep or an Analysis map too."));
            form_->addRow(toQString(q.key).replace(QLatin1Char('_'), QLatin1Char(' ')), box);
            boxes_.push_back(box);
            connect(box, &QDoubleSpinBox::valueChanged, this, [this, &q](double value) { commit(q, value); });
            connect(box, &QDoubleSpinBox::editingFinished, document_, &Document::endMerge);
        }
    }
    for (std::size_t i = 0; i < boxes_.size(); ++i) boxes_[i]->setValue(p.*(model.parameters[i].field));
    setVisible(!boxes_.empty());
    refreshing_ = false;
}

void CushionModelParameters::commit(const CushionModelParameter& parameter, double value)
{
    if (refreshing_) return;
    PhysicsParams p = document_->setup().physics;
    p.*(parameter.field) = parameter.integer ? std::round(value) : value;
    const CushionModelEntry& model = cushionModel(p.ballCushionModel);
    const int index = static_cast<int>(&parameter - model.parameters.data());
    if (!document_->setPhysics(p, tr("Change %1").arg(toQString(parameter.key).replace(QLatin1Char('_'), QLatin1Char(' '))),
                               kFirstField + index))
        rebuild();
}

}  // namespace cuelab
