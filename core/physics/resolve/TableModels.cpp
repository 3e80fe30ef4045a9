// The registry of ball-table models: the one place that maps a model to its resolver and its name
// in files. A new model is a new file in this folder and one row below.

#include "resolve/FrictionalTable.h"
#include "resolve/FrictionlessTable.h"
#include "resolve/TableModel.h"

#include <array>

namespace cuelab {

namespace {

const std::array kModels{
    TableModelEntry{BallTableModel::Frictional, "frictional", "Frictional",
                    "restitution and Coulomb friction with the cloth: a bounce removes slip (pooltool's frictional_inelastic)",
                    true, &frictionalTable},
    TableModelEntry{BallTableModel::Frictionless, "frictionless", "Frictionless",
                    "restitution only: a bounce leaves the horizontal velocity and the spin as they are", false,
                    &frictionlessTable},
};

}  // namespace

std::span<const TableModelEntry> tableModels() { return kModels; }

const TableModelEntry& tableModel(BallTableModel model)
{
    for (const TableModelEntry& e : kModels)
        if (e.model == model) return e;
    return kModels.front();  // unreachable: every enumerator has a row (tested)
}

const TableModelEntry* findTableModel(std::string_view name)
{
    for (const TableModelEntry& e : kModels)
        if (e.name == name) return &e;
    return nullptr;
}

std::string_view toString(BallTableModel m) { return tableModel(m).name; }

TableImpactResult resolveTableImpact(const AirState& before, double radius, double mass, const PhysicsParams& p)
{
    return tableModel(p.ballTableModel).resolve({before, radius, mass}, p);
}

double effectiveTableFriction(const PhysicsParams& p)
{
    return tableModel(p.ballTableModel).usesFriction ? p.tableFriction : 0.0;
}

}  // namespace cuelab
