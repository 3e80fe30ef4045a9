#include "MainWindow.h"
#include "MainWindowPrivate.h"

#include "DockLayout.h"
#include "ElidingStatusBar.h"
#include "Features.h"
#include "FirstStartTip.h"
#include "InputGuard.h"
#include "RefusalNote.h"
#include "RecentFiles.h"

#include "editor/BallsPanel.h"
#include "editor/Document.h"
#include "editor/EventsPanel.h"
#include "editor/ResultFeed.h"
#include "editor/InspectorPanel.h"
#include "editor/PhysicsPanel.h"
#include "editor/Playback.h"
#include "editor/Quantities.h"
#include "editor/Selection.h"
#include "editor/RunState.h"
#include "editor/ShotPanel.h"
#include "editor/SimulationOverlay.h"
#include "editor/TransportBar.h"
#include "view/TableView.h"

#include "SetupFile.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QGuiApplication>
#include <QScreen>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>
#include <QUndoStack>
#include <QVBoxLayout>

namespace cuelab {

namespace {

bool isSetupFile(const QUrl& url) { return url.isLocalFile() && url.toLocalFile().endsWith(QLatin1String(".json"), Qt::CaseInsensitive); }

}  // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), document_(new Document(this)), playback_(new Playback(this)), selection_(new Selection(this)),
      layout_(new DockLayout(this))
{
    setObjectName(QStringLiteral("MainWindow"));
    // First, so that it sees every editor polished: the wheel only for focused editors; Ctrl+Z
    // after Enter undoes the document's edit.
    new InputGuard(this);
    setAcceptDrops(true);
    setDockNestingEnabled(true);

    view_ = new TableView(this);
    view_->setObjectName(QStringLiteral("tableView"));
    view_->setMinimumSize(300, 200);  // an 800-pixel window keeps both 240-pixel side docks
    view_->setFocusPolicy(Qt::ClickFocus);
    transport_ = new TransportBar(playback_, this);
    transport_->setObjectName(QStringLiteral("transport"));
    auto* centre = new QWidget(this);
    auto* centreLayout = new QVBoxLayout(centre);
    centreLayout->setContentsMargins(0, 0, 0, 0);
    centreLayout->setSpacing(0);
    centreLayout->addWidget(view_, 1);
    centreLayout->addWidget(transport_);
    setCentralWidget(centre);
    // The first-start tip lies over the top of the table view (where the view has room to spare
    // above a table fitted to its width) instead of taking the view's height.
    tip_ = new FirstStartTip(view_);
    // The side columns run the window's full height; a bottom dock (Plots, Compare) sits under the
    // table view only.
    setCorner(Qt::TopLeftCorner, Qt::LeftDockWidgetArea);
    setCorner(Qt::BottomLeftCorner, Qt::LeftDockWidgetArea);
    setCorner(Qt::TopRightCorner, Qt::RightDockWidgetArea);
    setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);

    createDocks();
    createStatusBar();
    createMenus();
    installFeatures(*this);
    for (QMenu* m : findChildren<QMenu*>()) m->setToolTipsVisible(true);
    analysisMenu_->menuAction()->setVisible(!analysisMenu_->isEmpty());
    // The first start's arrangement (Arrangements.h), which View > Layouts > Reset Layout returns to.
    layout_->arrange(Arrangement::Default);

