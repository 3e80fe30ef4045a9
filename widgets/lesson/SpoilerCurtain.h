#pragma once
// Predictions without spoilers (issue 44): a dock whose panel runs the shot on its own (Compare,
// Analysis) does not read the document's cut result, so it would show what happens after an open
// question's moment: the other engine's collisions, whether the shot makes its goal. The curtain
// holds such a panel and, while the document withholds (Document::isWithholding), shows in its place
// one line saying so; at the reveal the panel is back as it was (it keeps working behind the curtain).

#include <QStackedWidget>

class QLabel;

namespace cuelab {

class Document;

class SpoilerCurtain : public QStackedWidget {
    Q_OBJECT
public:
    SpoilerCurtain(Document* document, QWidget* content, QWidget* parent = nullptr);

    bool isDrawn() const { return currentWidget() != content_; }
    QWidget* content() const { return content_; }
    QLabel* noteLabel() const { return note_; }
    static QString note();

signals:
    void drawnChanged(bool drawn);

private:
    void follow();

    Document* document_;
    QWidget* content_;
    QLabel* note_;
};

}  // namespace cuelab
