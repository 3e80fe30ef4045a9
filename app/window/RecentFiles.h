#pragma once
// The Open Recent menu: the last files opened or saved, newest first, kept in QSettings.

#include <QMenu>

namespace cuelab {

class RecentFiles : public QMenu {
    Q_OBJECT
public:
    explicit RecentFiles(const QString& title, QWidget* parent = nullptr);

    static constexpr int kMaxFiles = 8;

    QStringList files() const;
    void add(const QString& path);  // moves it to the top

signals:
    void openRequested(const QString& path);

private:
    void rebuild();
};

}  // namespace cuelab
