#pragma once
// The printable lesson report (PDF, A4 portrait, several pages): the shot diagram with its caption;
// the lesson's notes and the outcome in full (first contact, pockets, cushions, final positions); the
// event table (as many pages as it needs); the plots (speed, slip speed, side spin, kinetic energy).
// Written atomically (QSaveFile); the writer reports progress page by page and can be cancelled, in
// which case any existing file is left as it was. Painting only: write() may run on a worker thread.

#include "Simulation.h"

#include <QString>
#include <QStringList>

#include <functional>
#include <memory>

namespace cuelab {

class LessonReport {
public:
    LessonReport(std::shared_ptr<const SimulationResult> result, QString title, QString notes);

    static constexpr int kEventRowsPerPage = 40;
    // One row of the event table: #N (from 1, as everywhere a person reads), time, type, balls,
    // cushion or pocket, speeds before and after.
    static QStringList eventRow(const SimulationResult& result, int index);
    int eventPages() const;
    int pageCount() const { return 3 + eventPages(); }  // diagram, notes and outcome, events, plots

    // progress(done, total) after each page; returning false cancels (then *error = "cancelled").
    using Progress = std::function<bool(int done, int total)>;
    bool write(const QString& path, QString* error, const Progress& progress = {}) const;

private:
    std::shared_ptr<const SimulationResult> result_;
    QString title_;
    QString notes_;
};

}  // namespace cuelab
