#include "GoalWords.h"

#include "i18n/DisplayNames.h"

#include <QCoreApplication>
#include <QStringList>

namespace cuelab {

using analysis::Goal;
using analysis::GoalTerm;

namespace {

// The context lupdate gives tr() calls in functions of namespace cuelab (resources/translations).
QString tr(const char* text, int n = -1) { return QCoreApplication::translate("cuelab", text, nullptr, n); }

QString termWords(const GoalTerm& t)
{
    const QString ball = QString::fromStdString(t.ball);
    switch (t.kind) {
    case GoalTerm::Kind::Pocketed:
        if (t.pocket.empty()) return (t.negated ? tr("do not pot %1") : tr("pot %1")).arg(ball);
        return (t.negated ? tr("do not pot %1 in the %2") : tr("pot %1 in the %2")).arg(ball, displayElementName(t.pocket));
    case GoalTerm::Kind::FirstContact: return (t.negated ? tr("do not hit %1 first") : tr("hit %1 first")).arg(ball);
    case GoalTerm::Kind::StruckBallUp: return t.negated ? tr("scratch") : tr("no scratch");
    case GoalTerm::Kind::EndsInRegion:
        return (t.negated ? tr("%1 ends outside the region") : tr("%1 ends inside the region")).arg(ball);
    case GoalTerm::Kind::CushionHits: {
        const char* words = nullptr;
        switch (t.compare) {
        case GoalTerm::Compare::AtMost:
            words = t.negated ? QT_TRANSLATE_NOOP("cuelab", "%1 does not touch at most %n cushion(s)")
                              : QT_TRANSLATE_NOOP("cuelab", "%1 touches at most %n cushion(s)");
            break;
        case GoalTerm::Compare::AtLeast:
            words = t.negated ? QT_TRANSLATE_NOOP("cuelab", "%1 does not touch at least %n cushion(s)")
                              : QT_TRANSLATE_NOOP("cuelab", "%1 touches at least %n cushion(s)");
            break;
        case GoalTerm::Compare::Equal:
            words = t.negated ? QT_TRANSLATE_NOOP("cuelab", "%1 does not touch %n cushion(s)")
                              : QT_TRANSLATE_NOOP("cuelab", "%1 touches %n cushion(s)");
            break;
        }
        return tr(words, t.count).arg(ball);
    }
    // The terms of the game's rules (issue 43, core/rules).
    case GoalTerm::Kind::Legal: return t.negated ? tr("a foul") : tr("a legal shot");
    case GoalTerm::Kind::Scores: return t.negated ? tr("the turn passes") : tr("the striker plays on");
    case GoalTerm::Kind::Point: return t.negated ? tr("no point") : tr("a three-cushion point");
    }
    return {};
}

}  // namespace

QString goalWords(const Goal& goal)
{
    if (goal.empty()) return tr("any shot");
    QStringList terms;
    for (const GoalTerm& t : goal.terms) terms << termWords(t);
    return terms.join(tr(", "));
}

}  // namespace cuelab
