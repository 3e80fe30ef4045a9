#pragma once
// The CueLab main window: the table view and the transport in the middle, the editor's docks
// around it (Balls, Physics, Shot, Events, Inspector), the menus, files and the remembered layout.

#include "view/ViewScene.h"

#include <QMainWindow>

#include <array>

class QAction;
class QDockWidget;
class QLabel;
class QMenu;
class QProgressBar;

namespace cuelab {

class BallsPanel;
class Document;
class EventsPanel;
class InspectorPanel;
class Playback;
class PhysicsPanel;
class RecentFiles;
class ShotPanel;
class TableView;
class TransportBar;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Opens a setup file. A refused file shows the loader's message and keeps the current document.
    // Asks first when there are unsaved changes (and returns false if the user cancels).
    bool openFile(const QString& path);
    bool openExample(const QString& resourcePath);  // ":/examples/NAME.json"
    bool saveFile(const QString& path);

    Document* document() const { return document_; }
    Playback* playback() const { return playback_; }
    TableView* tableView() const { return view_; }
    TransportBar* transportBar() const { return transport_; }
    BallsPanel* ballsPanel() const { return balls_; }
    EventsPanel* eventsPanel() const { return events_; }
    InspectorPanel* inspector() const { return inspector_; }
    ShotPanel* shotPanel() const { return shot_; }
    PhysicsPanel* physicsPanel() const { return physics_; }
    RecentFiles* recentMenu() const { return recentMenu_; }
    QMenu* examplesMenu() const { return examplesMenu_; }

    static QStringList bundledExamples();  // resource paths, sorted

protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void createDocks();
    void createMenus();
    void createStatusBar();
    void readSettings();
    void writeSettings() const;

    bool maybeSave();  // true when it is fine to drop the current document
    bool save();
    bool saveAs();
    void newDocument();
    void open();
    void updateTitle();
    void showError(const QString& title, const QString& message);
    void about();

    void onResultChanged();
    void onTimeChanged(double seconds);
    void selectBall(int index);
    void selectEvent(int index);
    void selectEventAtCurrentTime();
    void refreshInspector();

    Document* document_;
    Playback* playback_;
    TableView* view_ = nullptr;
    TransportBar* transport_ = nullptr;
    BallsPanel* balls_ = nullptr;
    PhysicsPanel* physics_ = nullptr;
    ShotPanel* shot_ = nullptr;
    EventsPanel* events_ = nullptr;
    InspectorPanel* inspector_ = nullptr;
    QList<QDockWidget*> docks_;
    RecentFiles* recentMenu_ = nullptr;
    QMenu* examplesMenu_ = nullptr;
    std::array<QAction*, kOverlayCount> overlayActions_{};
    QLabel* summaryLabel_ = nullptr;
    QLabel* fpsLabel_ = nullptr;
    QProgressBar* busy_ = nullptr;

    int selectedBall_ = -1;
    int selectedEvent_ = -1;
    enum class InspectorSubject { None, Ball, Event };
    InspectorSubject inspectorSubject_ = InspectorSubject::None;
};

}  // namespace cuelab
