#pragma once
// Help > CueLab User Guide (F1): docs/user-guide.md as bundled with this build (resources
// ":/docs/"), with its pictures and its links to the other pages, in a window of the application:
// no browser, no network, the guide of the version that runs. In a translated interface it shows
// the guide's translation, docs/user-guide.<language>.md (user-guide.hu.md), when there is one.

#include <QDialog>
#include <QUrl>

class QTextBrowser;

namespace cuelab {

class UserGuide : public QDialog {
    Q_OBJECT
public:
    static constexpr const char* kHome = "qrc:/docs/user-guide.md";

    // The guide in `language` ("hu": qrc:/docs/user-guide.hu.md), kHome when it has none.
    static QUrl homeFor(const QString& language);
    // The guide in the installed interface language (Translations.h).
    static QUrl home();

    explicit UserGuide(QWidget* parent = nullptr);
    QTextBrowser* browser() const { return browser_; }

    // The one guide window of `parent` (made on the first call, and again when the language
    // changed since), shown and raised.
    static UserGuide* showFor(QWidget* parent);

    // The widest picture's width now (for tests): every picture fits the page's width.
    int widestPicture() const;
    // The width a picture `naturalWidth` pixels wide is drawn at on the page now: the page's width,
    // or less when the picture is narrower (never drawn wider than it is).
    int pictureWidthFor(int naturalWidth) const;

protected:
    // The page's own resizes (its viewport's), not the dialog's: a hidden dialog's resize comes
    // before its page is laid out, and the pictures fitted then stayed small.
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void fitPictures();

    QTextBrowser* browser_;
    QUrl home_;  // the page Contents goes back to
};

}  // namespace cuelab
