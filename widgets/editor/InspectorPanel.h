#pragma once
// The Inspector dock: everything about the selected ball at the current time, or about the selected
// event (time of impact, contact normal, relative speed, impulse, the agents' velocities and spins
// before and after, their momentum and kinetic energy before and after).

#include "Aim.h"
#include "Simulation.h"

#include <QWidget>

class QTreeWidget;
class QTreeWidgetItem;

namespace cuelab {

class InspectorPanel : public QWidget {
    Q_OBJECT
public:
    explicit InspectorPanel(QWidget* parent = nullptr);

    void showNothing();
    void showBall(const SimulationResult& result, int index, double time);
    void showEventDetails(const SimulationResult& result, int index);  // not QWidget::showEvent

    QTreeWidget* tree() const { return tree_; }
    // The value shown for a quantity (first match by name, searching the whole tree); for tests.
    QString value(const QString& quantity) const;

private:
    QTreeWidgetItem* add(QTreeWidgetItem* parent, const QString& quantity, const QString& value,
                         const QString& toolTip = {});
    void addState(QTreeWidgetItem* parent, const BallState& state, double radius);
    void addAim(QTreeWidgetItem* parent, const aim::AimGeometry& geometry);  // cut angle, ball fraction, ghost ball

    QTreeWidget* tree_;
};

}  // namespace cuelab
