#include "Arrangements.h"

#include <QCoreApplication>

namespace cuelab {

namespace {

const QString kBalls = QStringLiteral("BallsDock");
const QString kShot = QStringLiteral("ShotDock");
const QString kPhysics = QStringLiteral("PhysicsDock");
const QString kLesson = QStringLiteral("LessonDock");
const QString kPredict = QStringLiteral("PredictDock");  // issue 22: predict, then reveal
const QString kEvents = QStringLiteral("EventsDock");
const QString kOutcome = QStringLiteral("OutcomeDock");
const QString kExplain = QStringLiteral("ExplainDock");
const QString kInspector = QStringLiteral("InspectorDock");
const QString kHistory = QStringLiteral("UndoHistoryDock");
const QString kAnalysis = QStringLiteral("AnalysisDock");
const QString kPlots = QStringLiteral("PlotsDock");
const QString kCompare = QStringLiteral("CompareDock");

}  // namespace

ArrangementSpec arrangementSpec(Arrangement arrangement)
{
    ArrangementSpec s;
    switch (arrangement) {
    case Arrangement::Default:
        // The sides together take 44 % of the width: the table view keeps more than half of the
        // window at 1280x800 and above (tst_windowapi::tableViewKeepsItsShare).
        s.left = {{{kShot, kBalls, kPhysics, kLesson, kPredict}, {kShot, kBalls, kPhysics, kLesson, kPredict}, 1}};
        s.right = {{{kEvents, kOutcome}, {kEvents, kOutcome}, 4},
                   {{kExplain, kInspector, kHistory, kAnalysis}, {kExplain, kInspector, kHistory}, 6}};
        s.bottom = {{{kPlots, kCompare}, {}, 1}};
        s.leftShare = 0.2;
        s.rightShare = 0.24;
        break;
    case Arrangement::Teach:
        s.left = {{{kLesson, kPredict, kShot, kBalls, kPhysics}, {kLesson, kPredict}, 1}};
        s.right = {{{kExplain, kEvents, kOutcome, kInspector, kHistory, kAnalysis}, {kExplain}, 1}};
        s.bottom = {{{kPlots, kCompare}, {kPlots}, 1}};
        s.leftShare = 0.2;
        s.rightShare = 0.28;  // Explain's figures want the width
        s.bottomShare = 0.22;
        break;
    case Arrangement::Coach:
        s.left = {{{kShot, kBalls, kPhysics, kLesson, kPredict}, {kShot}, 1}};
        s.right = {{{kAnalysis, kExplain, kInspector, kHistory}, {kAnalysis}, 6},
                   {{kOutcome, kEvents}, {kOutcome}, 4}};
        s.bottom = {{{kPlots, kCompare}, {}, 1}};
        s.leftShare = 0.22;  // the tip picker whole
        s.rightShare = 0.26;
        break;
    case Arrangement::Edit:
        // Balls alone on the left: its list shows every ball of a rack above its editor.
        s.left = {{{kBalls, kShot, kLesson, kPredict}, {kBalls}, 1}};
        s.right = {{{kEvents, kOutcome, kExplain, kInspector, kHistory, kAnalysis}, {kEvents}, 9},
                   {{kPhysics}, {kPhysics}, 11}};
        s.bottom = {{{kPlots, kCompare}, {}, 1}};
        s.leftShare = 0.24;
        s.rightShare = 0.26;
        break;
    }
    return s;
}

QString arrangementName(Arrangement arrangement)
{
    switch (arrangement) {
    case Arrangement::Default: return QCoreApplication::translate("Arrangements", "&Reset Layout");
    case Arrangement::Teach: return QCoreApplication::translate("Arrangements", "&Teach");
    case Arrangement::Coach: return QCoreApplication::translate("Arrangements", "&Coach");
    case Arrangement::Edit: return QCoreApplication::translate("Arrangements", "&Edit");
    }
    return {};
}

QString arrangementTip(Arrangement arrangement)
{
    switch (arrangement) {
    case Arrangement::Default:
        return QCoreApplication::translate("Arrangements", "Every panel back where the first start put it: the editor on the left, the events and "
                  "explanations on the right, plots and comparisons hidden until asked for");
    case Arrangement::Teach: return QCoreApplication::translate("Arrangements", "For a lesson: the table, the Lesson notes, Explain and Plots");
    case Arrangement::Coach: return QCoreApplication::translate("Arrangements", "For a shot on the table: the table, Shot with the whole tip picker, Analysis and Outcome");
    case Arrangement::Edit: return QCoreApplication::translate("Arrangements", "For setting up: the table, Balls and Physics, Events");
    }
    return {};
}

}  // namespace cuelab
