#include "EventsPanel.h"

#include "EventTableModel.h"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QSortFilterProxyModel>
#include <QItemSelectionModel>
#include <QTableView>
#include <QVBoxLayout>

namespace cuelab {

namespace {

// Hides the changes of motion (slide to roll, roll to stop, ...) when the user only wants the
// collisions, strikes and pockets; a break has many more of them than collisions.
class EventKindFilter : public QSortFilterProxyModel {
public:
    using QSortFilterProxyModel::QSortFilterProxyModel;

    void setShowTransitions(bool show)
    {
        showTransitions_ = show;
        invalidateFilter();
    }

protected:
    bool filterAcceptsRow(int row, const QModelIndex&) const override
    {
        const Event* e = static_cast<const EventTableModel*>(sourceModel())->event(row);
        return showTransitions_ || !e || !isTransition(e->kind);
    }

private:
    bool showTransitions_ = true;
};

}  // namespace

EventsPanel::EventsPanel(QWidget* parent)
    : QWidget(parent),
      table_(new QTableView(this)),
      model_(new EventTableModel(this)),
      filter_(new EventKindFilter(this)),
      showTransitions_(new QCheckBox(tr("Show changes of motion"), this))
{
    filter_->setSourceModel(model_);
    table_->setModel(filter_);
    showTransitions_->setChecked(true);
    showTransitions_->setToolTip(tr("List the changes of motion too (slide to roll, roll to stop, ...), not only strikes, collisions and pockets"));
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
    layout->setSpacing(2);
    auto* options = new QHBoxLayout;
    options->setContentsMargins(6, 2, 6, 0);
    options->addWidget(showTransitions_);
    options->addStretch(1);
    layout->addLayout(options);
    layout->addWidget(table_);

    connect(showTransitions_, &QCheckBox::toggled, this, [this](bool show) {
        const int selected = selectedEvent();
        selecting_ = true;
        static_cast<EventKindFilter*>(filter_)->setShowTransitions(show);
        selecting_ = false;
        setSelectedEvent(-1);
        setSelectedEvent(selected);  // stays selected when it is still listed
    });

    connect(table_->selectionModel(), &QItemSelectionModel::selectionChanged, this, [this] {
        if (!selecting_) emit eventSelected(selectedEvent());
    });
}

int EventsPanel::selectedEvent() const
{
    const QModelIndexList rows = table_->selectionModel()->selectedRows();
    return rows.isEmpty() ? -1 : filter_->mapToSource(rows.front()).row();
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
    const QModelIndex row = filter_->mapFromSource(model_->index(index, 0));
    if (!row.isValid()) {  // out of range, or a change of motion that is not listed
        table_->clearSelection();
    } else {
        table_->selectRow(row.row());
        table_->scrollTo(row);
    }
    selecting_ = false;
}

}  // namespace cuelab
