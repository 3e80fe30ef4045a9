#include "ExplainExport.h"

#include "Explain.h"
#include "ExplainText.h"

#include <QFileInfo>
#include <QSaveFile>

namespace cuelab {

std::vector<int> collisionEvents(const SimulationResult& result)
{
    std::vector<int> out;
    for (std::size_t i = 0; i < result.events.size(); ++i)
        if (isCollision(result.events[i].kind) || result.events[i].kind == EventKind::BallPocket) out.push_back(int(i));
    return out;
}

bool exportExplanations(const QString& path, const SimulationResult& result, const std::optional<CueStrike>& shot,
                        const std::vector<int>& events, const QString& title, QString* error)
{
    std::vector<explain::Explanation> all;
    for (int i : events) {
        if (i < 0 || i >= int(result.events.size())) {
            if (error) *error = QObject::tr("no event %1 in this shot").arg(QString::fromStdString(explain::eventNumber(i)));
            return false;
        }
        all.push_back(explain::explain(result, i, shot));
    }
    const QString suffix = QFileInfo(path).suffix().toLower();
    const bool markdown = suffix == QLatin1String("md") || suffix == QLatin1String("markdown");
    const std::string text = markdown ? explain::toMarkdown(all, title.toStdString())
                                      : explain::toHtmlDocument(all, title.toStdString());
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        if (error) *error = QObject::tr("%1: %2").arg(QFileInfo(path).fileName(), file.errorString());
        return false;
    }
    file.write(text.data(), qint64(text.size()));
    if (!file.commit()) {
        if (error) *error = QObject::tr("%1: %2").arg(QFileInfo(path).fileName(), file.errorString());
        return false;
    }
    return true;
}

}  // namespace cuelab
