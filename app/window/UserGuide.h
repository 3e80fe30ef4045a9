#pragma once
// Help > CueLab User Guide (F1): docs/user-guide.md as bundled with this build (resources
// ":/docs/"), with its pictures and its links to the other pages, in a window of the application:
// no browser, no network, the guide of the version that runs.

#include <QDialog>

class QTextBrowser;

namespace cuelab {

class UserGuide : public QDialog {
    Q_OBJECT
public:
    static constexpr const char* kHome = "qrc:/docs/user-guide.md";

    explicit UserGuide(QWidget* parent = nullptr);
    QTextBrowser* browser() const { return browser_; }

    // The one guide window of `parent` (made on the first call), shown and raised.
    static UserGuide* showFor(QWidget* parent);

    // The widest picture's width now (for tests): every picture fits the page's width.
    int widestPicture() const;

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void fitPictures();

    QTextBrowser* browser_;
};

}  // namespace cuelab
