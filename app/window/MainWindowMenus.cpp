// MainWindow's menus and their actions (see MainWindow.h for how the class is split).

#include "MainWindow.h"
#include "MainWindowPrivate.h"
#include "RecentFiles.h"
#include "FirstStartTip.h"
#include "ShortcutsDialog.h"
#include "UserGuide.h"

#include "editor/BallsPanel.h"
#include "editor/Document.h"
#include "editor/TransportBar.h"
#include "i18n/ExampleTexts.h"
#include "view/TableView.h"

#include "SetupFile.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QDockWidget>
#include <QFile>
#include <QFileInfo>
#include <QMenuBar>
#include <QUndoStack>

namespace cuelab {

namespace {

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

// The platform's keys for a standard action, and the usual one as well when the platform has none or
// another: without a desktop theme Qt knows no Save As, Full Screen or Redo keys on Linux.
QList<QKeySequence> standardKeys(QKeySequence::StandardKey key, const QKeySequence& usual)
{
    QList<QKeySequence> keys = QKeySequence::keyBindings(key);
    if (!keys.contains(usual)) keys.prepend(usual);
    return keys;
}

}  // namespace

void MainWindow::createMenus()
{
    QMenu* file = fileMenu_ = menuBar()->addMenu(tr("&File"));
    QAction* newAction = file->addAction(QIcon::fromTheme(QStringLiteral("document-new")), tr("&New"), this, &MainWindow::newDocument);
    newAction->setShortcuts(standardKeys(QKeySequence::New, QKeySequence(Qt::CTRL | Qt::Key_N)));
    newAction->setToolTip(tr("A new setup: a 9-ft table with a cue ball and one object ball"));
    QAction* openAction = file->addAction(QIcon::fromTheme(QStringLiteral("document-open")), tr("&Open…"), this, &MainWindow::open);
    openAction->setShortcuts(standardKeys(QKeySequence::Open, QKeySequence(Qt::CTRL | Qt::Key_O)));
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
                title = translatedExampleText(setup->name);
        QAction* a = examplesMenu_->addAction(title, this, [this, path] { openExample(path); });
        a->setToolTip(tr("Open the bundled example %1 as a new, untitled setup").arg(QFileInfo(path).fileName()));
    }
    examplesMenu_->setEnabled(!examplesMenu_->isEmpty());
    file->addSeparator();
    QAction* saveAction = file->addAction(QIcon::fromTheme(QStringLiteral("document-save")), tr("&Save"), this, &MainWindow::save);
    saveAction->setShortcuts(standardKeys(QKeySequence::Save, QKeySequence(Qt::CTRL | Qt::Key_S)));
    QAction* saveAsAction = file->addAction(tr("Save &As…"), this, &MainWindow::saveAs);
    saveAsAction->setShortcuts(standardKeys(QKeySequence::SaveAs, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S)));
    saveAsAction->setObjectName(QStringLiteral("saveAsAction"));
    exportSeparator_ = file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcuts(standardKeys(QKeySequence::Quit, QKeySequence(Qt::CTRL | Qt::Key_Q)));

    QMenu* edit = editMenu_ = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = document_->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setShortcuts(standardKeys(QKeySequence::Undo, QKeySequence(Qt::CTRL | Qt::Key_Z)));
    undo->setObjectName(QStringLiteral("undoAction"));
    undo->setProperty("shortcutName", tr("Undo"));  // the shortcut list names it, not its changing caption
    QAction* redo = document_->undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setShortcuts(standardKeys(QKeySequence::Redo, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z)));
    redo->setObjectName(QStringLiteral("redoAction"));
    redo->setProperty("shortcutName", tr("Redo"));
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

    QMenu* view = viewMenu_ = menuBar()->addMenu(tr("&View"));
    panelsMenu_ = view->addMenu(tr("&Panels"));
    for (QDockWidget* d : std::as_const(docks_)) panelsMenu_->addAction(d->toggleViewAction());
    QMenu* layouts = view->addMenu(tr("La&youts"));
    layouts->setObjectName(QStringLiteral("layoutsMenu"));
    const std::pair<Arrangement, const char*> named[] = {{Arrangement::Teach, "teachLayoutAction"},
                                                         {Arrangement::Coach, "coachLayoutAction"},
                                                         {Arrangement::Edit, "editLayoutAction"}};
    for (const auto& [arrangement, name] : named) {
        QAction* a = layouts->addAction(arrangementName(arrangement), this, [this, which = arrangement] { arrange(which); });
        a->setObjectName(QLatin1String(name));
        a->setToolTip(arrangementTip(arrangement));
    }
    layouts->addSeparator();
    QAction* resetLayoutAction = layouts->addAction(arrangementName(Arrangement::Default), this, &MainWindow::resetLayout);
    resetLayoutAction->setObjectName(QStringLiteral("resetLayoutAction"));
    resetLayoutAction->setToolTip(arrangementTip(Arrangement::Default));
    QMenu* overlays = view->addMenu(tr("&Overlays"));
    overlays->setObjectName(QStringLiteral("overlaysMenu"));  // features add their own overlays to it
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
    const std::pair<BallScope, QString> scopes[] = {{BallScope::All, tr("&All Balls")},
                                                    {BallScope::Selected, tr("&Selected Ball Only")},
                                                    {BallScope::None, tr("&None")}};
    const auto scopeMenu = [&](const QString& title, const QString& tip, auto getter, auto setter) {
        QMenu* m = view->addMenu(title);
        m->setToolTip(tip);
        auto* group = new QActionGroup(m);
        for (const auto& [scope, name] : scopes) {
            QAction* a = m->addAction(name, this, [this, setter, sc = scope] {
                autoScoped_ = false;  // the user's choice from now on
                (view_->*setter)(sc);
            });
            a->setCheckable(true);
            a->setChecked(scope == (view_->*getter)());
            group->addAction(a);
            // Also when the window sets the scope itself (a busy shot opens with the struck ball's).
            connect(view_, &TableView::displayModesChanged, a, [this, a, getter, sc = scope] {
                if ((view_->*getter)() == sc) a->setChecked(true);
            });
        }
    };
    scopeMenu(tr("Pat&hs Of"), tr("Whose paths, trails, event markers and comparison ghosts are drawn (busy shots read better with one ball)"),
              &TableView::pathScope, &TableView::setPathScope);
    scopeMenu(tr("&Labels Of"), tr("Whose event times are labelled in the view"), &TableView::labelScope,
              &TableView::setLabelScope);
    QAction* follow = view->addAction(tr("F&ollow Selected Ball"));
    follow->setCheckable(true);
    follow->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_F));
    follow->setToolTip(tr("Keep the selected ball at the centre of the view as time runs"));
    connect(follow, &QAction::toggled, view_, &TableView::setFollowSelectedBall);
    QAction* zoom = view->addAction(tr("&Zoom to Selection"), this, [this] { view_->zoomToSelection(); });
    zoom->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_0));
    zoom->setToolTip(tr("Frame the selected ball's whole path (the table when no ball is selected)"));
    view->addSeparator();
    QAction* fullScreen = view->addAction(tr("&Full Screen"));
    fullScreen->setCheckable(true);
    fullScreen->setShortcuts(standardKeys(QKeySequence::FullScreen, QKeySequence(Qt::Key_F11)));
    fullScreen->setObjectName(QStringLiteral("fullScreenAction"));
    connect(fullScreen, &QAction::toggled, this, [this](bool on) {
        setWindowState(on ? (windowState() | Qt::WindowFullScreen) : (windowState() & ~Qt::WindowFullScreen));
    });

    analysisMenu_ = menuBar()->addMenu(tr("&Analysis"));
    playbackMenu_ = menuBar()->addMenu(tr("&Playback"));
    playbackMenu_->addActions(transport_->transportActions());
    playbackMenu_->addSeparator();
    // Stops a long simulation: the events computed so far stay, marked as a partial result.
    cancelAction_ = playbackMenu_->addAction(tr("&Cancel Simulation"), document_, &Document::cancelSimulation);
    cancelAction_->setShortcut(QKeySequence(Qt::Key_Escape));
    cancelAction_->setToolTip(tr("Stop the running simulation; the events computed so far stay, marked as a partial result"));
    cancelAction_->setEnabled(false);

    QMenu* help = helpMenu_ = menuBar()->addMenu(tr("&Help"));
    QAction* guide = help->addAction(tr("CueLab &User Guide"), this, [this] { UserGuide::showFor(this); });
    guide->setObjectName(QStringLiteral("userGuideAction"));
    guide->setShortcuts(standardKeys(QKeySequence::HelpContents, QKeySequence(Qt::Key_F1)));
    guide->setToolTip(tr("How to use the window, step by step (the guide bundled with this version)"));
    QAction* keys = help->addAction(tr("&Keyboard and Mouse…"), this, [this] {
        ShortcutsDialog dialog(menuBar(), this);
        dialog.exec();
    });
    keys->setObjectName(QStringLiteral("keyboardAndMouseAction"));
    keys->setToolTip(tr("Every keyboard shortcut and mouse gesture of the window"));
    QAction* tip = help->addAction(tr("Show First-Start &Tip"), tip_, &FirstStartTip::showAgain);
    tip->setToolTip(tr("The short tour shown above the table on the first start"));
    help->addSeparator();
    help->addAction(tr("&About CueLab"), this, &MainWindow::about);
    help->addAction(tr("About &Qt"), qApp, &QApplication::aboutQt);
}

}  // namespace cuelab
