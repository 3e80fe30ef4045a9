#pragma once
// The printable lesson report (PDF, A4 portrait, several pages): the shot diagram with its caption;
// the lesson's notes (flagged when they no longer match the setup), the shot and the physics as a
// table (ShotFacts.h) and the outcome in full (first contact, pockets, cushions, final positions);
// the lesson's questions with the student's guesses, where the balls went and the scores (issue 44;
// only when the setup has questions or a prediction was made); the key collision's derivation with
// its momentum and energy figure (core/explain, the same derivation as the Explain dock); the event
// table (as many pages as it needs); the plots (speed, slip speed, side spin, kinetic energy). Each
// table is printed once. Every word a person reads is translated.
// Written atomically (QSaveFile); the writer reports progress page by page and can be cancelled, in
// which case any existing file is left as it was. Painting only: write() may run on a worker thread.

#include "Prediction.h"
#include "Setup.h"
#include "ShotFacts.h"
#include "Simulation.h"

#include <QString>
#include <QStringList>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

class QPainter;

namespace cuelab {

namespace explain {
struct Step;
}

// A lesson question as the report prints it: the question as the run asks it and, once revealed,
// each asked ball's guess, where it went and its score (PredictSession). No answers: not answered.
struct ReportQuestion {
    lesson::AskedQuestion asked;
    std::vector<lesson::BallReveal> answers;
};

class LessonReport {
public:
    // Without the setup: no shot or physics table, no derivation of the cue strike's numbers.
    LessonReport(std::shared_ptr<const SimulationResult> result, QString title, QString notes);
    // `noteChanges`: what changed since the notes were written (factChanges); printed beside them.
    LessonReport(std::shared_ptr<const SimulationResult> result, const Setup& setup, QStringList noteChanges = {});

    // The collision the report derives: the struck ball's first contact with a ball, else the first
    // collision of any kind; -1 when the shot has none.
    static int keyCollision(const SimulationResult& result);

    // One step of a derivation as the report prints it: rich text with real subscripts and
    // superscripts (law, formula in italics, results), in the window's language.
    static QString stepHtml(const explain::Step& step);

    static constexpr int kEventRowsPerPage = 40;
    // One row of the event table: #N (from 1, as everywhere a person reads), time, type, balls,
    // cushion or pocket, speeds before and after.
    static QStringList eventRow(const SimulationResult& result, int index);
    int eventPages() const;
    // The questions and their answers (in the order asked); none: no page for them.
    void setQuestions(std::vector<ReportQuestion> questions) { questions_ = std::move(questions); }
    const std::vector<ReportQuestion>& questions() const { return questions_; }
    // diagram; notes, facts and outcome; [questions]; key collision; events; plots
    int pageCount() const { return 4 + (questions_.empty() ? 0 : 1) + eventPages(); }

    // Page `page` (1 to pageCount()) without its header and footer, on a canvas kPageWidth x
    // kPageHeight units (A4's proportions), in `painter`'s current transform. write() prints these.
    static constexpr double kPageWidth = 1000.0;
    static constexpr double kPageHeight = 1414.0;
    void paintPage(QPainter& painter, int page) const;

    // progress(done, total) after each page; returning false cancels (then *error = "cancelled").
    using Progress = std::function<bool(int done, int total)>;
    bool write(const QString& path, QString* error, const Progress& progress = {}) const;

private:
    std::shared_ptr<const SimulationResult> result_;
    QString title_;
    QString notes_;
    ShotFacts facts_;
    std::optional<CueStrike> shot_;
    std::optional<GameSpec> game_;  // the rules that judge the shot: the outcome ends with their verdict
    QStringList noteChanges_;
    std::vector<ReportQuestion> questions_;
};

}  // namespace cuelab
