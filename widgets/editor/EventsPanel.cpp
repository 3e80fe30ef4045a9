#include "EventsPanel.h"
#include "RunState.h"

#include "EventTreeModel.h"
#include "Quantities.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QSignalBlocker>
#include <QTreeView>
#include <QVBoxLayout>

#include <algorithm>

namespace cuelab {

EventsPanel::EventsPanel(QWidget* parent)
    : QWidget(parent),
      table_(new QTreeView(this)),
      model_(new EventTreeModel(this)),
      kinds_(new QComboBox(this)),
      ball_(new QComboBox(this)),
      minSpeed_(makeSpinBox({0.0, 20.0, 2, 0.05, tr("m/s"),
                             tr("Hide collisions whose normal approach speed is below this, in m/s (0 = show every collision)")},
                            this))
{
    using Kinds = EventFilter::Kinds;
    const std::pair<Kinds, QString> kinds[] = {
        {Kinds::All, tr("All events")},
        {Kinds::NoChangesOfMotion, tr("No changes of motion")},
        {Kinds::Collisions, tr("Collisions")},
        {Kinds::BallBall, tr("Ball–ball")},
        {Kinds::Cushions, tr("Cushions and jaws")},
        {Kinds::Pockets, tr("Pockets")},
        {Kinds::Strikes, tr("Cue strikes")},
        {Kinds::ChangesOfMotion, tr("Changes of motion")},
    };
    for (const auto& [kind, name] : kinds) kinds_->addItem(name, static_cast<int>(kind));
    kinds_->setToolTip(tr("Which kinds of event to list: changes of motion are slide to roll, roll to stop, ...; a break has many more of them than collisions"));
    ball_->setToolTip(tr("List only the events this ball takes part in"));
    minSpeed_->setSpecialValueText(tr("any speed"));
    minSpeed_->setPrefix(QStringLiteral("≥ "));

    table_->setModel(model_);
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->setSelectionMode(QAbstractItemView::SingleSelection);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setUniformRowHeights(true);  // fast scrolling through thousands of events
    table_->setRootIsDecorated(true);
    table_->setItemsExpandable(true);
    table_->setAllColumnsShowFocus(true);
    table_->header()->setSectionResizeMode(QHeaderView::Interactive);  // sized per result, not per frame
    table_->header()->setStretchLastSection(true);
    table_->setAlternatingRowColors(true);
    table_->setToolTip(tr("Select an event to jump to its time and see it in the Inspector; a row of events at one instant expands"));

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    // The filters show the start of a long choice rather than widening the side column.
    for (QComboBox* box : {kinds_, ball_}) {
        box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        box->setMinimumContentsLength(6);
    }
    auto* options = new QHBoxLayout;
    options->setContentsMargins(6, 2, 6, 0);
    options->addWidget(kinds_, 2);
    options->addWidget(ball_, 1);
    auto* speedLabel = new QLabel(tr("v_rel"), this);
    speedLabel->setToolTip(minSpeed_->toolTip());
    speedLabel->setBuddy(minSpeed_);
    // The speed filter on a row of its own: the panel fits a 240-pixel side column.
    auto* speedRow = new QHBoxLayout;
    speedRow->setContentsMargins(6, 0, 6, 0);
    speedRow->addWidget(speedLabel);
    speedRow->addWidget(minSpeed_, 1);
    layout->addLayout(options);
    layout->addLayout(speedRow);
    note_ = new QLabel(this);
    note_->setObjectName(QStringLiteral("eventsRunNote"));
    note_->setWordWrap(true);
    note_->setContentsMargins(6, 0, 6, 0);
    note_->hide();
    layout->addWidget(note_);
    layout->addWidget(table_);

    connect(kinds_, &QComboBox::currentIndexChanged, this, &EventsPanel::applyFilter);
    connect(ball_, &QComboBox::currentIndexChanged, this, &EventsPanel::applyFilter);
    connect(minSpeed_, &QDoubleSpinBox::valueChanged, this, &EventsPanel::applyFilter);
    connect(table_->selectionModel(), &QItemSelectionModel::selectionChanged, this, [this] {
        if (!selecting_) emit eventSelected(selectedEvent());
    });
    fillBalls();
}

int EventsPanel::selectedEvent() const
{
    const QModelIndexList rows = table_->selectionModel()->selectedRows();
    return rows.isEmpty() ? -1 : model_->eventAt(rows.front());
}

int EventsPanel::currentEvent() const { return model_->currentEvent(); }

void EventsPanel::fillBalls()
{
    const QSignalBlocker block(ball_);
    const int wanted = model_->filter().ball;
    ball_->clear();
    ball_->addItem(tr("Every ball"), -1);
    if (const auto& result = model_->result())
        for (std::size_t i = 0; i < result->balls.size(); ++i)
            ball_->addItem(tr("Ball %1").arg(QString::fromStdString(result->balls[i].id)), static_cast<int>(i));
    ball_->setCurrentIndex(std::max(0, ball_->findData(wanted)));
}

void EventsPanel::setResult(std::shared_ptr<const SimulationResult> result)
{
    const QString note = result ? RunState::unfinishedNote(*result) : QString();
    note_->setText(note);
    note_->setVisible(!note.isEmpty());
    selecting_ = true;
    model_->setResult(std::move(result));  // a reset clears the selection
    selecting_ = false;
    fillBalls();
    for (int c = 0; c < model_->columnCount(); ++c) table_->resizeColumnToContents(c);
    followCurrent();
}

void EventsPanel::setTime(double seconds)
{
    const int before = model_->currentEvent();
    model_->setTime(seconds);
    if (model_->currentEvent() != before) followCurrent();
}

void EventsPanel::followCurrent()
{
    // Keep the last event that has happened in view (at the start: the top; at the end: the last).
    const int current = model_->currentEvent();
    QModelIndex row = current >= 0 ? model_->indexOfEvent(current) : model_->index(0, 0);
    if (row.parent().isValid() && !table_->isExpanded(row.parent())) row = row.parent();
    if (row.isValid()) table_->scrollTo(row, QAbstractItemView::EnsureVisible);
}

void EventsPanel::setFilter(const EventFilter& filter)
{
    {
        const QSignalBlocker a(kinds_), b(ball_), c(minSpeed_);
        kinds_->setCurrentIndex(std::max(0, kinds_->findData(static_cast<int>(filter.kinds))));
        ball_->setCurrentIndex(std::max(0, ball_->findData(filter.ball)));
        minSpeed_->setValue(filter.minSpeed);
    }
    applyFilter();
}

void EventsPanel::applyFilter()
{
    EventFilter filter;
    filter.kinds = static_cast<EventFilter::Kinds>(kinds_->currentData().toInt());
    filter.ball = ball_->currentData().toInt();
    filter.minSpeed = minSpeed_->value();
    const int selected = selectedEvent();
    selecting_ = true;
    model_->setFilter(filter);
    selecting_ = false;
    setSelectedEvent(selected);  // stays selected when it is still listed
    followCurrent();
}

void EventsPanel::setSelectedEvent(int index)
{
    if (index == selectedEvent() && (index < 0 || table_->selectionModel()->hasSelection())) return;
    selecting_ = true;
    const QModelIndex row = model_->indexOfEvent(index);
    if (!row.isValid()) {  // out of range, or hidden by the filter
        table_->clearSelection();
    } else {
        if (row.parent().isValid()) table_->expand(row.parent());
        table_->selectionModel()->select(row, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
        table_->selectionModel()->setCurrentIndex(row, QItemSelectionModel::NoUpdate);
        table_->scrollTo(row);
    }
    selecting_ = false;
}

}  // namespace cuelab
