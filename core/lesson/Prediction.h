#pragma once
// Predict, then reveal (issue 22, item 4): a lesson question (LessonQuestion.h) stops playback just
// before an event; the student gives each asked ball a direction (or says it stays); the reveal sets
// each prediction beside where the ball actually went and scores the angle between them.
//
// Where a ball "goes" after the event is the direction a player would name: its velocity once it
// has stopped sliding (the slide-to-roll or slide-to-spin event: after a draw or follow shot the
// cue ball's path bends until then), or just before its next collision or pocketing if that comes
// first; for a ball that comes to rest first, the way it moved to its stop. A ball that moves less
// than kStillDistance in all that "stays".
//
// Scoring: the angle error is the smaller angle between the predicted and the actual direction
// (0° to 180°); a ball's score is 1 − error/90° (at least 0), so a guess at right angles or worse
// scores nothing. "Stays" against "stays" scores 1; "stays" against a move (or the reverse) and no
// answer score 0. A question's score is the mean over its balls.

#include "Setup.h"
#include "Simulation.h"

#include <optional>
#include <string>
#include <vector>

namespace cuelab::lesson {

// m: a ball that moves less than this after the event "stays" (a stun shot's cue ball that creeps
// a few millimetres on after a full hit with restitution 0.95 is still a stop to the eye).
constexpr double kStillDistance = 0.01;
// degrees: the verdicts' limits (a coach's "spot on" and "close").
constexpr double kSpotOnDeg = 5.0;
constexpr double kCloseDeg = 15.0;

// The question as a run asks it: the event it stops before and the balls it asks about.
struct AskedQuestion {
    int question = -1;              // index into Setup::questions
    int event = -1;                 // index into SimulationResult::events
    double time = 0.0;              // s, the event's time: playback stops just before it
    std::vector<int> balls;         // indices into SimulationResult::balls, in the question's order
    std::string prompt;             // the question's prompt ("": the surface's own "Where will each ball go?")
};

// Resolves each question against a run. A question whose event does not exist in this run (an
// index past its last event, or no collision at all), or that names a ball the run lacks, is not
// asked: *problems (when given) gets one line per such question ("question 2: the shot has only 5
// events"). The result is in time order (questions on the same event keep their file order).
std::vector<AskedQuestion> askedQuestions(const std::vector<PredictQuestion>& questions, const SimulationResult& result,
                                          std::vector<std::string>* problems = nullptr);

// The event a question without an event stops before: the first ball-ball collision, else the
// first collision of any kind; -1 when the run has none.
int firstCollisionEvent(const SimulationResult& result);

// Where ball `ball` goes after event `event` (see the header comment): a unit direction in the table
// frame as a heading (degrees, 0 = +x, counter-clockwise), or nullopt when it stays.
std::optional<double> actualHeading(const SimulationResult& result, int event, int ball);

// A student's answer for one ball: a heading (degrees, 0 = +x, counter-clockwise), "stays"
// (nullopt), or no answer at all.
struct BallPrediction {
    bool answered = false;
    std::optional<double> headingDeg;
};

enum class Verdict { SpotOn, Close, Off, Right, Wrong, NoAnswer };
// Right/Wrong: the "stays" answers; SpotOn/Close/Off: within kSpotOnDeg, within kCloseDeg, beyond.

struct BallReveal {
    int ball = -1;
    BallPrediction predicted;
    std::optional<double> actualDeg;  // nullopt: the ball stays
    std::optional<double> errorDeg;   // only when both are directions
    double score = 0.0;               // 0 to 1
    Verdict verdict = Verdict::NoAnswer;
};

// The smaller angle between two headings, in degrees (0 to 180).
double angleBetween(double headingA, double headingB);
// One ball's reveal from its prediction and where it actually went.
BallReveal scoreBall(int ball, const BallPrediction& predicted, std::optional<double> actualDeg);
// Every asked ball of a question (predictions in the order of question.balls; missing = no answer).
std::vector<BallReveal> reveal(const AskedQuestion& question, const std::vector<BallPrediction>& predictions,
                               const SimulationResult& result);
// The mean score of the balls (0 when there are none).
double questionScore(const std::vector<BallReveal>& balls);

}  // namespace cuelab::lesson
