#include "MainWindow.h"

#include "RecentFiles.h"

#include "editor/BallsPanel.h"
#include "editor/Document.h"
#include "editor/EventsPanel.h"
#include "editor/InspectorPanel.h"
#include "editor/PhysicsPanel.h"
#include "editor/Playback.h"
#include "editor/Quantities.h"
#include "editor/ShotPanel.h"
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
#include <QProgressBar>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>
#include <QUndoStack>
#include <QVBoxLayout>

namespace cuelab {

namespace {

constexpr int kStatusMessageMs = 6000;
const QString kFileFilter = QObject::tr("CueLab setups (*.json);;All files (*)");

QString overlayName(Overlay overlay)
{
    switch (overlay) {
    case Overlay::Velocities: return QObject::tr("&Velocities");
    case Overlay::Spin: return QObject::tr("&Spin");
    case Overlay::Trails: return QObject::tr("&Trails");
    case Overlay::FuturePaths: return QObject::tr("&Future Paths");
    case Overlay::EventMarkers: return QObject::tr("&Event Markers");
    case Overlay::GhostBalls: return QObject::tr("&Ghost Balls");
    case Overlay::CueAndAim: return QObject::tr("&Cue and Aim Line");
    }
    return {};
}

QString overlayKey(Overlay overlay) { return QStringLiteral("overlays/%1").arg(static_cast<int>(overlay)); }

bool isSetupFile(const QUrl& url) { return url.isLocalFile() && url.toLocalFile().endsWith(QLatin1String(".json"), Qt::CaseInsensitive); }

}  // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), document_(new Document(this)), playback_(new Playback(this))
{
    setObjectName(QStringLiteral("MainWindow"));
    setAcceptDrops(true);
    setDockNestingEnabled(true);

    view_ = new TableView(this);
    view_->setObjectName(QStringLiteral("tableView"));
    view_->setMinimumSize(320, 200);
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

    createDocks();
    createMenus();
    createStatusBar();

    connect(document_, &Document::resultChanged, this, &MainWindow::onResultChanged);
    connect(document_, &Document::setupChanged, this, [this] {
        // The shot's cue and aim line follow the setup at once; the balls follow with the result.
        ViewScene scene = view_->scene();
        scene.shot = document_->setup().shot;
        view_->setScene(scene);
    });
    connect(document_, &Document::modifiedChanged, this, &QWidget::setWindowModified);
    connect(document_, &Document::filePathChanged, this, &MainWindow::updateTitle);
    connect(document_, &Document::documentReplaced, this, [this] {
        selectEvent(-1);
        selectBall(-1);
        playback_->toStart();
        updateTitle();
    });
    connect(document_, &Document::editRefused, this, [this](const QString& message) {
        statusBar()->showMessage(tr("Not applied: %1").arg(message), kStatusMessageMs);
    });
    connect(document_, &Document::simulationFailed, this, [this](const QString& message) {
        statusBar()->showMessage(message, kStatusMessageMs);
    });
    connect(document_, &Document::simulatingChanged, busy_, &QWidget::setVisible);
    connect(playback_, &Playback::timeChanged, this, &MainWindow::onTimeChanged);

    connect(view_, &TableView::ballClicked, this, &MainWindow::selectBall);
    connect(view_, &TableView::ballDragged, this, [this](int index, double x, double y) {
        document_->moveBall(index, Vec2(x, y));
    });
    connect(view_, &TableView::ballDragFinished, document_, &Document::endMerge);
    connect(view_, &TableView::framesPerSecond, this, [this](double fps) {
        // An idle view draws nothing: no rate to show then.
        fpsLabel_->setText(fps >= 1.0 ? tr("%1 fps").arg(std::lround(fps)) : QString());
    });
    connect(balls_, &BallsPanel::ballSelected, this, &MainWindow::selectBall);
    connect(events_, &EventsPanel::eventSelected, this, &MainWindow::selectEvent);
    // Stepping from event to event selects the event it lands on (the list and the inspector follow).
    for (QAction* step : {transport_->previousEventAction(), transport_->nextEventAction()})
        connect(step, &QAction::triggered, this, &MainWindow::selectEventAtCurrentTime);

    // The first run fills most of the screen; later runs restore what the user left (readSettings).
    const QRect screen = QGuiApplication::primaryScreen()->availableGeometry();
    resize(std::min(1600, screen.width() * 9 / 10), std::min(1000, screen.height() * 9 / 10));
    readSettings();
    updateTitle();
    busy_->setVisible(document_->isSimulating());
}

MainWindow::~MainWindow() = default;

void MainWindow::createDocks()
{
    balls_ = new BallsPanel(document_, this);
    physics_ = new PhysicsPanel(document_, this);
    shot_ = new ShotPanel(document_, this);
    events_ = new EventsPanel(this);
    inspector_ = new InspectorPanel(this);

    const auto dock = [this](QWidget* content, const QString& title, const QString& name, Qt::DockWidgetArea area,
                             bool scroll) {
        auto* d = new QDockWidget(title, this);
        d->setObjectName(name);  // saveState/restoreState find docks by name
        if (scroll) {
            auto* scroller = new QScrollArea(d);
            scroller->setWidget(content);
            scroller->setWidgetResizable(true);
            scroller->setFrameShape(QFrame::NoFrame);
            d->setWidget(scroller);
        } else {
            d->setWidget(content);
        }
        addDockWidget(area, d);
        docks_ << d;
        return d;
    };
    QDockWidget* ballsDock = dock(balls_, tr("Balls"), QStringLiteral("BallsDock"), Qt::LeftDockWidgetArea, false);
    QDockWidget* shotDock = dock(shot_, tr("Shot"), QStringLiteral("ShotDock"), Qt::LeftDockWidgetArea, true);
    QDockWidget* physicsDock = dock(physics_, tr("Physics"), QStringLiteral("PhysicsDock"), Qt::LeftDockWidgetArea, true);
    QDockWidget* eventsDock = dock(events_, tr("Events"), QStringLiteral("EventsDock"), Qt::RightDockWidgetArea, false);
    QDockWidget* inspectorDock = dock(inspector_, tr("Inspector"), QStringLiteral("InspectorDock"), Qt::RightDockWidgetArea, false);
    tabifyDockWidget(shotDock, physicsDock);
    shotDock->raise();
    splitDockWidget(eventsDock, inspectorDock, Qt::Vertical);
    resizeDocks({ballsDock, eventsDock}, {430, 470}, Qt::Horizontal);
    resizeDocks({ballsDock, shotDock}, {260, 520}, Qt::Vertical);
    resizeDocks({eventsDock, inspectorDock}, {340, 460}, Qt::Vertical);
}

void MainWindow::createMenus()
{
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QAction* newAction = file->addAction(QIcon::fromTheme(QStringLiteral("document-new")), tr("&New"), this, &MainWindow::newDocument);
    newAction->setShortcut(QKeySequence::New);
    newAction->setToolTip(tr("A new setup: a 9-ft table with a cue ball and one object ball"));
    QAction* openAction = file->addAction(QIcon::fromTheme(QStringLiteral("document-open")), tr("&Open…"), this, &MainWindow::open);
    openAction->setShortcut(QKeySequence::Open);
    recentMenu_ = new RecentFiles(tr("Open &Recent"), this);
    file->addMenu(recentMenu_);
    connect(recentMenu_, &RecentFiles::openRequested, this, &MainWindow::openFile);
    examplesMenu_ = file->addMenu(tr("&Examples"));
    for (const QString& path : bundledExamples()) {
        QString title = QFileInfo(path).completeBaseName();
        QFile f(path);
        QString ignored;
        if (f.open(QIODevice::ReadOnly))
            if (const auto setup = io::parseSetup(f.readAll(), title, &ignored); setup && !setup->name.empty())
                title = QString::fromStdString(setup->name);
        QAction* a = examplesMenu_->addAction(title, this, [this, path] { openExample(path); });
        a->setToolTip(tr("Open the bundled example %1 as a new, untitled setup").arg(QFileInfo(path).fileName()));
    }
    examplesMenu_->setEnabled(!examplesMenu_->isEmpty());
    file->addSeparator();
    QAction* saveAction = file->addAction(QIcon::fromTheme(QStringLiteral("document-save")), tr("&Save"), this, &MainWindow::save);
    saveAction->setShortcut(QKeySequence::Save);
    QAction* saveAsAction = file->addAction(tr("Save &As…"), this, &MainWindow::saveAs);
    saveAsAction->setShortcut(QKeySequence::SaveAs);
    file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = document_->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = document_->undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setShortcut(QKeySequence::Redo);
    edit->addAction(undo);
    edit->addAction(redo);
    edit->addSeparator();
    balls_->addBallAction()->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_B));
    balls_->removeBallAction()->setShortcut(QKeySequence::Delete);
    balls_->duplicateBallAction()->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_D));
    edit->addAction(balls_->addBallAction());
    edit->addAction(balls_->duplicateBallAction());
    edit->addAction(balls_->removeBallAction());
    edit->addMenu(balls_->rackMenu());
    edit->addSeparator();
    edit->addAction(tr("Reset &Physics to Defaults"), document_, &Document::resetPhysics);

    QMenu* view = menuBar()->addMenu(tr("&View"));
    QMenu* panels = view->addMenu(tr("&Panels"));
    for (QDockWidget* d : docks_) panels->addAction(d->toggleViewAction());
    QMenu* overlays = view->addMenu(tr("&Overlays"));
    for (int i = 0; i < kOverlayCount; ++i) {
        const auto overlay = static_cast<Overlay>(i);
        QAction* a = overlays->addAction(overlayName(overlay));
        a->setCheckable(true);
        a->setChecked(view_->overlayVisible(overlay));
        connect(a, &QAction::toggled, this, [this, overlay](bool on) { view_->setOverlayVisible(overlay, on); });
        overlayActions_[static_cast<std::size_t>(i)] = a;
    }
    QMenu* camera = view->addMenu(tr("&Camera"));
    const std::pair<CameraPreset, QString> presets[] = {{CameraPreset::Top, tr("&Top")},
                                                        {CameraPreset::Player, tr("&Player")},
                                                        {CameraPreset::Side, tr("&Side")}};
    int key = Qt::Key_1;
    for (const auto& [preset, name] : presets) {
        QAction* a = camera->addAction(name, this, [this, p = preset] { view_->setCameraPreset(p); });
        a->setShortcut(QKeySequence(Qt::CTRL | key++));
    }
    view->addSeparator();
    QAction* fullScreen = view->addAction(tr("&Full Screen"));
    fullScreen->setCheckable(true);
    fullScreen->setShortcut(QKeySequence::FullScreen);
    connect(fullScreen, &QAction::toggled, this, [this](bool on) {
        setWindowState(on ? (windowState() | Qt::WindowFullScreen) : (windowState() & ~Qt::WindowFullScreen));
    });

    QMenu* playbackMenu = menuBar()->addMenu(tr("&Playback"));
    playbackMenu->addActions(transport_->transportActions());

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&About CueLab"), this, &MainWindow::about);
    help->addAction(tr("About &Qt"), qApp, &QApplication::aboutQt);

    for (QMenu* m : findChildren<QMenu*>()) m->setToolTipsVisible(true);
}

