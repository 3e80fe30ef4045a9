#include "InspectorPanel.h"

#include "i18n/UiNumbers.h"

#include "i18n/DisplayNames.h"
#include "EventTableModel.h"
#include "Quantities.h"

#include "Aim.h"
#include "Frames.h"
#include "Motion.h"

#include <QHeaderView>
#include <QScrollBar>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace cuelab {

namespace {
// Linear momentum, kg m/s; a pocketed ball has left the table and carries none.
Vec2 momentum(const BallState& state, double mass)
{
    if (state.motion == MotionState::Pocketed) return Vec2::Zero();
    return mass * state.velocity;
}
}  // namespace

InspectorPanel::InspectorPanel(QWidget* parent) : QWidget(parent), tree_(new QTreeWidget(this))
{
    tree_->setColumnCount(2);
    tree_->setHeaderLabels({tr("Quantity"), tr("Value")});
    tree_->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    tree_->setRootIsDecorated(true);
    tree_->setAlternatingRowColors(true);
    tree_->setSelectionMode(QAbstractItemView::NoSelection);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(tree_);
    showNothing();
}

QTreeWidgetItem* InspectorPanel::add(QTreeWidgetItem* parent, const QString& quantity, const QString& value,
                                     const QString& toolTip)
{
    auto* item = parent ? new QTreeWidgetItem(parent) : new QTreeWidgetItem(tree_);
    item->setText(0, quantity);
    item->setText(1, value);
    if (!toolTip.isEmpty()) item->setToolTip(0, toolTip);
    return item;
}

QString InspectorPanel::value(const QString& quantity) const
{
    const QList<QTreeWidgetItem*> found = tree_->findItems(quantity, Qt::MatchExactly | Qt::MatchRecursive, 0);
    return found.isEmpty() ? QString() : found.front()->text(1);
}

void InspectorPanel::showNothing()
{
    tree_->clear();
    auto* hint = add(nullptr, tr("Select a ball or an event"), QString());
    hint->setDisabled(true);
}

void InspectorPanel::addState(QTreeWidgetItem* parent, const BallState& s, double radius)
{
    add(parent, tr("State"), displayName(s.motion));
    if (isOutOfPlay(s.motion)) return;
    add(parent, tr("Position"), formatVector(s.position, QStringLiteral("m"), 4));
    add(parent, tr("Velocity"), formatVector(s.velocity, QStringLiteral("m/s"), 4));
    add(parent, tr("Speed"), formatQuantity(s.velocity.norm(), QStringLiteral("m/s"), 4));
    // A ball off the cloth (or leaving it): its height and vertical speed. A ball that never flies
    // shows neither, as before balls could fly.
    if (s.motion == MotionState::Airborne || s.z != 0.0 || s.vz != 0.0) {
        add(parent, tr("Height"), formatQuantity(s.z * 1000.0, QStringLiteral("mm"), 4),
            tr("Height of the centre above its resting height (mm); 0 on the cloth"));
        add(parent, tr("Vertical speed"), formatQuantity(s.vz, QStringLiteral("m/s"), 4),
            tr("Vertical velocity vz (m/s), positive upwards; in flight it falls by g t"));
    }
    add(parent, tr("Spin"), formatVector(s.spin, QStringLiteral("rad/s"), 3), tr("Angular velocity (ωx, ωy, ωz); ωz > 0 is counter-clockwise seen from above"));
    add(parent, tr("Slip"), formatVector(slipVelocity(s, radius), QStringLiteral("m/s"), 4),
        tr("Velocity of the contact point with the cloth, v + R (z × ω); zero when rolling"));
}

static QString cutSideText(aim::CutSide side)
{
    switch (side) {
    case aim::CutSide::Left: return InspectorPanel::tr("left");
    case aim::CutSide::Right: return InspectorPanel::tr("right");
    case aim::CutSide::Straight: break;
    }
    return InspectorPanel::tr("straight");
}

