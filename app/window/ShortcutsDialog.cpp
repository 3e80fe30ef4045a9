#include "ShortcutsDialog.h"

#include <QAction>
#include <QDialogButtonBox>
#include <QGuiApplication>
#include <QScreen>
#include <QScrollBar>
#include <QHeaderView>
#include <QMenu>
#include <QMenuBar>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace cuelab {

namespace {

QString plain(QString text)
{
    text.remove(QLatin1Char('&'));
    text.remove(QStringLiteral("…"));
    return text.trimmed();
}

void collect(const QMenu* menu, const QString& path, QList<ShortcutsDialog::Row>& rows)
{
    for (QAction* a : menu->actions()) {
        if (a->isSeparator()) continue;
        if (QMenu* sub = a->menu()) {
            collect(sub, path + QStringLiteral(" › ") + plain(sub->title()), rows);
            continue;
        }
        QStringList keys;
        for (const QKeySequence& k : a->shortcuts()) keys << k.toString(QKeySequence::NativeText);
        if (keys.isEmpty()) continue;
        // An action whose caption changes (Undo says what it undoes) names itself for the list.
        const QString name = a->property("shortcutName").toString();
        rows.push_back({path, name.isEmpty() ? plain(a->text()) : name, keys.join(QStringLiteral(", "))});
    }
}

}  // namespace

QList<ShortcutsDialog::Row> ShortcutsDialog::keyboardRows(const QMenuBar* menus)
{
    QList<Row> rows;
    for (QAction* top : menus->actions())
        if (QMenu* m = top->menu()) collect(m, plain(m->title()), rows);
    // One group per menu: a submenu in the middle of its menu (File › Export before Quit) must not
    // split the menu's rows into two groups of the same name.
    QList<Row> grouped;
    QStringList order;
    for (const Row& r : std::as_const(rows))
        if (!order.contains(r.group)) order << r.group;
    for (const QString& group : std::as_const(order))
        for (const Row& r : std::as_const(rows))
            if (r.group == group) grouped << r;
    return grouped;
}

QList<ShortcutsDialog::Row> ShortcutsDialog::mouseRows()
{
    const QString view = tr("Table view");
    const QString predict = tr("Predict (while a question waits)");
    const QString panels = tr("Panels");
    return {
        {view, tr("Select a ball"), tr("Click the ball")},
        {view, tr("Move a ball (at t = 0)"), tr("Drag the ball; it lands on the nearest free spot")},
        {view, tr("Aim: turn the cue (at t = 0)"), tr("Drag across the cue, or drag the ghost ball")},
        {view, tr("Cue speed"), tr("Drag along the cue: back for faster, forward for slower")},
        {view, tr("Strike off centre (side, height)"), tr("Drag the tip mark on the ball in the player view (Ctrl+2)")},
        {view, tr("Fine-tune the aim (view focused)"), tr("Ctrl+Left/Right: heading ±0.1°; Ctrl+Up/Down: speed ±0.1 m/s; Shift ×10, Alt ×0.1")},
        {view, tr("Give a ball an initial velocity (at t = 0)"),
         tr("Ctrl + drag from the ball (not the struck ball), or drag the head of its velocity arrow")},
        {view, tr("Orbit the camera"), tr("Drag on the cloth or the background")},
        {view, tr("Pan the camera"), tr("Right or middle drag, or Shift + drag")},
        {view, tr("Zoom towards the cursor"), tr("Mouse wheel")},
        {view, tr("Centre the camera on a point"), tr("Double-click")},
        {predict, tr("Say where a ball will go"), tr("Drag from the ringed ball the way it will go; drag again to change it")},
        {predict, tr("Say a ball stays"), tr("Click the ringed ball")},
        {predict, tr("Move the camera"), tr("Right or middle drag, and the mouse wheel")},
        {panels, tr("Edit a value"), tr("Double-click a cell, type, Enter")},
        {panels, tr("Place the cue tip"), tr("Click or drag on the ball face in Shot")},
        {panels, tr("Jump to an event"), tr("Click its row in Events")},
        {panels, tr("Scrub time"), tr("Drag the time slider; ticks mark events")},
        {panels, tr("Open a setup"), tr("Drop a .json file on the window")},
    };
}

ShortcutsDialog::ShortcutsDialog(const QMenuBar* menus, QWidget* parent) : QDialog(parent)
{
    setObjectName(QStringLiteral("ShortcutsDialog"));
    setWindowTitle(tr("Keyboard and Mouse"));
    auto* tree = new QTreeWidget(this);
    tree->setObjectName(QStringLiteral("shortcutsTree"));
    tree->setColumnCount(2);
    tree->setHeaderLabels({tr("Action"), tr("Keys or gesture")});
    tree->setRootIsDecorated(true);
    tree->setAlternatingRowColors(true);
    const auto fill = [tree](const QString& title, const QList<Row>& rows) {
        auto* top = new QTreeWidgetItem(tree, {title});
        QFont bold = top->font(0);
        bold.setBold(true);
        top->setFont(0, bold);
        QTreeWidgetItem* group = nullptr;
        QString groupName;
        for (const Row& r : rows) {
            if (!group || r.group != groupName) {
                group = new QTreeWidgetItem(top, {r.group});
                groupName = r.group;
            }
            new QTreeWidgetItem(group, {r.what, r.how});
        }
    };
    fill(tr("Keyboard"), keyboardRows(menus));
    fill(tr("Mouse"), mouseRows());
    tree->expandAll();
    // Both columns whole: the keys are what the list is for.
    tree->header()->setStretchLastSection(false);
    tree->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    tree->header()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(tree);
    layout->addWidget(buttons);
    // As wide as both columns (and the tree's frame and scroll bar), within the screen.
    const int columns = tree->header()->sectionSizeHint(0) + tree->header()->sectionSizeHint(1);
    const QAbstractItemView* view = tree;
    int width = std::max(columns, view->sizeHintForColumn(0) + view->sizeHintForColumn(1));
    width += 2 * tree->frameWidth() + tree->verticalScrollBar()->sizeHint().width() + 40;
    const QRect screen = QGuiApplication::primaryScreen() ? QGuiApplication::primaryScreen()->availableGeometry() : QRect(0, 0, 1280, 800);
    resize(std::min(std::max(620, width), screen.width() * 9 / 10), std::min(720, screen.height() * 9 / 10));
}

}  // namespace cuelab