    connect(document_, &Document::resultChanged, this, &MainWindow::onResultChanged);
    ResultFeed::follow(document_, this, [this] { refreshResultLists(); });
    // The drag keeps clear of the setup's balls, not of the last result's (which lags behind while
    // a re-simulation runs); a dropped ball moved to a free spot says so.
    view_->setSetupBalls(document_->setup().balls);
    connect(document_, &Document::setupChanged, this, [this] { view_->setSetupBalls(document_->setup().balls); });
    connect(view_, &TableView::ballPlacementAdjusted, this, [this](int, const QString& message) {
        statusBar()->showMessage(message, window::kStatusMessageMs);
    });
    // An edit in the view refused while it is locked (a lesson's open question): why, in the status bar.
    connect(view_, &TableView::editRefused, this, [this](const QString& why) { statusBar()->showMessage(why, window::kStatusMessageMs); });
    // Dragging a velocity arrow at t = 0 sets that ball's initial velocity: features/EditorFeature.cpp.
    connect(document_, &Document::setupChanged, this, [this] {
        // The shot's cue and aim line follow the setup at once; the balls follow with the result.
        ViewScene scene = view_->scene();
        scene.shot = document_->setup().shot;
        view_->setScene(scene);
    });
    connect(document_, &Document::modifiedChanged, this, &QWidget::setWindowModified);
    connect(document_, &Document::filePathChanged, this, &MainWindow::updateTitle);
    connect(document_, &Document::documentReplaced, this, [this] {
        selection_->clear();
        playback_->toStart();
        updateTitle();
        scopeForBusyShot();
    });
    // A refused edit: said beside the field that made it, and in the status bar.
    auto* refusal = new RefusalNote(this);
    connect(document_, &Document::editRefused, this, [this, refusal](const QString& message) {
        statusBar()->showMessage(tr("Not applied: %1").arg(message), window::kStatusMessageMs);
        refusal->say(tr("Not applied: %1").arg(message));
    });
    connect(document_, &Document::simulationFailed, this, [this](const QString& message) {
        statusBar()->showMessage(message, window::kStatusMessageMs);
    });
    // A run that takes a while is shown as it goes, over the view, with its Cancel (issue 39).
    overlay_ = new SimulationOverlay(document_, view_);
    connect(document_, &Document::simulatingChanged, this, [this](bool running) { cancelAction_->setEnabled(running); });
    connect(playback_, &Playback::timeChanged, this, &MainWindow::onTimeChanged);

    connect(selection_, &Selection::ballChanged, this, &MainWindow::onBallSelected);
    connect(selection_, &Selection::eventChanged, this, &MainWindow::onEventSelected);
    connect(selection_, &Selection::subjectChanged, this, &MainWindow::refreshInspector);
    connect(view_, &TableView::ballClicked, selection_, &Selection::selectBall);
    connect(view_, &TableView::ballDragged, this, [this](int index, double x, double y) {
        document_->moveBall(index, Vec2(x, y));
    });
    connect(view_, &TableView::ballDragFinished, document_, &Document::endMerge);
    connect(view_, &TableView::framesPerSecond, this, [this](double fps) {
        // An idle view draws nothing: no rate to show then.
        fpsLabel_->setText(fps >= 1.0 ? tr("%1 fps").arg(std::lround(fps)) : QString());
    });
    connect(balls_, &BallsPanel::ballSelected, selection_, &Selection::selectBall);
    connect(events_, &EventsPanel::eventSelected, selection_, &Selection::selectEvent);
    // Stepping from event to event selects the event it lands on (the list and the inspector follow).
    for (QAction* step : {transport_->previousEventAction(), transport_->nextEventAction()})
        connect(step, &QAction::triggered, this, &MainWindow::selectEventAtCurrentTime);

    // The first run takes the screen's available area (showOnStart maximises it on a screen up to
    // 1920 px wide); later runs restore what the user left (readSettings).
    if (QScreen* screen = QGuiApplication::primaryScreen()) setGeometry(firstStartGeometry(screen->availableGeometry()));
    readSettings();
    updateTitle();
    cancelAction_->setEnabled(document_->isSimulating());
}

MainWindow::~MainWindow() = default;

void MainWindow::createDocks()
{
    balls_ = new BallsPanel(document_, this);
    physics_ = new PhysicsPanel(document_, this);
    shot_ = new ShotPanel(document_, this);
    events_ = new EventsPanel(this);
    inspector_ = new InspectorPanel(this);

    // Where each goes, with the features' docks, is the default arrangement's (Arrangements.h).
    addPanel(balls_, tr("Balls"), QStringLiteral("BallsDock"), {Qt::LeftDockWidgetArea});
    addPanel(shot_, tr("Shot"), QStringLiteral("ShotDock"), {Qt::LeftDockWidgetArea, QStringLiteral("BallsDock")});
    addPanel(physics_, tr("Physics"), QStringLiteral("PhysicsDock"), {Qt::LeftDockWidgetArea, QStringLiteral("BallsDock")});
    addPanel(events_, tr("Events"), QStringLiteral("EventsDock"), {Qt::RightDockWidgetArea});
    addPanel(inspector_, tr("Inspector"), QStringLiteral("InspectorDock"), {Qt::RightDockWidgetArea, QStringLiteral("EventsDock")});
}


