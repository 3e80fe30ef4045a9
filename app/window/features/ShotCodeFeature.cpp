// Edit > Copy Shot Code and Paste Shot Code (issue 44; CONTRACT.md, Extensions version 3, "Shot
// codes"): a whole setup as one line of text to share in a chat or a link, and back. A pasted code
// opens as a new untitled document (after asking to save unsaved changes), as a file would; a broken
// code is refused with the problem named, and the document stays as it was. `cuelab CODE` and
// cuelab: links (the desktop entry's URL scheme) open the same way.

#include "Features.h"
#include "MainWindow.h"
#include "editor/Document.h"

#include "ShotCode.h"

#include <QAction>
#include <QClipboard>
#include <QCoreApplication>
#include <QGuiApplication>
#include <QMenu>
#include <QMessageBox>
#include <QStatusBar>

namespace cuelab {

namespace {

QString tr(const char* text, const char* disambiguation = nullptr, int n = -1)
{
    return QCoreApplication::translate("cuelab", text, disambiguation, n);
}

}  // namespace

void installShotCode(MainWindow& window)
{
    QMenu* edit = window.menu(WindowMenu::Edit);
    edit->addSeparator();
    QAction* copy = edit->addAction(tr("&Copy Shot Code"));
    copy->setObjectName(QStringLiteral("copyShotCodeAction"));
    copy->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_C));
    copy->setToolTip(tr("Copy the whole setup as one line of text (cuelab:1:...) to share: anyone pastes it "
                        "into CueLab, or passes it to cuelab-cli, and gets the same shot"));
    QObject::connect(copy, &QAction::triggered, &window, [&window] {
        const QString code = io::shotCode(window.document()->setup());
        QGuiApplication::clipboard()->setText(code);
        window.statusBar()->showMessage(tr("Shot code copied: %n character(s)", nullptr, static_cast<int>(code.size())), 5000);
    });
    QAction* paste = edit->addAction(tr("&Paste Shot Code"));
    paste->setObjectName(QStringLiteral("pasteShotCodeAction"));
    paste->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_V));
    paste->setToolTip(tr("Open the shot code on the clipboard as a new setup"));
    QObject::connect(paste, &QAction::triggered, &window, [&window] {
        const QString text = QGuiApplication::clipboard()->text().trimmed();
        if (!io::isShotCode(text)) {
            QMessageBox::information(&window, tr("Paste Shot Code"),
                                     tr("The clipboard holds no shot code. A shot code is one line beginning with "
                                        "\"cuelab:\", as Edit › Copy Shot Code makes it."));
            return;
        }
        window.openFile(text);
    });
}

}  // namespace cuelab
