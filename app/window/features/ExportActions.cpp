#include "ExportActions.h"

#include "ResultText.h"
#include "export/DiagramFiles.h"
#include "export/LessonReport.h"

namespace cuelab::exports {

namespace {

bool writeText(const std::optional<std::string>& text, const QString& path, QString* error)
{
    if (!text) {
        if (error) *error = QStringLiteral("cancelled");
        return false;
    }
    return writeFileAtomically(path, QByteArray::fromStdString(*text), error);
}

}  // namespace

bool trajectoryCsv(const SimulationResult& result, double frameDt, const QString& path, QString* error,
                   const Progress& progress)
{
    return writeText(cli::trajectoryCsv(result, frameDt, progress ? progress : cli::Progress([](double) { return true; })),
                     path, error);
}

bool trajectoryJson(const SimulationResult& result, double frameDt, const QString& path, QString* error,
                    const Progress& progress)
{
    return writeText(cli::trajectoryJson(result, frameDt, progress), path, error);
}

bool eventsCsv(const SimulationResult& result, const QString& path, QString* error)
{
    return writeFileAtomically(path, QByteArray::fromStdString(cli::eventsCsv(result)), error);
}

bool eventsJson(const SimulationResult& result, const QString& path, QString* error, const GameSpec* game)
{
    return writeFileAtomically(path, QByteArray::fromStdString(cli::simulationJson(result, game)), error);
}

bool lessonReport(std::shared_ptr<const SimulationResult> result, const Setup& setup, const QStringList& noteChanges,
                  std::vector<ReportQuestion> questions, const QString& path, QString* error, const Progress& progress)
{
    LessonReport report(std::move(result), setup, noteChanges);
    report.setQuestions(std::move(questions));
    return report.write(path, error, [&](int done, int total) {
        return !progress || progress(static_cast<double>(done) / total);
    });
}

}  // namespace cuelab::exports
