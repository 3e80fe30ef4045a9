#include "PredictionText.h"

#include "i18n/UiNumbers.h"

namespace cuelab {

QString PredictionText::heading(const std::optional<double>& headingDeg)
{
    return headingDeg ? tr("%1°").arg(uiNumber(*headingDeg, 1)) : tr("stays");
}

QString PredictionText::verdict(lesson::Verdict v)
{
    switch (v) {
    case lesson::Verdict::SpotOn: return tr("spot on");
    case lesson::Verdict::Close: return tr("close");
    case lesson::Verdict::Off: return tr("off");
    case lesson::Verdict::Right: return tr("right");
    case lesson::Verdict::Wrong: return tr("wrong");
    case lesson::Verdict::NoAnswer: return tr("no answer");
    }
    return {};
}

QString PredictionText::error(const lesson::BallReveal& r)
{
    return r.errorDeg ? tr("%1° (%2)").arg(uiNumber(*r.errorDeg, 1)).arg(verdict(r.verdict)) : verdict(r.verdict);
}

QString PredictionText::score(double s) { return tr("%1 %").arg(uiNumber(s * 100.0, 0)); }

QString PredictionText::prompt(const lesson::AskedQuestion& q)
{
    return q.prompt.empty() ? tr("Where will each ball go?") : QString::fromStdString(q.prompt);
}

}  // namespace cuelab
