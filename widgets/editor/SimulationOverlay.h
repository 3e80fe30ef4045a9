#pragma once
// Over the table view while the document's simulation takes a while (issue 39): "Simulating… 1,240
// events, t = 0.840 s" with a Cancel button; once a shown result is partial (cancelled, cut short),
// a note that says where it stopped. It lies over its parent (the view) at the bottom left and
// follows its size; a quick run (under Document's pending delay) never shows it.

#include <QFrame>

class QLabel;
class QPushButton;

namespace cuelab {

class Document;

class SimulationOverlay : public QFrame {
    Q_OBJECT
public:
    SimulationOverlay(Document* document, QWidget* view);

    QString text() const;  // what it says now (tests)

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void refresh();
    void place();

    Document* document_;
    QLabel* label_;
    QPushButton* cancel_;
};

}  // namespace cuelab
