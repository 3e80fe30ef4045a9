#pragma once
// The CueLab main window: the table view and the transport in the middle, the editor's docks
// around it (Balls, Physics, Shot, Events, Inspector), the menus, files and the remembered layout.
//
// Features (plots, explanations, comparisons, analysis, ...) add themselves through the public
// extension API below: addPanel() for a dock, menu() for a place in the menus, and the shared
// objects (document, playback, selection, table view). Each feature is one install function in
// app/window/features/, called from Features.cpp, so that a new dock touches no central file.
//
// The class is split by job: MainWindow.cpp (layout, docks, selection and result wiring),
// MainWindowMenus.cpp (menus and actions), MainWindowFiles.cpp (new, open, save, examples, settings).

#include "Arrangements.h"
#include "view/ViewScene.h"

#include <QMainWindow>

#include <array>

class QAction;
class QDockWidget;
class QLabel;
class QMenu;

namespace cuelab {

class BallsPanel;
class DockLayout;
class FirstStartTip;
class SimulationOverlay;
class Document;
class EventsPanel;
class InspectorPanel;
class Playback;
class PhysicsPanel;
class RecentFiles;
class Selection;
class ShotPanel;
class TableView;
class TransportBar;

// The menus a feature can add to. Export is the File menu's Export submenu; Analysis is a top-level
// menu between View and Playback, shown once something is in it.
enum class WindowMenu { File, Export, Edit, View, Analysis, Playback, Help };

// Where a feature's dock goes first (the user may move it; the layout is remembered).
struct PanelPlacement {
    Qt::DockWidgetArea area = Qt::RightDockWidgetArea;
    QString tabifyWith;   // object name of a dock to share tabs with ("InspectorDock"), or empty
    // Every dock's content now sits in a scroll area (resizable: it fills the dock, and scrolls only
    // below its own minimum size), so that no panel's minimum keeps the window from shrinking to
    // 800x600. The flag is kept for the callers that say a panel is a tall form.
    bool scroll = false;
    bool visible = true;  // shown on the first start
};

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

    Selection* selection() const { return selection_; }

    // The extension API for features (app/window/features/). addPanel puts `content` in a dock named
    // `objectName` (saveState/restoreState find docks by name: keep it stable) and lists it in
    // View > Panels. menu() is a menu a feature adds its actions to.
    QDockWidget* addPanel(QWidget* content, const QString& title, const QString& objectName,
                          const PanelPlacement& placement = {});
    QMenu* menu(WindowMenu which);
    QList<QDockWidget*> panels() const { return docks_; }
    DockLayout* dockLayout() const { return layout_; }
    void resetLayout();  // View > Layouts > Reset Layout: the docks where the first start put them
    void arrange(Arrangement arrangement);  // View > Layouts

    // The first start: the screen's available area, maximised on a screen up to 1920 px wide, about
    // 80 % of it (centred) beyond. showOnStart shows the window so (main.cpp); later starts restore
    // the remembered geometry.
    static constexpr int kMaximiseUpToWidth = 1920;
    // More balls than this make a busy shot (a break): it opens with the struck ball selected and
    // only its paths and event times shown (View > Paths Of, Labels Of: Selected Ball Only).
    static constexpr std::size_t kBusyShotBalls = 6;
    static QRect firstStartGeometry(const QRect& available);
    static bool maximisesOnFirstStart(const QRect& available);
    void showOnStart();

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
    void refreshResultLists();
    void scopeForBusyShot();  // a setup with many balls opens with the struck ball's paths and times

    void onTimeChanged(double seconds);
    void onBallSelected(int index);
    void onEventSelected(int index);
    void selectEventAtCurrentTime();
    void refreshInspector();

    Document* document_;
    Playback* playback_;
    Selection* selection_;
    DockLayout* layout_;
    FirstStartTip* tip_ = nullptr;
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
    QMenu* fileMenu_ = nullptr;
    QMenu* exportMenu_ = nullptr;
    QAction* exportSeparator_ = nullptr;  // before Quit: the Export submenu goes in front of it
    QMenu* editMenu_ = nullptr;
    QMenu* viewMenu_ = nullptr;
    QMenu* panelsMenu_ = nullptr;
    QMenu* analysisMenu_ = nullptr;
    QMenu* playbackMenu_ = nullptr;
    QMenu* helpMenu_ = nullptr;
    std::array<QAction*, kOverlayCount> overlayActions_{};
    QLabel* summaryLabel_ = nullptr;
    QLabel* fpsLabel_ = nullptr;
    SimulationOverlay* overlay_ = nullptr;  // "Simulating…" with Cancel over the view (issue 39)
    QAction* cancelAction_ = nullptr;       // Playback > Cancel Simulation (Esc)
    bool autoScoped_ = false;  // the view's Paths Of / Labels Of were set by scopeForBusyShot
};

}  // namespace cuelab
