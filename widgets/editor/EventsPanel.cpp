#include "EventsPanel.h"

#include "EventTableModel.h"

#include <QHeaderView>
#include <QItemSelectionModel>
#include <QTableView>
#include <QVBoxLayout>

namespace cuelab {

EventsPanel::EventsPanel(QWidget* parent) : QWidget(parent), table_(new QTableView(this)), model_(new EventTableModel(this))
{
    table_->setModel(model_);
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->setSelectionMode(QAbstractItemView::SingleSelection);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->verticalHeader()->hide();
    table_->verticalHeader()->setDefaultSectionSize(table_->fontMetrics().height() + 6);
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);  // sized per result, not per frame
    table_->horizontalHeader()->setStretchLastSection(true);
    table_->setAlternatingRowColors(true);
    table_->setToolTip(tr("Select an event to jump to its time and see it in the Inspector"));

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(table_);

    connect(table_->selectionModel(), &QItemSelectionModel::selectionChanged, this, [this] {
        if (!selecting_) emit eventSelected(selectedEvent());
    });
}

int EventsPanel::selectedEvent() const
{
    const QModelIndexList rows = table_->selectionModel()->selectedRows();
    return rows.isEmpty() ? -1 : rows.front().row();
}

void EventsPanel::setResult(std::shared_ptr<const SimulationResult> result)
{
    selecting_ = true;
    model_->setResult(std::move(result));  // a reset clears the selection
    selecting_ = false;
    table_->resizeColumnsToContents();
}

void EventsPanel::setTime(double seconds) { model_->setTime(seconds); }

void EventsPanel::setSelectedEvent(int index)
{
    if (index == selectedEvent()) return;
    selecting_ = true;
    if (index < 0 || index >= model_->rowCount()) {
        table_->clearSelection();
    } else {
        table_->selectRow(index);
        table_->scrollTo(model_->index(index, 0));
    }
    selecting_ = false;
}

}  // namespace cuelab