void MainWindow::createStatusBar()
{
    summaryLabel_ = new QLabel(this);
    fpsLabel_ = new QLabel(this);
    fpsLabel_->setToolTip(tr("Frames per second the table view draws"));
    busy_ = new QProgressBar(this);
    busy_->setRange(0, 0);  // busy indicator: the simulator reports no fraction
    busy_->setMaximumWidth(120);
    busy_->setMaximumHeight(14);
    busy_->setToolTip(tr("Simulating the edited setup"));
    busy_->setTextVisible(false);
    statusBar()->addPermanentWidget(busy_);
    statusBar()->addPermanentWidget(summaryLabel_);
    statusBar()->addPermanentWidget(fpsLabel_);
}

QStringList MainWindow::bundledExamples()
{
    QStringList paths;
    const QDir dir(QStringLiteral(":/examples"));
    for (const QString& name : dir.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name)) paths << dir.filePath(name);
    return paths;
}

void MainWindow::readSettings()
{
    QSettings settings;
    if (const QByteArray geometry = settings.value(QStringLiteral("window/geometry")).toByteArray(); !geometry.isEmpty())
        restoreGeometry(geometry);
    if (const QByteArray state = settings.value(QStringLiteral("window/state")).toByteArray(); !state.isEmpty())
        restoreState(state);
    for (int i = 0; i < kOverlayCount; ++i) {
        const QVariant on = settings.value(overlayKey(static_cast<Overlay>(i)));
        if (on.isValid()) overlayActions_[static_cast<std::size_t>(i)]->setChecked(on.toBool());
    }
}

