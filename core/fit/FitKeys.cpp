#include "FitKeys.h"

#include <algorithm>
#include <cmath>

namespace cuelab::fit {

std::vector<std::string> defaultStrikeKeys() { return {"shot.heading", "shot.speed", "shot.side", "shot.height"}; }

bool isTipKey(const std::string& key) { return key == "shot.side" || key == "shot.height"; }

std::variant<std::vector<FitKey>, analysis::OverrideError> resolveFitKeys(const Setup& setup,
                                                                          const std::vector<std::string>& keys)
{
    std::vector<FitKey> out;
    for (const std::string& key : keys) {
        auto resolved = analysis::Parameter::resolve(setup, key);
        if (auto* error = std::get_if<analysis::OverrideError>(&resolved)) return *error;
        analysis::Parameter p = std::get<analysis::Parameter>(std::move(resolved));
        if (!p.isNumber())
            return analysis::OverrideError{analysis::OverrideError::Kind::BadValue, key,
                                           "key \"" + key + "\" is not a number and cannot be fitted"};
        for (const FitKey& k : out)
            if (k.parameter.key() == key)
                return analysis::OverrideError{analysis::OverrideError::Kind::BadValue, key,
                                               "key \"" + key + "\" is named twice"};
        const double x = p.number(setup);
        FitKey k{std::move(p)};
        if (key == "shot.heading") {
            k.lower = x - 30.0;
            k.upper = x + 30.0;
            k.step = 1.0;
        } else if (key == "shot.speed") {
            k.lower = 0.05;
            k.upper = std::max(12.0, 3.0 * x);
            k.step = 0.05 * std::max(x, 0.5);
        } else if (isTipKey(key)) {
            k.lower = -0.8;
            k.upper = 0.8;
            k.step = 0.1;
        } else if (key == "shot.elevation") {
            k.lower = 0.0;
            k.upper = 60.0;
            k.step = 2.0;
        } else if (key.ends_with("restitution")) {
            k.lower = 0.3;
            k.upper = 1.0;
            k.step = 0.03;
        } else if (x > 0.0) {
            k.lower = x / 5.0;
            k.upper = x * 5.0;
            k.step = 0.1 * x;
        } else {
            k.lower = x - 1.0;
            k.upper = x + 1.0;
            k.step = 0.1;
        }
        out.push_back(std::move(k));
    }
    return out;
}

}  // namespace cuelab::fit
