#include "CollisionTable.h"

#include "i18n/UiNumbers.h"

#include "i18n/DisplayNames.h"

#include <QHeaderView>

namespace cuelab {

namespace {

enum Column { Index, ExactTime, ExactWhat, EngineTime, EngineWhat, Difference, ColumnCount };

QTableWidgetItem* makeItem(const QString& text, const QVariant& time = {})
{
    auto* i = new QTableWidgetItem(text);
    i->setFlags(Qt::ItemIsSelectable | Qt::ItemIsEnabled);
    if (time.isValid()) i->setData(Qt::UserRole, time);
    return i;
}

}  // namespace

CollisionTable::CollisionTable(QWidget* parent) : QTableWidget(parent)
{
    setColumnCount(ColumnCount);
    setHorizontalHeaderLabels({tr("#"), tr("exact t (s)"), tr("exact"), tr("engine t (s)"), tr("engine"), tr("Δt (ms)")});
    horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    horizontalHeader()->setStretchLastSection(true);
    verticalHeader()->hide();
    setSelectionBehavior(QAbstractItemView::SelectRows);
    setToolTip(tr("The collisions each method found, in order; # is the exact run's event number, as in the Events "
                  "list. Δt is the engine's time minus the exact one, in milliseconds, while the two sequences agree; "
                  "the first row where they differ is marked. Double-click a row to go to its time."));
    connect(this, &QTableWidget::cellDoubleClicked, this, [this](int row, int column) {
        const QTableWidgetItem* i = this->item(row, column);
        if (!i || !i->data(Qt::UserRole).isValid()) i = this->item(row, column <= ExactWhat ? ExactTime : EngineTime);
        if (!i || !i->data(Qt::UserRole).isValid()) i = this->item(row, ExactTime);
        if (!i || !i->data(Qt::UserRole).isValid()) i = this->item(row, EngineTime);
        if (i && i->data(Qt::UserRole).isValid()) emit timeRequested(i->data(Qt::UserRole).toDouble());
    });
}

QString CollisionTable::describe(const compare::Collision& c, const std::vector<std::string>& ids)
{
    const QString ball = QString::fromStdString(ids[static_cast<std::size_t>(c.ball)]);
    switch (c.kind) {
    case compare::CollisionKind::BallBall:
        return ball + QStringLiteral(" – ") + QString::fromStdString(ids[static_cast<std::size_t>(c.other)]);
    case compare::CollisionKind::BallCushion: return ball + QStringLiteral(" | ") + QString::fromStdString(c.agent);
    case compare::CollisionKind::BallPocket: return ball + QStringLiteral(" ↓ ") + QString::fromStdString(c.agent);
    }
    return ball;
}

void CollisionTable::clearComparison()
{
    setRowCount(0);
}

void CollisionTable::setComparison(const compare::Comparison& c)
{
    const auto& a = c.exact.collisions;
    const auto& b = c.run.collisions;
    setHorizontalHeaderItem(EngineTime, new QTableWidgetItem(
                                            tr("%1 t (s)").arg(QString::fromUtf8(compare::toString(c.run.settings.engine).data()))));
    setHorizontalHeaderItem(EngineWhat, new QTableWidgetItem(QString::fromUtf8(compare::toString(c.run.settings.engine).data())));
    const int rows = static_cast<int>(std::max(a.size(), b.size()));
    setRowCount(rows);
    const int first = c.divergence.firstSequenceDifference.value_or(-1);
    for (int r = 0; r < rows; ++r) {
        const std::size_t k = static_cast<std::size_t>(r);
        // The exact run's event number (#N, as the Events list, Explain and the report write it).
        setItem(r, Index, makeItem(k < a.size() && a[k].event >= 0 ? eventNumber(a[k].event) : QString()));
        if (k < a.size()) {
            setItem(r, ExactTime, makeItem(uiNumber(a[k].time, 4), a[k].time));
            setItem(r, ExactWhat, makeItem(describe(a[k], c.exact.ids)));
        } else {
            setItem(r, ExactTime, makeItem(QString()));
            setItem(r, ExactWhat, makeItem(tr("(none)")));
        }
        if (k < b.size()) {
            setItem(r, EngineTime, makeItem(uiNumber(b[k].time, 4), b[k].time));
            setItem(r, EngineWhat, makeItem(describe(b[k], c.run.ids)));
        } else {
            setItem(r, EngineTime, makeItem(QString()));
            setItem(r, EngineWhat, makeItem(tr("(none)")));
        }
        const bool matched = k < c.divergence.matched.size();
        setItem(r, Difference, makeItem(matched ? uiNumber(1000.0 * c.divergence.matched[k].difference(), 2)
                                            : QString()));
        if (r == first) {
            for (int col = 0; col < ColumnCount; ++col) {
                QTableWidgetItem* i = this->item(r, col);
                i->setBackground(QColor(255, 210, 200));
                i->setForeground(QColor(20, 20, 20));
                i->setToolTip(tr("The first collision where the two methods disagree"));
            }
        } else if (first >= 0 && r > first) {
            for (int col = 0; col < ColumnCount; ++col) this->item(r, col)->setForeground(QColor(130, 130, 130));
        }
    }
}

}  // namespace cuelab