void MainWindow::writeSettings() const
{
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("window/state"), saveState());
    for (int i = 0; i < kOverlayCount; ++i)
        settings.setValue(overlayKey(static_cast<Overlay>(i)), overlayActions_[static_cast<std::size_t>(i)]->isChecked());
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

bool MainWindow::maybeSave()
{
    if (!document_->isModified()) return true;
    const QMessageBox::StandardButton answer = QMessageBox::warning(
        this, tr("Unsaved Changes"), tr("%1 has unsaved changes. Save them first?").arg(document_->displayName()),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save) return save();
    return answer == QMessageBox::Discard;
}

void MainWindow::newDocument()
{
    if (maybeSave()) document_->newDocument();
}

void MainWindow::open()
{
    if (!maybeSave()) return;
    QSettings settings;
    const QString dir = settings.value(QStringLiteral("files/lastDir"), QDir::homePath()).toString();
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Setup"), dir, kFileFilter);
    if (!path.isEmpty()) openFile(path);
}

bool MainWindow::openFile(const QString& path)
{
    if (!maybeSave()) return false;
    QString error;
    if (!document_->load(path, &error)) {
        showError(tr("Cannot Open Setup"), error);
        return false;
    }
    recentMenu_->add(document_->filePath());
    QSettings().setValue(QStringLiteral("files/lastDir"), QFileInfo(path).absolutePath());
    statusBar()->showMessage(tr("Opened %1").arg(QDir::toNativeSeparators(document_->filePath())), kStatusMessageMs);
    return true;
}

