#pragma once
// A recorded shot (CONTRACT.md, Extensions version 2: `cuelab-recording`): each ball's tracked
// centre at known times, in the table frame of PHYSICS.md (metres, seconds from the first sample).
// A plain value; files are read by core/io (RecordingFile.h), checked here (recordingProblem).

#include "Table.h"
#include "Types.h"

#include <optional>
#include <string>
#include <vector>

namespace cuelab {

struct RecordedSample {
    double time = 0.0;             // s, from the recording's start
    Vec2 position = Vec2::Zero();  // m, the ball's centre in the table frame
};

struct RecordedBall {
    std::string id;                 // matches a setup ball's id
    std::optional<double> radius;   // m; the table kind's ball when absent
    std::vector<RecordedSample> samples;  // times strictly increasing, at least two
};

struct Recording {
    std::string name;
    std::string source;  // where and how it was tracked
    TableSpec table;     // default: a 9-ft pool table, as for a setup
    std::vector<RecordedBall> balls;

    const RecordedBall* ball(const std::string& id) const;
    double duration() const;  // s, the latest sample time of any ball (0 without samples)
};

// What is wrong with a recording and where: the JSON path of the culprit ("balls[1].samples[7]")
// and a sentence a person can act on. The CSV reader names the line instead.
struct RecordingProblem {
    std::string path;
    std::string message;
};

// The first problem of a recording's values, nullopt when it is usable: no balls, an empty or
// repeated id, a radius <= 0, fewer than two samples, a time not finite or not after the one before
// it, a centre beyond the playing surface of its table (more than kOffTableTolerance outside
// [0, length] x [0, width]: tracked centres lie at least a radius inside the cushion noses, so a
// centre beyond a nose is a tracking error or the wrong table).
inline constexpr double kOffTableTolerance = 0.005;  // m, tracking noise allowed beyond a nose
std::optional<RecordingProblem> recordingProblem(const Recording& recording);

// How far a ball must get from its first sample to count as moved: well above tracking noise (about
// a centimetre in the carom data of ../shared/data/recordings) and below any real shot's travel.
inline constexpr double kMovedDistance = 0.03;  // m

// The time of a ball's first sample farther than kMovedDistance from its first sample; nullopt when
// it never moves so far.
std::optional<double> firstMoveTime(const RecordedBall& ball);

// Whether the ball moved in the recording (firstMoveTime has a value).
bool moved(const RecordedBall& ball);

// The index of the ball that moves first (the struck one), nullopt when none moves. Ties go to the
// ball listed first.
std::optional<std::size_t> firstBallToMove(const Recording& recording);

}  // namespace cuelab
