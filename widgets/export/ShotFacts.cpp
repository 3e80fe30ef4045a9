#include "ShotFacts.h"

#include "i18n/DisplayNames.h"

#include "Table.h"
#include "resolve/CushionModel.h"

#include <QCoreApplication>

#include <cmath>

namespace cuelab {

namespace {

// The context lupdate gives tr() calls in functions of namespace cuelab (resources/translations).
QString tr(const char* text) { return QCoreApplication::translate("cuelab", text); }
QString text(std::string_view s) { return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size())); }

// Six significant digits, as a person reads a parameter (0.4, 16, 0.0127, 1000): short, and a change
// a person would make always shows.
QString number(double value) { return QString::number(value, 'g', 6); }
QString withUnit(double value, const QString& unit) { return number(value) + QLatin1Char(' ') + unit; }

}  // namespace

ShotFacts shotFacts(const Setup& setup)
{
    ShotFacts f;
    if (const std::optional<CueStrike>& s = setup.shot) {
        f.shot = {
            {tr("Struck ball"), QString::fromStdString(s->ball)},
            {tr("Cue speed"), withUnit(s->speed, tr("m/s"))},
            {tr("Heading"), number(s->headingDeg) + QStringLiteral("°")},
            {tr("Tip offset, side"), withUnit(s->side, tr("R (+ right)"))},
            {tr("Tip offset, height"), withUnit(s->height, tr("R (+ above centre)"))},
            {tr("Cue elevation"), number(s->elevationDeg) + QStringLiteral("°")},
            {tr("Cue mass"), withUnit(s->cueMass, tr("kg"))},
            {tr("Squirt (cue end mass)"), s->endMass > 0.0 ? withUnit(s->endMass * 1000.0, tr("g")) : tr("none")},
        };
    }
    const PhysicsParams& p = setup.physics;
    const Table table = makeTable(setup.table);
    f.physics = {
        {tr("Table"), tr("%1, %2 × %3 m").arg(text(toString(table.kind)), number(table.length), number(table.width))},
        {tr("Pockets"), table.hasPockets() ? tr("open") : tr("closed")},
        {tr("Sliding friction μs"), number(p.muSlide)},
        {tr("Rolling resistance μr"), number(p.muRoll)},
        {tr("Spin friction μsp"), number(p.muSpin)},
        {tr("Gravity"), withUnit(p.gravity, tr("m/s²"))},
    };
    QString ballBall = displayCoreName(toString(p.ballBallModel));  // "frictionless", in the window's language
    if (p.ballBallModel == BallBallModel::Frictional)
        ballBall += p.ballBallFrictionKind == BallBallFriction::Alciatore ? tr(", μb from Alciatore's fit")
                                                                          : tr(", μb = %1").arg(number(p.ballBallFriction));
    f.physics << Fact{tr("Ball-ball model"), ballBall} << Fact{tr("Ball-ball restitution e"), number(p.ballBallRestitution)};
    const CushionModelEntry& cushion = cushionModel(p.ballCushionModel);
    f.physics << Fact{tr("Ball-cushion model"), text(cushion.title)}
              << Fact{tr("Cushion restitution e"), number(p.cushionRestitution)};
    if (cushion.usesFriction) f.physics << Fact{tr("Cushion friction μ"), number(p.cushionFriction)};
    for (const CushionModelParameter& q : cushion.parameters)
        f.physics << Fact{text(cushion.title) + QLatin1Char(' ') + text(q.key).replace(QLatin1Char('_'), QLatin1Char(' ')),
                          number(p.*(q.field))};
    return f;
}

QStringList factChanges(const Setup& written, const Setup& now)
{
    QStringList changes;
    const ShotFacts before = shotFacts(written);
    const ShotFacts after = shotFacts(now);
    if (before.shot.isEmpty() != after.shot.isEmpty())
        changes << (after.shot.isEmpty() ? tr("the cue strike was removed") : tr("a cue strike was added"));
    for (const auto& [was, is] : {std::pair{&before.shot, &after.shot}, std::pair{&before.physics, &after.physics}}) {
        for (const Fact& b : *was)
            for (const Fact& a : *is)
                if (a.name == b.name && a.value != b.value) changes << QStringLiteral("%1: %2 → %3").arg(a.name, b.value, a.value);
    }
    bool moved = written.balls.size() != now.balls.size();
    for (std::size_t i = 0; !moved && i < now.balls.size(); ++i) {
        const Ball& a = written.balls[i];
        const Ball& b = now.balls[i];
        moved = a.id != b.id || a.state.position != b.state.position || a.state.velocity != b.state.velocity ||
                a.state.spin != b.state.spin || a.radius != b.radius || a.mass != b.mass;
    }
    if (moved) changes << tr("the balls (positions, motion or sizes)");
    return changes;
}

}  // namespace cuelab
