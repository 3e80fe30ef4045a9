#include "BallsPanel.h"

#include "BallEditor.h"
#include "i18n/DisplayNames.h"
#include "layout/ColumnFit.h"
#include "Document.h"
#include "ResultFeed.h"
#include "Quantities.h"

#include <QAction>
#include <QFontMetrics>
#include <QDoubleSpinBox>
#include <QHeaderView>
#include <QMenu>
#include <QSplitter>
#include <QSignalBlocker>
#include <QStyledItemDelegate>
#include <QEvent>
#include <QTableWidget>
#include <QToolBar>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>

namespace cuelab {

namespace {

constexpr int kPositionDecimals = 4;  // 0.1 mm: finer than a ball is ever placed by hand
constexpr int kValueRole = Qt::UserRole;  // the exact coordinate, m, behind the rounded text

// Edits a coordinate cell with a spin box in metres; the exact value travels in kValueRole.
class CoordinateDelegate : public QStyledItemDelegate {
public:
    using QStyledItemDelegate::QStyledItemDelegate;

    QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem&, const QModelIndex&) const override
    {
        return makeSpinBox({0.0, 10.0, kPositionDecimals, 0.001, QStringLiteral("m"),
                            QObject::tr("Position of the ball's centre at t = 0, in metres")},
                           parent);
    }
    void setEditorData(QWidget* editor, const QModelIndex& index) const override
    {
        static_cast<QDoubleSpinBox*>(editor)->setValue(index.data(kValueRole).toDouble());
    }
    void setModelData(QWidget* editor, QAbstractItemModel* model, const QModelIndex& index) const override
    {
        auto* box = static_cast<QDoubleSpinBox*>(editor);
        box->interpretText();
        // Unchanged digits keep the exact value (a file may hold more digits than the spin box shows).
        if (formatNumber(box->value(), kPositionDecimals) == formatNumber(index.data(kValueRole).toDouble(), kPositionDecimals))
            return;
        model->setData(index, box->value(), kValueRole);
    }
};

}  // namespace

