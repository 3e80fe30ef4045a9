#include "SimulationOverlay.h"

#include "Document.h"
#include "RunState.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

#include <algorithm>

namespace cuelab {

SimulationOverlay::SimulationOverlay(Document* document, QWidget* view)
    : QFrame(view), document_(document), label_(new QLabel(this)), cancel_(new QPushButton(tr("Cancel"), this))
{
    setObjectName(QStringLiteral("simulationOverlay"));
    setFrameShape(QFrame::StyledPanel);
    setAutoFillBackground(true);
    QPalette p = palette();
    p.setColor(QPalette::Window, p.color(QPalette::ToolTipBase));
    p.setColor(QPalette::WindowText, p.color(QPalette::ToolTipText));
    setPalette(p);
    label_->setObjectName(QStringLiteral("simulationOverlayText"));
    cancel_->setObjectName(QStringLiteral("simulationOverlayCancel"));
    cancel_->setToolTip(tr("Stop the simulation: the events computed so far stay, marked as a partial result (Esc)"));
    connect(cancel_, &QPushButton::clicked, document_, &Document::cancelSimulation);
    // The note keeps its height when Cancel goes (the GL view under it is not always drawn again
    // where a child widget shrank away).
    QSizePolicy keep = cancel_->sizePolicy();
    keep.setRetainSizeWhenHidden(true);
    cancel_->setSizePolicy(keep);
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(10, 4, 6, 4);
    layout->addWidget(label_, 1);
    layout->addWidget(cancel_);
    connect(document_, &Document::resultChanged, this, &SimulationOverlay::refresh);
    connect(document_, &Document::simulatingChanged, this, &SimulationOverlay::refresh);
    connect(document_, &Document::simulationProgress, this, [this](qint64 events, double time) {
        if (!isVisible() || !cancel_->isVisible()) return;
        label_->setText(RunState::simulatingText(events, time));
        place();
    });
    view->installEventFilter(this);
    refresh();
}

QString SimulationOverlay::text() const { return isVisible() ? label_->text() : QString(); }

void SimulationOverlay::refresh()
{
    const auto result = document_->result();
    // Shown once the document shows the run as it goes (its result so far), or a partial result.
    const bool shown = result && document_->isResultForSetup() && !result->finished();
    if (!shown) {
        hide();
        return;
    }
    const bool running = document_->isSimulating() && result->status == SimulationStatus::Running;
    cancel_->setVisible(running);
    label_->setText(running ? RunState::simulatingText(static_cast<long long>(result->events.size()), result->endTime)
                            : RunState::unfinishedNote(*result));
    show();
    raise();
    place();
}

bool SimulationOverlay::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == parent() && event->type() == QEvent::Resize) place();
    return QFrame::eventFilter(watched, event);
}

void SimulationOverlay::place()
{
    const QWidget* over = parentWidget();
    if (!over) return;
    constexpr int kMargin = 8;  // px from the view's edges
    const QSize wanted = sizeHint();
    const int width = std::min(wanted.width(), std::max(0, over->width() - 2 * kMargin));
    const QRect was = geometry();
    setGeometry(kMargin, std::max(0, over->height() - wanted.height() - kMargin), width, wanted.height());
    // A narrower note (Cancel gone) leaves part of the view it covered: the view draws that part again
    // (the GL view is not told by itself). Not when it only grows or stays: no redraw per progress line.
    if (isVisible() && !geometry().contains(was)) parentWidget()->update();
}

}  // namespace cuelab
