#include "OutcomeLine.h"

#include "i18n/UiNumbers.h"

#include "i18n/DisplayNames.h"

#include <QCoreApplication>
#include <QStringList>

namespace cuelab {

namespace {

// The context lupdate gives tr() calls in functions of namespace cuelab (resources/translations).
QString tr(const char* text) { return QCoreApplication::translate("cuelab", text); }

QString seconds(double t) { return tr("%1 s").arg(uiNumber(t, 3)); }
QString cushions(int n) { return n == 1 ? tr("1 cushion") : tr("%1 cushions").arg(n); }

}  // namespace

QString outcomeLine(const SimulationResult& r, const ShotOutcome& o)
{
    const auto id = [&](int ball) { return QString::fromStdString(r.balls.at(static_cast<std::size_t>(ball)).id); };
    QString line;
    if (o.struckBall < 0) {
        line = tr("no shot");
    } else if (o.firstContact) {
        line = tr("%1 → %2 at %3, %4 before")
                   .arg(id(o.struckBall), id(o.firstContact->ball), seconds(o.firstContact->time), cushions(o.cushionsBeforeFirstContact));
    } else {
        line = tr("%1 touched no ball, %2").arg(id(o.struckBall), cushions(o.cushionsBeforeFirstContact));
    }
    if (!r.table.pockets.empty()) {  // a carom table has none to speak of
        QStringList pocketed;
        for (const PocketedBall& p : o.pocketed)
            pocketed << tr("%1 (%2, %3)").arg(id(p.ball), displayElementName(r.table.pockets.at(static_cast<std::size_t>(p.pocket)).id),
                                              seconds(p.time));
        line += tr("; pocketed: %1").arg(pocketed.isEmpty() ? tr("none") : pocketed.join(QStringLiteral(", ")));
        if (o.struckBall >= 0 && o.struckBallPocketed) line += tr("; %1 pocketed too").arg(id(o.struckBall));
    }
    QStringList off;
    for (const OffTableBall& b : o.offTable) off << tr("%1 (%2)").arg(id(b.ball), seconds(b.time));
    if (!off.isEmpty()) line += tr("; off the table: %1").arg(off.join(QStringLiteral(", ")));
    return line;
}

}  // namespace cuelab
