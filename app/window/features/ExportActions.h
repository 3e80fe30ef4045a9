#pragma once
// What File > Export writes, as functions of the current result (the ExportFeature's actions call
// them, tests call them directly). Each writes atomically (QSaveFile): on failure *error names the
// file and the reason, and a file already there is left intact. The long ones take a progress
// callback (fraction done, 0..1) that cancels the work by returning false (then *error = "cancelled").

#include "Setup.h"
#include "Simulation.h"
#include "export/LessonReport.h"

#include <QString>
#include <QStringList>

#include <functional>
#include <memory>
#include <vector>

namespace cuelab::exports {

using Progress = std::function<bool(double fraction)>;

// The trajectory, frame step frameDt (s): the CSV equals `cuelab-cli trajectory --frame-dt S` byte
// for byte (the same function, app/cli/ResultText.h); JSON has the same frames.
bool trajectoryCsv(const SimulationResult& result, double frameDt, const QString& path, QString* error,
                   const Progress& progress = {});
bool trajectoryJson(const SimulationResult& result, double frameDt, const QString& path, QString* error,
                    const Progress& progress = {});

// The events: CSV one row per event and agent; JSON as `cuelab-cli simulate` prints it (with the outcome).
bool eventsCsv(const SimulationResult& result, const QString& path, QString* error);
bool eventsJson(const SimulationResult& result, const QString& path, QString* error, const GameSpec* game = nullptr);

// The lesson report (widgets/export/LessonReport): several PDF pages, with the setup's shot and
// physics, `noteChanges` (what changed since the notes were written) beside the notes, and the
// lesson's questions with the guesses and scores made so far.
bool lessonReport(std::shared_ptr<const SimulationResult> result, const Setup& setup, const QStringList& noteChanges,
                  std::vector<ReportQuestion> questions, const QString& path, QString* error, const Progress& progress = {});

}  // namespace cuelab::exports
