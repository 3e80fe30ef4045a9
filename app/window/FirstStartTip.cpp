#include "FirstStartTip.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QSettings>
#include <QToolButton>

#include <algorithm>

namespace cuelab {

namespace {

const QString kSeenKey = QStringLiteral("help/firstStartTipSeen");

}  // namespace

FirstStartTip::FirstStartTip(QWidget* parent) : QFrame(parent)
{
    setObjectName(QStringLiteral("firstStartTip"));
    setFrameShape(QFrame::StyledPanel);
    setAutoFillBackground(true);
    QPalette p = palette();
    p.setColor(QPalette::Window, p.color(QPalette::ToolTipBase));
    p.setColor(QPalette::WindowText, p.color(QPalette::ToolTipText));
    setPalette(p);
    auto* text = new QLabel(
        tr("<b>New to CueLab?</b> Open a lesson from <i>File › Examples</i>. <b>Space</b> plays the shot, "
           "<b>←/→</b> step a frame, <b>Shift+←/→</b> jump to the next event; click an event in <i>Events</i> "
           "to read its mathematics. Drag a ball to move it; every edit can be undone (<b>Ctrl+Z</b>). "
           "<b>F1</b> opens the user guide; <i>Help › Keyboard and Mouse</i> lists every shortcut and mouse gesture."),
        this);
    text->setWordWrap(true);
    text->setTextFormat(Qt::RichText);
    auto* close = new QToolButton(this);
    close->setObjectName(QStringLiteral("firstStartTipClose"));
    close->setText(QStringLiteral("✕"));
    close->setToolTip(tr("Hide this tip (Help › Show First-Start Tip brings it back)"));
    close->setAutoRaise(true);
    connect(close, &QToolButton::clicked, this, &FirstStartTip::dismiss);
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(10, 6, 6, 6);
    layout->addWidget(text, 1);
    layout->addWidget(close, 0, Qt::AlignTop);
    setVisible(pending());
    if (parent) {
        parent->installEventFilter(this);
        place();
    }
    // Seen once is enough: the next start shows it no more, even if this one never closes it.
    QSettings().setValue(kSeenKey, true);
}

bool FirstStartTip::pending() { return !QSettings().value(kSeenKey, false).toBool(); }

void FirstStartTip::showAgain()
{
    show();
    raise();
    place();
}

bool FirstStartTip::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == parent() && event->type() == QEvent::Resize) place();
    // Escape over the table view closes the tip first (a new user's first reflex), before the view
    // sees the key.
    if (watched == parent() && event->type() == QEvent::KeyPress && !isHidden() &&
        static_cast<QKeyEvent*>(event)->key() == Qt::Key_Escape) {
        dismiss();
        return true;
    }
    return QFrame::eventFilter(watched, event);
}

void FirstStartTip::place()
{
    const QWidget* over = parentWidget();
    if (!over) return;
    constexpr int kMargin = 8;  // px from the view's edges
    const int width = std::max(0, over->width() - 2 * kMargin);
    const int height = layout() && layout()->hasHeightForWidth() ? layout()->totalHeightForWidth(width) : sizeHint().height();
    setGeometry(kMargin, kMargin, width, std::min(height, std::max(0, over->height() - 2 * kMargin)));
}

void FirstStartTip::dismiss()
{
    QSettings().setValue(kSeenKey, true);
    hide();
}

}  // namespace cuelab
