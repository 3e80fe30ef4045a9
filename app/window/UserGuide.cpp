#include "UserGuide.h"

#include "Translations.h"

#include <QDesktopServices>
#include <QDialogButtonBox>
#include <QFile>
#include <QGuiApplication>
#include <QPushButton>
#include <QImage>
#include <QScreen>
#include <QTextBlock>
#include <QTextCursor>
#include <QTextDocument>
#include <QTextFragment>
#include <QTextBrowser>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace cuelab {

QUrl UserGuide::homeFor(const QString& language)
{
    const QString translated = QStringLiteral("/docs/user-guide.%1.md").arg(language);
    if (language != QLatin1String("en") && !language.isEmpty() && QFile::exists(QStringLiteral(":") + translated))
        return QUrl(QStringLiteral("qrc:") + translated);
    return QUrl(QString::fromLatin1(kHome));
}

QUrl UserGuide::home()
{
    return homeFor(installedLanguage());
}

UserGuide::UserGuide(QWidget* parent) : QDialog(parent), browser_(new QTextBrowser(this)), home_(home())
{
    setObjectName(QStringLiteral("userGuide"));
    setWindowTitle(tr("CueLab User Guide"));
    browser_->setObjectName(QStringLiteral("userGuideBrowser"));
    // Links between the bundled pages open here; a web address opens in the desktop's browser.
    browser_->setOpenLinks(false);
    connect(browser_, &QTextBrowser::anchorClicked, this, [this](const QUrl& url) {
        const QUrl target = browser_->source().resolved(url);
        if (target.scheme() == QLatin1String("qrc") && target.path().endsWith(QLatin1String(".md")))
            browser_->setSource(target, QTextDocument::MarkdownResource);
        else if (target.scheme() == QLatin1String("qrc"))
            browser_->setSource(target);
        else
            QDesktopServices::openUrl(target);
    });
    connect(browser_, &QTextBrowser::sourceChanged, this, &UserGuide::fitPictures);
    browser_->viewport()->installEventFilter(this);
    // The pages are long: a scroll bar that came and went as the pictures were fitted changed the
    // page's width under them (fitted 14 px too wide).
    browser_->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOn);
    browser_->setSource(home_, QTextDocument::MarkdownResource);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    QPushButton* back = buttons->addButton(tr("&Back"), QDialogButtonBox::ActionRole);
    QPushButton* home = buttons->addButton(tr("&Contents"), QDialogButtonBox::ActionRole);
    back->setEnabled(false);
    connect(browser_, &QTextBrowser::backwardAvailable, back, &QWidget::setEnabled);
    connect(back, &QPushButton::clicked, browser_, &QTextBrowser::backward);
    connect(home, &QPushButton::clicked, browser_, &QTextBrowser::home);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(browser_);
    layout->addWidget(buttons);

    // Wide enough for the guide's pictures at a readable size, within the screen.
    const QRect screen = QGuiApplication::primaryScreen() ? QGuiApplication::primaryScreen()->availableGeometry() : QRect(0, 0, 1280, 800);
    resize(std::min(980, screen.width() * 9 / 10), std::min(1000, screen.height() * 9 / 10));
}

bool UserGuide::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == browser_->viewport() && event->type() == QEvent::Resize) fitPictures();
    return QDialog::eventFilter(watched, event);
}

int UserGuide::pictureWidthFor(int naturalWidth) const
{
    const int room = std::max(200, browser_->viewport()->width() - 2 * static_cast<int>(browser_->document()->documentMargin()) - 8);
    return std::min(room, naturalWidth);
}

void UserGuide::fitPictures()
{
    // The screenshots are as wide as the screens they show: each is drawn at most as wide as the
    // page (its height follows), never wider than it is. The pictures are found first and changed
    // after: changing a fragment's format while walking the fragments skips the ones after it.
    QTextDocument* doc = browser_->document();
    std::vector<std::pair<QTextFragment, QTextImageFormat>> changes;
    for (QTextBlock block = doc->begin(); block.isValid(); block = block.next()) {
        for (auto it = block.begin(); !it.atEnd(); ++it) {
            const QTextFragment fragment = it.fragment();
            QTextImageFormat image = fragment.charFormat().toImageFormat();
            if (!image.isValid()) continue;
            const QUrl url = browser_->source().resolved(QUrl(image.name()));
            const QImage picture(QStringLiteral(":") + url.path());
            if (picture.isNull()) continue;
            const int width = pictureWidthFor(picture.width());
            if (std::abs(image.width() - width) < 1) continue;
            image.setWidth(width);
            image.setHeight(static_cast<double>(width) * picture.height() / picture.width());
            changes.emplace_back(fragment, image);
        }
    }
    for (const auto& [fragment, image] : changes) {
        QTextCursor cursor(doc);
        cursor.setPosition(fragment.position());
        cursor.setPosition(fragment.position() + fragment.length(), QTextCursor::KeepAnchor);
        cursor.setCharFormat(image);
    }
}

int UserGuide::widestPicture() const
{
    int widest = 0;
    const QTextDocument* doc = browser_->document();
    for (QTextBlock block = doc->begin(); block.isValid(); block = block.next())
        for (auto it = block.begin(); !it.atEnd(); ++it) {
            const QTextImageFormat image = it.fragment().charFormat().toImageFormat();
            if (image.isValid()) widest = std::max(widest, static_cast<int>(image.width()));
        }
    return widest;
}

UserGuide* UserGuide::showFor(QWidget* parent)
{
    auto* guide = parent->findChild<UserGuide*>(QString(), Qt::FindDirectChildrenOnly);
    if (guide && guide->home_ != home()) {  // the interface's language changed: the guide follows it
        delete guide;
        guide = nullptr;
    }
    if (!guide) guide = new UserGuide(parent);
    guide->QDialog::show();
    guide->raise();
    guide->activateWindow();
    return guide;
}

}  // namespace cuelab
