#include "RecentFiles.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>

namespace cuelab {

namespace {
const QString kKey = QStringLiteral("files/recent");
}  // namespace

RecentFiles::RecentFiles(const QString& title, QWidget* parent) : QMenu(title, parent)
{
    setToolTipsVisible(true);
    rebuild();
}

QStringList RecentFiles::files() const { return QSettings().value(kKey).toStringList(); }

void RecentFiles::add(const QString& path)
{
    QStringList list = files();
    list.removeAll(path);
    list.prepend(path);
    while (list.size() > kMaxFiles) list.removeLast();
    QSettings().setValue(kKey, list);
    rebuild();
}

void RecentFiles::rebuild()
{
    clear();
    const QStringList list = files();
    int n = 1;
    for (const QString& path : list) {
        QAction* a = addAction(QStringLiteral("&%1 %2").arg(n++).arg(QFileInfo(path).fileName()), this,
                               [this, path] { emit openRequested(path); });
        a->setToolTip(QDir::toNativeSeparators(path));
    }
    if (!list.isEmpty()) {
        addSeparator();
        addAction(tr("&Clear List"), this, [this] {
            QSettings().remove(kKey);
            rebuild();
        });
    }
    setEnabled(!list.isEmpty());
}

}  // namespace cuelab
