#pragma once
// The collisions of the exact run and of the compared engine side by side, row by row in order: a
// row where they agree shows the time difference; the first row where the sequences part is marked.

#include "Divergence.h"

#include <QTableWidget>

namespace cuelab {

class CollisionTable : public QTableWidget {
    Q_OBJECT
public:
    explicit CollisionTable(QWidget* parent = nullptr);
    void setComparison(const compare::Comparison& comparison);
    void clearComparison();

    // Text of a collision as the table shows it: "cue - 1", "cue | rail-r", "1 > pocket-tr".
    static QString describe(const compare::Collision& c, const std::vector<std::string>& ids);

signals:
    void timeRequested(double seconds);  // a cell was double-clicked: go to its collision's time
};

}  // namespace cuelab
