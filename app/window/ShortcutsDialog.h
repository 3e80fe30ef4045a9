#pragma once
// Help > Keyboard and Mouse: every shortcut of the window's menus (read from the actions
// themselves, so a new action with a shortcut appears without editing this file) and the mouse
// gestures of the table view and the panels.

#include <QDialog>

class QMenuBar;

namespace cuelab {

class ShortcutsDialog : public QDialog {
    Q_OBJECT
public:
    ShortcutsDialog(const QMenuBar* menus, QWidget* parent = nullptr);

    // The rows shown: (where, what, keys or gesture). Public for tests.
    struct Row {
        QString group;
        QString what;
        QString how;
    };
    static QList<Row> keyboardRows(const QMenuBar* menus);
    static QList<Row> mouseRows();
};

}  // namespace cuelab
