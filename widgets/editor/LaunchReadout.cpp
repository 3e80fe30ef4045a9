#include "LaunchReadout.h"

#include "Document.h"
#include "Quantities.h"

#include "Aim.h"

namespace cuelab {

LaunchReadout::LaunchReadout(Document* document, QWidget* parent) : QLabel(parent), document_(document)
{
    setObjectName(QStringLiteral("launchReadout"));
    setWordWrap(true);
    setToolTip(tr("The struck ball just after the cue strike: its speed (m/s), its topspin (+) or backspin (−) about "
                  "the axis across its path and its side spin (counter-clockwise + seen from above), in rad/s"));
    connect(document_, &Document::resultChanged, this, &LaunchReadout::refresh);
    refresh();
}

void LaunchReadout::refresh()
{
    const auto result = document_->result();
    const std::optional<aim::Launch> l = result ? aim::launchOf(*result) : std::nullopt;
    if (!l) return setText(QString());
    setText(tr("ball %1, topspin %2, side spin %3")
                .arg(formatQuantity(l->speed, tr("m/s"), 2), formatQuantity(l->topspin, tr("rad/s"), 1),
                     formatQuantity(l->sideSpin, tr("rad/s"), 1)));
}

}  // namespace cuelab