BallsPanel::BallsPanel(Document* document, QWidget* parent) : QWidget(parent), document_(document)
{
    table_ = new QTableWidget(0, ColumnCount, this);
    table_->setHorizontalHeaderLabels({tr("Ball"), tr("x₀ (m)"), tr("y₀ (m)"), tr("State"), tr("Position (m)"), tr("|v| (m/s)")});
    table_->horizontalHeaderItem(XColumn)->setToolTip(tr("Set-up position along the length, in metres (double-click to edit)"));
    table_->horizontalHeaderItem(YColumn)->setToolTip(tr("Set-up position across the width, in metres (double-click to edit)"));
    table_->horizontalHeaderItem(StateColumn)->setToolTip(tr("Motion state at the current time"));
    table_->horizontalHeaderItem(PositionColumn)->setToolTip(tr("Position at the current time, in metres"));
    table_->horizontalHeaderItem(SpeedColumn)->setToolTip(tr("Speed at the current time, in m/s"));
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->setSelectionMode(QAbstractItemView::SingleSelection);
    table_->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
    table_->verticalHeader()->hide();
    // Compact rows: a full rack (16 balls) shows whole above the editor in a dock of a 800-pixel-high window.
    table_->verticalHeader()->setDefaultSectionSize(table_->fontMetrics().height() + 6);
    // Columns are sized when the balls change, not on every frame of playback (ResizeToContents
    // would measure every row each time a speed changes).
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
    table_->setAlternatingRowColors(true);
    auto* delegate = new CoordinateDelegate(table_);
    table_->setItemDelegateForColumn(XColumn, delegate);
    table_->setItemDelegateForColumn(YColumn, delegate);
    table_->viewport()->installEventFilter(this);

    add_ = new QAction(QIcon::fromTheme(QStringLiteral("list-add")), tr("&Add Ball"), this);
    add_->setToolTip(tr("Add a ball on a free spot near the centre of the table"));
    remove_ = new QAction(QIcon::fromTheme(QStringLiteral("list-remove")), tr("&Remove Ball"), this);
    remove_->setToolTip(tr("Remove the selected ball"));
    duplicate_ = new QAction(QIcon::fromTheme(QStringLiteral("edit-copy")), tr("D&uplicate Ball"), this);
    duplicate_->setToolTip(tr("Add a copy of the selected ball next to it"));
    rackMenu_ = new QMenu(tr("Rac&k"), this);
    rackMenu_->setToolTip(tr("Replace the balls by a standard rack"));
    for (RackPreset preset : kAllRackPresets)
        rackMenu_->addAction(rackName(preset), document_, [this, preset] { document_->applyRack(preset); });

    auto* tools = new QToolBar(this);
    tools->setToolButtonStyle(Qt::ToolButtonTextOnly);
    tools->addAction(add_);
    tools->addAction(remove_);
    tools->addAction(duplicate_);
    auto* rackButton = new QToolButton(tools);
    rackButton->setText(tr("Rack"));
    rackButton->setToolTip(rackMenu_->toolTip());
    rackButton->setMenu(rackMenu_);
    rackButton->setPopupMode(QToolButton::InstantPopup);
    tools->addWidget(rackButton);

    editor_ = new BallEditor(document_, this);
    auto* split = new QSplitter(Qt::Vertical, this);
    split->setChildrenCollapsible(false);
    split->addWidget(table_);
    split->addWidget(editor_);
    split->setStretchFactor(0, 1);
    split->setStretchFactor(1, 0);

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addWidget(tools);
    layout->addWidget(split);

    connect(add_, &QAction::triggered, this, [this] {
        const int index = document_->addBall();
        if (index < 0) return;
        setSelectedBall(index);
        emit ballSelected(index);
    });
    connect(remove_, &QAction::triggered, this, [this] { document_->removeBall(selectedBall()); });
    connect(duplicate_, &QAction::triggered, this, [this] {
        const int index = document_->duplicateBall(selectedBall());
        if (index < 0) return;
        setSelectedBall(index);
        emit ballSelected(index);
    });
    // The edit runs after the item delegate has closed its editor: the rebuild it causes must not
    // pull the table out from under an editor that is still committing.
    connect(table_, &QTableWidget::itemChanged, this, [this](QTableWidgetItem* item) {
        const int row = item->row(), column = item->column();
        QMetaObject::invokeMethod(this, [this, row, column] { commitItem(row, column); }, Qt::QueuedConnection);
    });
    connect(table_, &QTableWidget::itemSelectionChanged, this, [this] {
        updateActions();
        editor_->setBall(selectedBall());
        if (!refreshing_) emit ballSelected(selectedBall());
    });
    connect(document_, &Document::setupChanged, this, &BallsPanel::rebuild);
    ResultFeed::follow(document_, this, [this] { refreshMotion(); });
    connect(document_, &Document::dragFinished, this, &BallsPanel::fitColumns);
    rebuild();
}

int BallsPanel::selectedBall() const
{
    const QList<QTableWidgetSelectionRange> ranges = table_->selectedRanges();
    return ranges.isEmpty() ? -1 : ranges.front().topRow();
}

void BallsPanel::setSelectedBall(int index)
{
    if (index == selectedBall()) return;
    refreshing_ = true;
    if (index < 0 || index >= table_->rowCount()) table_->clearSelection();
    else table_->selectRow(index);
    refreshing_ = false;
    editor_->setBall(selectedBall());
    updateActions();
}

void BallsPanel::setTime(double seconds)
{
    time_ = seconds;
    refreshMotion();
}

void BallsPanel::updateActions()
{
    const bool any = selectedBall() >= 0;
    remove_->setEnabled(any);
    duplicate_->setEnabled(any);
}

