#pragma once

#include <QMainWindow>

class QUndoStack;

// The CueLab main window: menus, status bar, docks around the table view.
class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);

private:
    void createMenus();
    void about();

    QUndoStack* undoStack_ = nullptr;
};
