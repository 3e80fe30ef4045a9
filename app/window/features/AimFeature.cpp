// Aiming (issue 22): View > Overlays > Aim Line and Ghost Ball draws the struck ball's first contact
// in the table view (widgets/editor/AimLayer.h); the Shot dock's own aim fields and readouts are
// part of the Shot panel (widgets/editor/AimControl.h, LaunchReadout.h). Aiming in the view (issue
// 44: the cue, the ghost ball and the tip mark dragged, Ctrl+arrows; widgets/view/AimDrag.h) edits
// the shot through the document, one undo step per gesture.

#include "Features.h"
#include "MainWindow.h"

#include "editor/AimLayer.h"
#include "editor/Document.h"
#include "view/TableView.h"

#include <QAction>
#include <QKeySequence>
#include <QMenu>
#include <QSettings>

namespace cuelab {

namespace {
const QString kAimKey = QStringLiteral("overlays/aim");
// Document::setShot merge fields of the view's gestures, apart from the Shot dock's (0-6) and its
// Aim at control's, so that a gesture never merges with a field's edit.
constexpr int kViewAimField = 40;

QString aimStep(AimGesture gesture)
{
    switch (gesture) {
    case AimGesture::Turn: return QObject::tr("Turn the cue");
    case AimGesture::Pull: return QObject::tr("Pull back the cue");
    case AimGesture::Ghost: return QObject::tr("Aim through the ghost ball");
    case AimGesture::Tip: return QObject::tr("Move the cue tip");
    }
    return QString();
}

void aimInView(MainWindow& w)
{
    Document* document = w.document();
    QObject::connect(w.tableView(), &TableView::shotAimed, document,
                     [document](AimGesture gesture, double heading, double speed, double side, double height) {
                         std::optional<CueStrike> shot = document->setup().shot;
                         if (!shot) return;
                         shot->headingDeg = heading;
                         shot->speed = speed;
                         shot->side = side;
                         shot->height = height;
                         document->setShot(shot, aimStep(gesture), kViewAimField + static_cast<int>(gesture));
                     });
    QObject::connect(w.tableView(), &TableView::shotAimFinished, document, &Document::endMerge);
}
}  // namespace

void installAim(MainWindow& w)
{
    auto* toggle = new QAction(QObject::tr("Aim &Line and Ghost Ball"), &w);
    toggle->setObjectName(QStringLiteral("aimOverlayAction"));
    toggle->setCheckable(true);
    toggle->setChecked(QSettings().value(kAimKey, false).toBool());
    toggle->setShortcut(QKeySequence(QStringLiteral("Ctrl+Alt+G")));
    const QString tip = QObject::tr("In the table view: the struck ball's first contact, with the ghost ball (where its "
                                    "centre is at contact), the aim line through it, the line of centres, the cut angle "
                                    "in degrees and the ball fraction");
    toggle->setToolTip(tip);
    toggle->setStatusTip(tip);
    auto* overlays = w.findChild<QMenu*>(QStringLiteral("overlaysMenu"));
    (overlays ? overlays : w.menu(WindowMenu::View))->addAction(toggle);

    const auto update = [&w, toggle] {
        const auto result = w.document()->result();
        if (!toggle->isChecked() || !result) return w.tableView()->clearLayer(kAimLayer);
        ViewLayer layer = aimLayer(*result);
        if (layer.empty()) return w.tableView()->clearLayer(kAimLayer);
        w.tableView()->setLayer(kAimLayer, std::move(layer));
    };
    aimInView(w);
    QObject::connect(w.document(), &Document::resultChanged, &w, update);
    QObject::connect(toggle, &QAction::toggled, &w, [update](bool on) {
        QSettings().setValue(kAimKey, on);
        update();
    });
    update();
}

}  // namespace cuelab