bool MainWindow::openExample(const QString& resourcePath)
{
    if (!maybeSave()) return false;
    QFile file(resourcePath);
    QString error;
    if (!file.open(QIODevice::ReadOnly)) {
        showError(tr("Cannot Open Example"), tr("%1: %2").arg(resourcePath, file.errorString()));
        return false;
    }
    QString title = QFileInfo(resourcePath).fileName();
    if (!document_->loadData(file.readAll(), title, &error)) {
        showError(tr("Cannot Open Example"), error);
        return false;
    }
    statusBar()->showMessage(tr("Example %1: save it to keep your changes").arg(title), kStatusMessageMs);
    return true;
}

bool MainWindow::save()
{
    return document_->filePath().isEmpty() ? saveAs() : saveFile(document_->filePath());
}

bool MainWindow::saveAs()
{
    QSettings settings;
    QString suggestion = document_->filePath();
    if (suggestion.isEmpty()) {
        const QString dir = settings.value(QStringLiteral("files/lastDir"), QDir::homePath()).toString();
        QString base = QFileInfo(document_->displayName()).completeBaseName();
        suggestion = QDir(dir).filePath((base.isEmpty() ? tr("untitled") : base) + QStringLiteral(".json"));
    }
    QString path = QFileDialog::getSaveFileName(this, tr("Save Setup As"), suggestion, kFileFilter);
    if (path.isEmpty()) return false;
    if (QFileInfo(path).suffix().isEmpty()) path += QStringLiteral(".json");
    return saveFile(path);
}