QDockWidget* MainWindow::addPanel(QWidget* content, const QString& title, const QString& objectName,
                                  const PanelPlacement& placement)
{
    auto* d = new QDockWidget(title, this);
    d->setObjectName(objectName);  // saveState/restoreState find docks by name
    auto* scroller = new QScrollArea(d);
    scroller->setWidget(content);
    scroller->setWidgetResizable(true);
    scroller->setFrameShape(QFrame::NoFrame);
    d->setWidget(scroller);
    if (placement.area == Qt::TopDockWidgetArea || placement.area == Qt::BottomDockWidgetArea)
        d->setMinimumHeight(DockLayout::kMinimumDockHeight);
    else
        d->setMinimumWidth(DockLayout::kMinimumDockWidth);
    addDockWidget(placement.area, d);
    layout_->adopt(d);
    if (!placement.tabifyWith.isEmpty()) {
        for (QDockWidget* other : std::as_const(docks_))
            if (other->objectName() == placement.tabifyWith) tabifyDockWidget(other, d);
    }
    if (!placement.visible) d->hide();
    docks_ << d;
    if (panelsMenu_) panelsMenu_->addAction(d->toggleViewAction());
    return d;
}

void MainWindow::resetLayout()
{
    layout_->reset();
}

void MainWindow::arrange(Arrangement arrangement)
{
    layout_->arrange(arrangement);
}

bool MainWindow::maximisesOnFirstStart(const QRect& available) { return available.width() <= kMaximiseUpToWidth; }

QRect MainWindow::firstStartGeometry(const QRect& available)
{
    // Up to 1920 px wide the whole available area (maximised); beyond, about 80 % of it, centred:
    // a 2560x1440 screen gives 2048x1152, as wide as a 1920 screen's window and a little more.
    if (maximisesOnFirstStart(available)) return available;
    const QSize size(available.width() * 4 / 5, available.height() * 4 / 5);
    QRect r(QPoint(0, 0), size);
    r.moveCenter(available.center());
    return r;
}

void MainWindow::showOnStart()
{
    const bool firstStart = !QSettings().contains(QStringLiteral("window/geometry"));
    QScreen* screen = QGuiApplication::primaryScreen();
    if (firstStart && screen && maximisesOnFirstStart(screen->availableGeometry())) showMaximized();
    else show();
}

QMenu* MainWindow::menu(WindowMenu which)
{
    switch (which) {
    case WindowMenu::File: return fileMenu_;
    case WindowMenu::Export:
        if (!exportMenu_) {
            exportMenu_ = new QMenu(tr("&Export"), fileMenu_);
            exportMenu_->setToolTipsVisible(true);
            fileMenu_->insertMenu(exportSeparator_, exportMenu_);
        }
        return exportMenu_;
    case WindowMenu::Edit: return editMenu_;
    case WindowMenu::View: return viewMenu_;
    case WindowMenu::Analysis:
        analysisMenu_->menuAction()->setVisible(true);
        return analysisMenu_;
    case WindowMenu::Playback: return playbackMenu_;
    case WindowMenu::Help: return helpMenu_;
    }
    return nullptr;
}

void MainWindow::createStatusBar()
{
    setStatusBar(new window::ElidingStatusBar(this));
    summaryLabel_ = new QLabel(this);
    summaryLabel_->setObjectName(QStringLiteral("summaryStatus"));
    fpsLabel_ = new QLabel(this);
    fpsLabel_->setToolTip(tr("Frames per second the table view draws"));
    statusBar()->addPermanentWidget(summaryLabel_);
    statusBar()->addPermanentWidget(fpsLabel_);
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (!maybeSave()) {
        event->ignore();
        return;
    }
    playback_->pause();
    writeSettings();
    event->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event)
{
    const QList<QUrl> urls = event->mimeData()->urls();
    if (urls.size() == 1 && isSetupFile(urls.front())) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event)
{
    const QList<QUrl> urls = event->mimeData()->urls();
    if (urls.size() != 1 || !isSetupFile(urls.front())) return;
    event->acceptProposedAction();
    openFile(urls.front().toLocalFile());
}

void MainWindow::onResultChanged()
{
    const auto result = document_->result();
    if (!result) return;
    std::vector<double> times;
    times.reserve(result->events.size());
    for (const Event& e : result->events) times.push_back(e.time);
    playback_->setTimeline(result->endTime, times, document_->setup().simulation.frameDt);
    transport_->refreshTimeline();
    view_->setScene(ViewScene{result, document_->setup().shot});
    view_->setTime(playback_->time());
    if (selection_->event() >= static_cast<int>(result->events.size())) selection_->selectEvent(-1);
    if (selection_->ball() >= static_cast<int>(result->balls.size())) selection_->selectBall(-1);
    refreshInspector();
}

