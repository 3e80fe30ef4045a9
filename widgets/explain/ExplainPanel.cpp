#include "ExplainPanel.h"

#include "ConservationWidget.h"
#include "editor/Document.h"
#include "editor/ResultFeed.h"
#include "Explain.h"
#include "ExplainLanguage.h"
#include "ExplainRunner.h"
#include "ExplainText.h"
#include "editor/Playback.h"
#include "ToiChart.h"
#include "editor/Selection.h"

#include <QLabel>
#include <QScrollBar>
#include <QSplitter>
#include <QStackedWidget>
#include <QTabWidget>
#include <QTextBrowser>
#include <QTimer>
#include <QVBoxLayout>

namespace cuelab {

ExplainPanel::ExplainPanel(Document* document, Selection* selection, Playback* playback, QWidget* parent)
    : QWidget(parent), document_(document), selection_(selection), playback_(playback)
{
    placeholder_ = new QLabel(this);
    placeholder_->setWordWrap(true);
    text_ = new QTextBrowser(this);
    text_->setObjectName(QStringLiteral("explainText"));
    text_->setOpenLinks(false);
    chart_ = new ToiChart(this);
    chart_->setToolTip(tr("The time-of-impact polynomial f(τ) over the prediction window: its roots are marked, "
                          "the root that gave the event in red. τ in seconds from t₀."));
    conservation_ = new ConservationWidget(this);

    auto* lower = figures_ = new QSplitter(Qt::Horizontal, this);
    lower->setObjectName(QStringLiteral("explainFigures"));
    lower->setChildrenCollapsible(false);
    lower->addWidget(chart_);
    lower->addWidget(conservation_);
    figureTabs_ = new QTabWidget(this);
    figureTabs_->setObjectName(QStringLiteral("explainFigureTabs"));
    figureTabs_->setDocumentMode(true);
    // Never wider than the narrowest dock: the tab names elide, and scroll, rather than widen it.
    figureTabs_->setElideMode(Qt::ElideRight);
    figureTabs_->setUsesScrollButtons(true);
    // Its tab bar's width is no minimum for the dock (the figures in it have their own).
    figureTabs_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    figureHolder_ = new QStackedWidget(this);
    figureHolder_->addWidget(lower);
    figureHolder_->addWidget(figureTabs_);
    auto* split = new QSplitter(Qt::Vertical, this);
    split->addWidget(text_);
    split->addWidget(figureHolder_);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addWidget(placeholder_);
    layout->addWidget(split, 1);

    runner_ = new ExplainRunner(this);
    connect(runner_, &ExplainRunner::finished, this, &ExplainPanel::derived);
    derivingNotice_ = new QTimer(this);
    derivingNotice_->setSingleShot(true);
    derivingNotice_->setInterval(kDerivingNoticeMs);
    connect(derivingNotice_, &QTimer::timeout, this, &ExplainPanel::showDerivingNotice);

    if (selection_)
        connect(selection_, &Selection::eventChanged, this, [this](int index) {
            if (index >= 0) showEvent(index);
        });
    if (playback_) connect(playback_, &Playback::timeChanged, this, &ExplainPanel::followTime);
    if (document_) {
        ResultFeed::follow(document_, this, [this] { refresh(); });
        connect(document_, &Document::documentReplaced, this, [this] { showEvent(-1); });
    }
    showEvent(-1);
}

QString ExplainPanel::html() const { return text_->toHtml(); }

ExplainPanel::FigureLayout ExplainPanel::figureLayout() const
{
    if (figureHolder_->currentWidget() == figureTabs_) return FigureLayout::Tabbed;
    return figures_->orientation() == Qt::Horizontal ? FigureLayout::SideBySide : FigureLayout::Stacked;
}

void ExplainPanel::setFiguresTabbed(bool tabbed)
{
    if (tabbed == (figureHolder_->currentWidget() == figureTabs_)) return;
    // The same two figure widgets move between the splitter and the tabs (reparented, not copied).
    if (tabbed) {
        figureTabs_->addTab(chart_, tr("Time of impact"));
        figureTabs_->addTab(conservation_, tr("Momenta and energy"));
        figureHolder_->setCurrentWidget(figureTabs_);
    } else {
        figureTabs_->clear();
        figures_->addWidget(chart_);
        figures_->addWidget(conservation_);
        figureHolder_->setCurrentWidget(figures_);
    }
    showFigures();
}

void ExplainPanel::showFigures()
{
    // A figure with nothing to show gives its room to the derivation: no chart for an event whose
    // time is closed-form (a transition, the cue strike), no momenta without bodies. With no event
    // at all only the placeholder stays: the dock then asks for no height of its own, and the
    // table view beside it keeps the window's height. In tabs, such a figure loses its tab.
    if (figureHolder_->currentWidget() == figureTabs_) {
        chart_->setVisible(true);
        conservation_->setVisible(true);
        figureTabs_->setTabVisible(figureTabs_->indexOf(chart_), chartShown_);
        figureTabs_->setTabVisible(figureTabs_->indexOf(conservation_), conservationShown_);
    } else {
        chart_->setVisible(chartShown_);
        conservation_->setVisible(conservationShown_);
    }
    figureHolder_->setVisible(chartShown_ || conservationShown_);
}

void ExplainPanel::resizeEvent(QResizeEvent* event)
{
    QWidget::resizeEvent(event);
    reflow();
}

void ExplainPanel::reflow()
{
    const bool wide = width() >= kFiguresSideBySideWidth;
    figures_->setOrientation(wide ? Qt::Horizontal : Qt::Vertical);
    setFiguresTabbed(!wide && height() < kTabbedHeight);
    // Narrow, the momenta stand above the energy: the figure needs more height. In a short dock (a
    // window of 800 px or less in height) the figures give some of it up, so that the derivation
    // keeps a third of the dock.
    const bool tall = height() >= kTallHeight;
    const int conservationWidth = wide ? width() / 2 : width();
    // In tabs a figure has the figures' whole room: the momenta above the energy take their full
    // height there (below 380 px the energy's legend runs into its bars).
    const bool roomy = tall || figureLayout() == FigureLayout::Tabbed;
    conservation_->setMinimumHeight(conservationWidth < ConservationWidget::kSideBySideWidth ? (roomy ? 380 : 260) : 230);
    chart_->setMinimumHeight(230);  // lower, Qt Charts elides the axes' numbers
}

void ExplainPanel::followTime(double t)
{
    const auto result = document_ ? document_->result() : nullptr;
    if (!result) return;
    // The transport lands exactly on event times (next/previous event): show that event, unless the
    // one shown already happens then (a chain of events at one instant keeps the chosen one).
    if (event_ >= 0 && event_ < int(result->events.size()) && result->events[std::size_t(event_)].time == t) return;
    for (std::size_t i = 0; i < result->events.size(); ++i)
        if (result->events[i].time == t) {
            showEvent(int(i));
            return;
        }
}

void ExplainPanel::refresh()
{
    // A new result (an edit re-simulated): explain the same event index again if it still exists.
    showEvent(event_);
}

void ExplainPanel::showEvent(int index)
{
    const auto result = document_ ? document_->result() : nullptr;
    // The same event again (a new result while dragging, or the language changed): the reader keeps
    // his place. Another event opens at its heading.
    const bool again = (explanation_.has_value() || deriving_) && index == event_;
    const int scrolled = !again ? 0 : deriving_ ? derivingScroll_ : text_->verticalScrollBar()->value();
    // A derivation under way is of another event or of an older result: stopped, never shown.
    runner_->cancel();
    derivingNotice_->stop();
    deriving_ = false;
    if (!result || index < 0 || index >= int(result->events.size())) {
        event_ = -1;
        display(std::nullopt, 0);
        return;
    }
    event_ = index;
    if (explain::runsAgain(*result, index)) {
        // A held group's solve: the shot is run again up to the event, off this thread. Until it comes,
        // the text and figures shown stay (a quick derivation replaces them without a flash; the
        // figures keep pointing at explanation_, which stays alive), but explanation() is empty; past
        // kDerivingNoticeMs, "Deriving…" stands in for them.
        deriving_ = true;
        derivingScroll_ = scrolled;
        runner_->start(result, index, document_->setup().shot);
        derivingNotice_->start();
        emit explanationChanged();
        return;
    }
    // Every other event is derived in closed form, in microseconds: at once.
    display(explain::explain(*result, index, document_->setup().shot), scrolled);
}

void ExplainPanel::derived(int index, std::shared_ptr<const explain::Explanation> explanation, const QString& error)
{
    // (The runner reports only the derivation it was last asked for: this one.)
    derivingNotice_->stop();
    deriving_ = false;
    if (!explanation) {
        qWarning("Explain: event %d could not be derived: %s", index, qPrintable(error));
        event_ = -1;
        display(std::nullopt, 0);
        return;
    }
    display(*explanation, derivingScroll_);
}

void ExplainPanel::showDerivingNotice()
{
    if (!deriving_) return;
    placeholder_->setText(tr("Deriving event #%1… (its held group is found by running the shot again up to it)")
                              .arg(event_ + 1));
    placeholder_->setVisible(true);
    text_->setVisible(false);
    chartShown_ = conservationShown_ = false;
    showFigures();
}

void ExplainPanel::display(std::optional<explain::Explanation> explanation, int scrolled)
{
    explanation_ = std::move(explanation);
    placeholder_->setText(tr("Select an event (in Events, or step to one with Shift+Right) to see its mathematics."));
    placeholder_->setVisible(!explanation_);
    if (explanation_) {
        text_->setHtml(QString::fromStdString(explain::toHtml(*explanation_, explainLanguage())));
    } else {
        text_->clear();
    }
    chart_->setExplanation(explanation_ ? &*explanation_ : nullptr);
    conservation_->setExplanation(explanation_ ? &*explanation_ : nullptr);
    chartShown_ = explanation_ && explanation_->toi.has_value();
    conservationShown_ = explanation_ && !explanation_->bodies.empty();
    showFigures();
    text_->setVisible(explanation_.has_value());
    // Last: showing the text and its figures lays the text out again, which scrolls it.
    text_->verticalScrollBar()->setValue(scrolled);
    emit explanationChanged();
}

}  // namespace cuelab
