#pragma once
// What `fit` and `calibrate` share: reading the options they have in common (--fit, --calibrate,
// --balls, --jobs), reading a recording and the setup it is fitted in, and the JSON of one fit.

#include "Command.h"

#include "Calibration.h"
#include "JsonText.h"
#include "Recording.h"
#include "StrikeFit.h"

#include <optional>
#include <string>
#include <vector>

namespace cuelab::cli {

struct FitArguments {
    std::vector<std::string> fitKeys;        // --fit (default: the strike)
    std::vector<std::string> calibrateKeys;  // --calibrate
    BallSelection balls = BallSelection::Moved;
    int jobs = 0;
};

// Parses --fit, --calibrate, --balls and --jobs; a usage error is printed and *status set.
std::optional<FitArguments> fitArguments(const Invocation& in, int* status);

// One recording and the setup it is fitted in: the file of --setup (its table also the CSV's) or
// the setup made from the recording, then --set. Refusals printed, *status set (1, or 2 for --set).
struct FitInput {
    QString name;  // the recording's file name, as messages name it
    Recording recording;
    Setup setup;
};
std::optional<FitInput> loadFitInput(const Invocation& in, const QString& recordingPath, const QString& setupPath,
                                     int* status);

// Resolves keys against a setup; a usage error (printed, *status = 2) when one is unknown.
std::optional<std::vector<fit::FitKey>> fitKeys(const Invocation& in, const Setup& setup,
                                                const std::vector<std::string>& keys, const char* option, int* status);

// The members of one fit's object: "rmse", "per_ball", "fitted", "evaluations", "seconds" (the
// contract's), then "rmse_struck", "rmse_all", "balls", "struck_ball".
void writeFit(io::JsonWriter& w, const fit::FitResult& result, BallSelection balls);

}  // namespace cuelab::cli