// The Events list and the summary beside it: every result, a few times a second during a drag
// (ResultFeed), while the view above shows each one.
void MainWindow::refreshResultLists()
{
    const auto result = document_->result();
    if (!result) return;
    events_->setResult(result);
    events_->setTime(playback_->time());
    events_->setSelectedEvent(selection_->event());

    QString summary = tr("%n event(s), at rest at %1", nullptr, static_cast<int>(result->events.size()))
                          .arg(formatQuantity(result->endTime, QStringLiteral("s"), 3));
    if (result->status == SimulationStatus::ReachedUntil) summary = tr("%n event(s), stopped at the time limit", nullptr, static_cast<int>(result->events.size()));
    if (!result->finished()) summary = RunState::unfinishedNote(*result);
    // A lesson's question waits (Document::setHorizon): the count is the shown part's (the outcome
    // line beside it says up to when).
    if (document_->isWithholding())
        summary = tr("%n event(s) before the question", nullptr, static_cast<int>(result->events.size()));
    summaryLabel_->setToolTip(result->finished() ? QString() : QString::fromStdString(result->error));
    summaryLabel_->setText(summary);
}

void MainWindow::scopeForBusyShot()
{
    const Setup& setup = document_->setup();
    int struck = -1;
    if (setup.shot)
        for (std::size_t i = 0; i < setup.balls.size(); ++i)
            if (setup.balls[i].id == setup.shot->ball) struck = static_cast<int>(i);
    if (setup.balls.size() > kBusyShotBalls && struck >= 0) {
        if (view_->pathScope() == BallScope::All && view_->labelScope() == BallScope::All) autoScoped_ = true;
        if (!autoScoped_) return;  // the user chose the scopes: keep them
        selection_->selectBall(struck);
        view_->setPathScope(BallScope::Selected);
        view_->setLabelScope(BallScope::Selected);
        statusBar()->showMessage(tr("A busy shot: the paths and event times of the selected ball %1 only (View › Paths Of, Labels Of)")
                                     .arg(QString::fromStdString(setup.shot->ball)),
                                 window::kStatusMessageMs);
    } else if (autoScoped_) {
        // Back to every ball for a shot with few balls, as before the busy one.
        autoScoped_ = false;
        view_->setPathScope(BallScope::All);
        view_->setLabelScope(BallScope::All);
    }
}

void MainWindow::onTimeChanged(double seconds)
{
    view_->setTime(seconds);
    balls_->setTime(seconds);
    events_->setTime(seconds);
    if (selection_->subject() == Selection::Subject::Ball) refreshInspector();
}

void MainWindow::onBallSelected(int index)
{
    view_->setSelectedBall(index);
    balls_->setSelectedBall(index);
    if (index >= 0) {
        events_->setSelectedEvent(-1);
        view_->setHighlightedEvent(-1);
    }
    refreshInspector();
}

void MainWindow::onEventSelected(int index)
{
    const auto result = document_->result();
    if (index >= 0 && (!result || index >= static_cast<int>(result->events.size()))) return selection_->selectEvent(-1);
    events_->setSelectedEvent(index);
    view_->setHighlightedEvent(index);
    if (index >= 0) {
        playback_->pause();
        playback_->setTime(result->events[static_cast<std::size_t>(index)].time);
    }
    refreshInspector();
}

void MainWindow::selectEventAtCurrentTime()
{
    const auto result = document_->result();
    if (!result) return;
    const double t = playback_->time();
    for (std::size_t i = 0; i < result->events.size(); ++i) {
        if (result->events[i].time == t) return selection_->selectEvent(static_cast<int>(i));  // the first of a tie
    }
    selection_->selectEvent(-1);  // stepped to the start or the end
}

void MainWindow::refreshInspector()
{
    const auto result = document_->result();
    if (!result || selection_->subject() == Selection::Subject::None) return inspector_->showNothing();
    if (selection_->subject() == Selection::Subject::Ball) inspector_->showBall(*result, selection_->ball(), playback_->time());
    else inspector_->showEventDetails(*result, selection_->event());
}

}  // namespace cuelab
