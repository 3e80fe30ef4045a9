#pragma once
// The words for a prediction and its reveal (core/lesson's headings, verdicts and scores), shared by
// the Predict dock and the lesson report so that both say the same in every language. They keep the
// Predict dock's translation context, where they were first translated.

#include "Prediction.h"

#include <QCoreApplication>
#include <QString>

#include <optional>

namespace cuelab {

class PredictionText {
    Q_DECLARE_TR_FUNCTIONS(cuelab::PredictPanel)
public:
    // "12.5°", or "stays" for a ball said (or found) to stay.
    static QString heading(const std::optional<double>& headingDeg);
    // "spot on", "close", "off", "right", "wrong", "no answer".
    static QString verdict(lesson::Verdict verdict);
    // The angle error with its verdict, "10.0° (close)"; the verdict alone without an angle.
    static QString error(const lesson::BallReveal& reveal);
    // A score of 0 to 1 as a person reads it: "83 %".
    static QString score(double score);
    // What the student reads: the question's own prompt, or "Where will each ball go?".
    static QString prompt(const lesson::AskedQuestion& question);
};

}  // namespace cuelab
