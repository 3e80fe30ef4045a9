#pragma once
// The Explain dock: the selected event's derivation (core/explain) as rich text, the time-of-impact
// polynomial over its prediction window with its roots (Qt Charts), and the momenta diagram and
// kinetic energy bars of the event. It shows the event selected in the window and the event the
// transport steps to (playback time exactly at an event).

#include "Explanation.h"

#include <QWidget>

#include <memory>
#include <optional>

class QTextBrowser;
class QLabel;
class QSplitter;
class QStackedWidget;
class QTabWidget;
class QTimer;

namespace cuelab {

class Document;
class Selection;
class Playback;
class ToiChart;
class ConservationWidget;
class ExplainRunner;

class ExplainPanel : public QWidget {
    Q_OBJECT
public:
    ExplainPanel(Document* document, Selection* selection, Playback* playback, QWidget* parent = nullptr);

    int shownEvent() const { return event_; }  // -1 when nothing is explained (or derived)
    // The derivation of shownEvent() is being computed off the GUI thread (a held group's: the shot is
    // run again up to the event); explanation() is empty until it arrives.
    bool deriving() const { return deriving_; }
    // ms: a derivation that takes longer shows "Deriving…" in place of the text; a quicker one
    // replaces the text before anything else is shown, so the dock does not flash.
    static constexpr int kDerivingNoticeMs = 100;
    // The derivation of shownEvent(); empty while it is being derived (deriving()).
    const std::optional<explain::Explanation>& explanation() const { return deriving_ ? kNone : explanation_; }
    QString html() const;                        // what the text view shows
    ConservationWidget* conservation() const { return conservation_; }  // the momenta and energy figure

public slots:
    void showEvent(int index);                   // -1 clears

signals:
    void explanationChanged();                   // explanation() changed (or cleared)

public:
    // The figures reflow with the dock: the chart beside the momenta and energy when the panel is
    // at least kFiguresSideBySideWidth wide; narrower, the chart above them; narrower and shorter
    // than kTabbedHeight, one figure at a time in tabs, so that the derivation keeps a third of the
    // dock (the stacked figures alone need about 500 px).
    static constexpr int kTallHeight = 850;  // px: shorter, the figures shrink for the derivation
    static constexpr int kTabbedHeight = 720;  // px
    static constexpr int kFiguresSideBySideWidth = 760;
    enum class FigureLayout { SideBySide, Stacked, Tabbed };
    FigureLayout figureLayout() const;
    bool figuresSideBySide() const { return figureLayout() == FigureLayout::SideBySide; }

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void reflow();
    void setFiguresTabbed(bool tabbed);
    void showFigures();
    void followTime(double t);
    void refresh();
    void display(std::optional<explain::Explanation> explanation, int scrolled);
    void derived(int index, std::shared_ptr<const explain::Explanation> explanation, const QString& error);
    void showDerivingNotice();

    Document* document_;
    Selection* selection_;
    Playback* playback_;
    QLabel* placeholder_;
    QTextBrowser* text_;
    ToiChart* chart_;
    ConservationWidget* conservation_;
    QSplitter* figures_ = nullptr;       // the figures side by side or stacked
    QTabWidget* figureTabs_ = nullptr;   // or one at a time
    QStackedWidget* figureHolder_ = nullptr;  // shows one of the two
    bool chartShown_ = false, conservationShown_ = false;  // whether the event has each figure
    int event_ = -1;
    std::optional<explain::Explanation> explanation_;  // the one shown (while deriving, the one before)
    static inline const std::optional<explain::Explanation> kNone{};
    ExplainRunner* runner_;
    QTimer* derivingNotice_;  // single shot: kDerivingNoticeMs after a derivation starts
    bool deriving_ = false;
    int derivingScroll_ = 0;  // px: where the text of the event being derived is to open
};

}  // namespace cuelab