void BallsPanel::rebuild()
{
    refreshing_ = true;
    const int selected = selectedBall();
    const QSignalBlocker block(table_);
    const std::vector<Ball>& balls = document_->setup().balls;
    table_->setRowCount(static_cast<int>(balls.size()));
    for (int row = 0; row < table_->rowCount(); ++row) {
        const Ball& ball = balls[static_cast<std::size_t>(row)];
        for (int column = 0; column < ColumnCount; ++column) {
            if (!table_->item(row, column)) {
                auto* item = new QTableWidgetItem;
                const bool editable = column == IdColumn || column == XColumn || column == YColumn;
                item->setFlags(editable ? item->flags() | Qt::ItemIsEditable : item->flags() & ~Qt::ItemIsEditable);
                if (column != IdColumn && column != StateColumn) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
                table_->setItem(row, column, item);
            }
        }
        table_->item(row, IdColumn)->setText(QString::fromStdString(ball.id));
        table_->item(row, IdColumn)->setToolTip(tr("Ball id (double-click to rename)"));
        table_->item(row, XColumn)->setData(kValueRole, ball.state.position.x());
        table_->item(row, XColumn)->setText(formatNumber(ball.state.position.x(), kPositionDecimals));
        table_->item(row, YColumn)->setData(kValueRole, ball.state.position.y());
        table_->item(row, YColumn)->setText(formatNumber(ball.state.position.y(), kPositionDecimals));
    }
    if (selected >= 0 && selected < table_->rowCount()) table_->selectRow(selected);
    refreshing_ = false;
    editor_->setBall(selectedBall());
    refreshMotion();
    if (!document_->isDragging()) fitColumns();  // a drag's steps change numbers, not the columns' widths
    updateActions();
}

void BallsPanel::fitColumns()
{
    table_->resizeColumnsToContents();
    // Room for the widest text the time-dependent columns can show.
    const QFontMetrics fm = table_->fontMetrics();
    const int padding = fm.averageCharWidth() + 4;
    const auto atLeast = [&](int column, const QString& widest) {
        table_->setColumnWidth(column, std::max(table_->columnWidth(column), fm.horizontalAdvance(widest) + padding));
    };
    atLeast(StateColumn, QStringLiteral("stationary"));
    atLeast(PositionColumn, QStringLiteral("(0.000, 0.000)"));
    // A narrow dock: the columns give up what they have beyond their texts rather than scroll sideways.
    fitColumnsToWidth(table_, ColumnText::OneLine);
}

bool BallsPanel::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == table_->viewport() && event->type() == QEvent::Resize) fitColumns();
    return QWidget::eventFilter(watched, event);
}

void BallsPanel::refreshMotion()
{
    const QSignalBlocker block(table_);
    const auto result = document_->result();
    // A result still being computed for an older setup may have other balls: show nothing rather
    // than a wrong row.
    const bool usable = result && document_->isResultForSetup() &&
                        result->balls.size() == static_cast<std::size_t>(table_->rowCount());
    for (int row = 0; row < table_->rowCount(); ++row) {
        if (!usable) {
            for (int column : {StateColumn, PositionColumn, SpeedColumn}) table_->item(row, column)->setText(QStringLiteral("–"));
            continue;
        }
        const BallState s = result->stateAt(row, time_);
        table_->item(row, StateColumn)->setText(displayName(s.motion));
        const bool onTable = s.motion != MotionState::Pocketed;
        table_->item(row, PositionColumn)->setText(onTable ? formatVector(s.position, QString(), 3).trimmed() : QStringLiteral("–"));
        table_->item(row, SpeedColumn)->setText(onTable ? formatNumber(s.velocity.norm(), 3) : QStringLiteral("–"));
    }
}

void BallsPanel::commitItem(int row, int column)
{
    if (refreshing_ || row < 0 || row >= static_cast<int>(document_->setup().balls.size())) return;
    Ball ball = document_->setup().balls[static_cast<std::size_t>(row)];
    QString text;
    if (column == IdColumn) {
        const std::string id = table_->item(row, IdColumn)->text().trimmed().toStdString();
        if (id == ball.id) return;
        text = tr("Rename ball %1 to %2").arg(QString::fromStdString(ball.id), QString::fromStdString(id));
        ball.id = id;
    } else if (column == XColumn || column == YColumn) {
        ball.state.position = Vec2(table_->item(row, XColumn)->data(kValueRole).toDouble(),
                                   table_->item(row, YColumn)->data(kValueRole).toDouble());
        text = tr("Move ball %1").arg(QString::fromStdString(ball.id));
    } else {
        return;
    }
    // The columns are the first BallProperty values (Id, X, Y): one merge field with the editor's.
    if (!document_->setBall(row, ball, text, column)) rebuild();  // refused: show the setup as it is
    document_->endMerge();  // a typed value is a step of its own
}

}  // namespace cuelab
