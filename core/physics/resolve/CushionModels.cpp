// The registry of ball-cushion models: the one place that maps a model to its resolver, its name in
// files and its parameters. A new model is a new file in this folder and one row below.

#include "resolve/CushionModel.h"
#include "resolve/Han2005Cushion.h"
#include "resolve/Mathavan2010Cushion.h"
#include "resolve/MirrorCushion.h"
#include "resolve/StrongeCushion.h"

#include <array>

namespace cuelab {

namespace {

const std::array kMathavanParameters{
    CushionModelParameter{"steps",
                          "Impulse steps of the numerical integration over one impact (a whole number, 10 to 1000000; "
                          "1000 by default, the paper used 5000). The cloth friction during the impact is μ slide.",
                          &PhysicsParams::mathavanSteps, 10.0, 1e6, false, false, true, 100.0, 0},
};
const std::array kStrongeParameters{
    CushionModelParameter{"omega_ratio",
                          "Ratio of the tangential to the normal frequency of the contact's springs (dimensionless, "
                          "between 1 and 2, bounds excluded; 1.8 as pooltool)",
                          &PhysicsParams::strongeOmegaRatio, 1.0, 2.0, true, true, false, 0.01, 3},
};

const std::array kModels{
    CushionModelEntry{BallCushionModel::Mirror, "mirror", "Mirror",
                      "a plain reflection with restitution; the spin is left alone (the 2011 method)", false,
                      &mirrorCushion, {}},
    CushionModelEntry{BallCushionModel::Han2005, "han2005", "Han 2005",
                      "one impulse at the cushion contact above the equator, with Coulomb friction (Han 2005)", true,
                      &han2005Cushion, {}},
    CushionModelEntry{BallCushionModel::Mathavan2010, "mathavan2010", "Mathavan 2010",
                      "the impact integrated over its impulse, with friction at the cushion and on the cloth (Mathavan et al. 2010)",
                      true, &mathavan2010Cushion, kMathavanParameters},
    CushionModelEntry{BallCushionModel::Stronge, "stronge", "Stronge compliant",
                      "normal and tangential springs at the contact: the ball can slip, stick and spring back (Stronge 2000)",
                      true, &strongeCushion, kStrongeParameters},
};

}  // namespace

std::span<const CushionModelEntry> cushionModels() { return kModels; }

const CushionModelEntry& cushionModel(BallCushionModel model)
{
    for (const CushionModelEntry& e : kModels)
        if (e.model == model) return e;
    return kModels.back();  // unreachable: every enumerator has a row (tested)
}

const CushionModelEntry* findCushionModel(std::string_view name)
{
    for (const CushionModelEntry& e : kModels)
        if (e.name == name) return &e;
    return nullptr;
}

}  // namespace cuelab
