#pragma once
// Physics parameters in SI units, defaults from ../shared/PHYSICS.md (sources cited per value).

#include <cstdint>
#include <string_view>

namespace cuelab {

enum class BallBallModel : std::uint8_t {
    Frictionless,  // normal impulse with restitution only; spins unchanged
    Frictional,    // plus a tangential impulse (throw), Coulomb-limited
};
enum class BallBallFriction : std::uint8_t {
    Fixed,      // mu_b = PhysicsParams::ballBallFriction
    Alciatore,  // mu_b(v_rel) = 9.951e-3 + 0.108 exp(-1.088 v_rel)  (Alciatore TP A-14)
};
enum class BallCushionModel : std::uint8_t {
    Mirror,   // v' = v - (1 + e)(v.N)N, spins unchanged (the 2011 method)
    Han2005,  // Han 2005, contact above the equator, Coulomb friction
    Mathavan2010,  // Mathavan et al. 2010: cushion and cloth contacts, integrated over the impulse
    Stronge,       // Stronge's compliant frictional impact (normal and tangential springs)
};
// Each model's resolver, name and parameters: resolve/CushionModel.h (the registry).
enum class BallTableModel : std::uint8_t {
    Frictional,    // restitution and Coulomb friction with the cloth (pooltool's frictional_inelastic)
    Frictionless,  // restitution only: the horizontal velocity and the spin go through unchanged
};
// Each model's resolver, name and parameters: resolve/TableModel.h (the registry).

std::string_view toString(BallBallModel m);     // "frictionless" | "frictional"
std::string_view toString(BallCushionModel m);  // its name in files (resolve/CushionModel.h)
std::string_view toString(BallTableModel m);    // its name in files (resolve/TableModel.h)

struct PhysicsParams {
    double gravity = 9.81;        // m/s^2
    double muSlide = 0.2;         // sliding friction ball-cloth (Alciatore; 0.15-0.4)
    double muRoll = 0.01;         // rolling resistance (Alciatore, pooltool; 0.005-0.015)
    double muSpin = 0.0127;       // spin friction about z, alpha = 5 mu g / (2R) ~ 10.9 rad/s^2 (pooltool)

    BallBallModel ballBallModel = BallBallModel::Frictionless;
    double ballBallRestitution = 0.95;                        // (Alciatore, pooltool; 0.92-0.98)
    BallBallFriction ballBallFrictionKind = BallBallFriction::Fixed;
    double ballBallFriction = 0.05;                           // mu_b when Fixed (pooltool)

    BallCushionModel ballCushionModel = BallCushionModel::Han2005;
    double cushionRestitution = 0.85;                         // (Alciatore, pooltool; 0.6-0.9)
    double cushionFriction = 0.2;                             // (pooltool)
    // mathavan2010 only: impulse steps over the expected normal impulse (a whole number). The paper
    // found 5000 satisfactory; 1000 keeps the error below 1e-3 of the rebound speed (tested).
    double mathavanSteps = 1000.0;
    // stronge only: omega_t / omega_n, the ratio of the tangential to the normal frequency of the
    // contact's springs, in (1, 2) (pooltool's omega_ratio; 1.8, PHYSICS.md).
    double strongeOmegaRatio = 1.8;

    // A ball landing on (or driven into) the cloth: CONTRACT.md physics.ball_table, PHYSICS.md
    // "Airborne balls". Not read by the simulator yet (docs/airborne.md, the plan to wire it in).
    BallTableModel ballTableModel = BallTableModel::Frictional;
    double tableRestitution = 0.5;  // e of a bounce on the cloth (Alciatore's table of properties, pooltool e_t)
    double tableFriction = 0.2;     // mu between ball and cloth during a bounce (pooltool uses mu_s = 0.2)
};

}  // namespace cuelab