bool MainWindow::saveFile(const QString& path)
{
    QString error;
    if (!document_->save(path, &error)) {
        showError(tr("Cannot Save Setup"), error);
        return false;
    }
    recentMenu_->add(document_->filePath());
    QSettings().setValue(QStringLiteral("files/lastDir"), QFileInfo(path).absolutePath());
    statusBar()->showMessage(tr("Saved %1").arg(QDir::toNativeSeparators(document_->filePath())), kStatusMessageMs);
    return true;
}

void MainWindow::updateTitle()
{
    setWindowTitle(tr("%1[*] — CueLab").arg(document_->displayName()));
    setWindowModified(document_->isModified());
    setWindowFilePath(document_->filePath());
}

void MainWindow::showError(const QString& title, const QString& message)
{
    statusBar()->showMessage(message, kStatusMessageMs);
    QMessageBox::warning(this, title, message);
}

void MainWindow::about()
{
    QMessageBox::about(this, tr("About CueLab"),
                       tr("<h3>CueLab %1</h3><p>An exact, event-based billiards simulator and shot "
                          "editor: every time of impact is a root of a polynomial.</p>")
                           .arg(QApplication::applicationVersion()));
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
    events_->setResult(result);
    events_->setTime(playback_->time());
    if (selectedEvent_ >= static_cast<int>(result->events.size())) selectEvent(-1);
    else events_->setSelectedEvent(selectedEvent_);
    if (selectedBall_ >= static_cast<int>(result->balls.size())) selectBall(-1);
    refreshInspector();

    QString summary = tr("%n event(s), at rest at %1", nullptr, static_cast<int>(result->events.size()))
                          .arg(formatQuantity(result->endTime, QStringLiteral("s"), 3));
    if (result->status == SimulationStatus::ReachedUntil) summary = tr("%n event(s), stopped at the time limit", nullptr, static_cast<int>(result->events.size()));
    if (result->status == SimulationStatus::EventLimit) summary = tr("Cut short: %1").arg(QString::fromStdString(result->error));
    summaryLabel_->setText(summary);
}

void MainWindow::onTimeChanged(double seconds)
{
    view_->setTime(seconds);
    balls_->setTime(seconds);
    events_->setTime(seconds);
    if (inspectorSubject_ == InspectorSubject::Ball) refreshInspector();
}

void MainWindow::selectBall(int index)
{
    selectedBall_ = index;
    view_->setSelectedBall(index);
    balls_->setSelectedBall(index);
    if (index >= 0) {
        inspectorSubject_ = InspectorSubject::Ball;
        selectedEvent_ = -1;
        events_->setSelectedEvent(-1);
        view_->setHighlightedEvent(-1);
    } else if (inspectorSubject_ == InspectorSubject::Ball) {
        inspectorSubject_ = InspectorSubject::None;
    }
    refreshInspector();
}

void MainWindow::selectEvent(int index)
{
    const auto result = document_->result();
    if (!result || index < 0 || index >= static_cast<int>(result->events.size())) index = -1;
    selectedEvent_ = index;
    events_->setSelectedEvent(index);
    view_->setHighlightedEvent(index);
    if (index >= 0) {
        inspectorSubject_ = InspectorSubject::Event;
        playback_->pause();
        playback_->setTime(result->events[static_cast<std::size_t>(index)].time);
    } else if (inspectorSubject_ == InspectorSubject::Event) {
        inspectorSubject_ = InspectorSubject::None;
    }
    refreshInspector();
}

void MainWindow::selectEventAtCurrentTime()
{
    const auto result = document_->result();
    if (!result) return;
    const double t = playback_->time();
    for (std::size_t i = 0; i < result->events.size(); ++i) {
        if (result->events[i].time == t) return selectEvent(static_cast<int>(i));  // the first of a tie
    }
    selectEvent(-1);  // stepped to the start or the end
}

void MainWindow::refreshInspector()
{
    const auto result = document_->result();
    if (!result || inspectorSubject_ == InspectorSubject::None) return inspector_->showNothing();
    if (inspectorSubject_ == InspectorSubject::Ball) inspector_->showBall(*result, selectedBall_, playback_->time());
    else inspector_->showEventDetails(*result, selectedEvent_);
}

}  // namespace cuelab