void InspectorPanel::addAim(QTreeWidgetItem* parent, const aim::AimGeometry& g)
{
    auto* node = add(parent, tr("Aim"), QString());
    add(node, tr("Cut angle"), tr("%1 %2").arg(formatQuantity(g.cutAngleDeg, QStringLiteral("°"), 4), cutSideText(g.side)),
        tr("Angle in degrees between the first ball's path and the line of centres at contact: 0° full hit, "
           "30° half ball; left or right: where the other ball goes, seen along the path"));
    add(node, tr("Ball fraction"), uiNumber(g.ballFraction, 3),
        tr("1 − sin(cut angle): the share of the other ball the first covers along its path (1 full, 0.5 half ball, 0 a graze)"));
    add(node, tr("Ghost ball"), formatVector(g.ghostBall, QStringLiteral("m"), 4),
        tr("Where the first ball's centre is at contact (m): aim at it"));
    add(node, tr("Contact on first ball"), formatQuantity(g.contactOnStruckDeg, QStringLiteral("°"), 4),
        tr("Where on the first ball the contact lies: degrees from its path, counter-clockwise positive"));
    add(node, tr("Contact on second ball"), formatQuantity(g.contactOnObjectDeg, QStringLiteral("°"), 4),
        tr("Where on the second ball the contact lies: degrees from the first ball's path, counter-clockwise positive"));
}

namespace {
// Rebuilding the tree on every frame of playback must neither flicker nor jump back to the top.
class KeepScrollPosition {
public:
    explicit KeepScrollPosition(QTreeWidget* tree) : tree_(tree), value_(tree->verticalScrollBar()->value())
    {
        tree_->setUpdatesEnabled(false);
    }
    ~KeepScrollPosition()
    {
        tree_->verticalScrollBar()->setValue(value_);
        tree_->setUpdatesEnabled(true);
    }
    KeepScrollPosition(const KeepScrollPosition&) = delete;
    KeepScrollPosition& operator=(const KeepScrollPosition&) = delete;

private:
    QTreeWidget* tree_;
    int value_;
};
}  // namespace

void InspectorPanel::showBall(const SimulationResult& result, int index, double time)
{
    const KeepScrollPosition keep(tree_);
    tree_->clear();
    if (index < 0 || index >= static_cast<int>(result.balls.size())) return showNothing();
    const Ball& ball = result.balls[static_cast<std::size_t>(index)];
    const BallState s = result.stateAt(index, time);
    auto* top = add(nullptr, tr("Ball %1").arg(QString::fromStdString(ball.id)), tr("at t = %1").arg(formatQuantity(time, QStringLiteral("s"), 4)));
    addState(top, s, ball.radius);
    if (s.motion == MotionState::Pocketed && s.pocket >= 0 && s.pocket < static_cast<int>(result.table.pockets.size()))
        add(top, tr("Pocket"), displayElementName(result.table.pockets[static_cast<std::size_t>(s.pocket)].id));
    add(top, tr("Momentum"), formatVector(momentum(s, ball.mass), QStringLiteral("kg·m/s"), 4));
    add(top, tr("Kinetic energy"), formatQuantity(kineticEnergy(s, ball.radius, ball.mass), QStringLiteral("J"), 5),
        tr("Translation plus rotation, I = 2/5 m R²"));
    add(top, tr("Radius"), formatQuantity(ball.radius * 1000.0, QStringLiteral("mm"), 3));
    add(top, tr("Mass"), formatQuantity(ball.mass, QStringLiteral("kg"), 4));
    tree_->expandAll();
}

void InspectorPanel::showEventDetails(const SimulationResult& result, int index)
{
    const KeepScrollPosition keep(tree_);
    tree_->clear();
    if (index < 0 || index >= static_cast<int>(result.events.size())) return showNothing();
    const std::size_t i = static_cast<std::size_t>(index);
    const Event& e = result.events[i];
    auto* top = add(nullptr, tr("Event %1").arg(eventNumber(index)), displayName(e.kind));
    add(top, tr("Agents"), EventTableModel::agents(result, e));
    add(top, tr("Time of impact"), formatQuantity(e.time, QStringLiteral("s"), 9),
        tr("Exact time of the event: a root of the polynomial that describes the contact"));
    if (i > 0) add(top, tr("Since previous"), formatQuantity(e.time - result.events[i - 1].time, QStringLiteral("s"), 9));
    if (isCollision(e.kind)) {
        add(top, tr("Contact point"), formatVector(e.contactPoint, QStringLiteral("m"), 4));
        add(top, tr("Contact normal"), formatVector(e.normal, QString(), 5), tr("Unit normal from the first ball towards the other body"));
        add(top, tr("Relative speed"), formatQuantity(e.approachSpeed, QStringLiteral("m/s"), 4), tr("Normal approach speed just before contact"));
        add(top, tr("Impulse"), formatVector(e.impulse, QStringLiteral("N·s"), 5), tr("Impulse on the first ball, table frame"));
        add(top, tr("|Impulse|"), formatQuantity(e.impulse.norm(), QStringLiteral("N·s"), 5));
    }

    if (const std::optional<aim::AimGeometry> g = aim::contactOfEvent(result, index)) addAim(top, *g);

    const int agents = e.kind == EventKind::BallBall ? 2 : 1;
    Vec2 pBefore = Vec2::Zero(), pAfter = Vec2::Zero();
    double keBefore = 0.0, keAfter = 0.0;
    for (int k = 0; k < agents; ++k) {
        const int b = e.balls[static_cast<std::size_t>(k)];
        if (b < 0 || b >= static_cast<int>(result.balls.size())) continue;
        const Ball& ball = result.balls[static_cast<std::size_t>(b)];
        const BallState& before = e.before[static_cast<std::size_t>(k)];
        const BallState& after = e.after[static_cast<std::size_t>(k)];
        auto* node = add(nullptr, tr("Ball %1").arg(QString::fromStdString(ball.id)), QString());
        addState(add(node, tr("Before"), QString()), before, ball.radius);
        addState(add(node, tr("After"), QString()), after, ball.radius);
        pBefore += momentum(before, ball.mass);
        pAfter += momentum(after, ball.mass);
        keBefore += kineticEnergy(before, ball.radius, ball.mass);
        keAfter += kineticEnergy(after, ball.radius, ball.mass);
    }
    auto* totals = add(nullptr, agents == 2 ? tr("Both balls") : tr("Totals"), QString());
    add(totals, tr("Momentum before"), formatVector(pBefore, QStringLiteral("kg·m/s"), 5));
    add(totals, tr("Momentum after"), formatVector(pAfter, QStringLiteral("kg·m/s"), 5));
    add(totals, tr("Kinetic energy before"), formatQuantity(keBefore, QStringLiteral("J"), 6), tr("Translation plus rotation, I = 2/5 m R²"));
    add(totals, tr("Kinetic energy after"), formatQuantity(keAfter, QStringLiteral("J"), 6));
    add(totals, tr("Energy change"), formatQuantity(keAfter - keBefore, QStringLiteral("J"), 6));
    if (e.kind != EventKind::CueStrike) {
        const aim::EnergyParts parts = aim::energyParts(result, index);
        add(totals, tr("Lost to the cloth"), formatQuantity(parts.lostToCloth, QStringLiteral("J"), 6),
            tr("Kinetic energy (J) the cloth took from these balls since each one's previous event"));
    }
    if (agents == 2) {
        const aim::CentreOfMassFrame com = aim::centreOfMassFrame(aim::frameBodies(result, index));
        auto* frame = add(totals, tr("Centre-of-mass frame"), formatVector(com.velocity, QStringLiteral("m/s"), 4),
                          tr("The pair's centre of mass moves at V = (m_a v_a + m_b v_b) / (m_a + m_b) (m/s); seen "
                             "from it the momenta p* = m (v − V) are equal and opposite"));
        for (int k = 0; k < 2; ++k) {
            const QString id = QString::fromStdString(result.balls[static_cast<std::size_t>(e.balls[static_cast<std::size_t>(k)])].id);
            add(frame, tr("p* %1 before").arg(id), formatVector(com.momentaBefore[static_cast<std::size_t>(k)], QStringLiteral("kg·m/s"), 5));
            add(frame, tr("p* %1 after").arg(id), formatVector(com.momentaAfter[static_cast<std::size_t>(k)], QStringLiteral("kg·m/s"), 5));
        }
    }
    tree_->expandAll();
}

}  // namespace cuelab
