#pragma once
// A cue strike at t = 0 (Alciatore, technical proof A-30). Angles are kept in degrees, exactly as
// they stand in a setup file, so that a save/load round trip cannot perturb them.

#include <string>

namespace cuelab {

struct CueStrike {
    std::string ball;          // id of the struck ball
    double speed = 3.0;        // m/s, cue speed V0
    double headingDeg = 0.0;   // degrees, 0 = +x, counter-clockwise positive
    double elevationDeg = 0.0; // degrees above the cloth
    double side = 0.0;         // tip offset / R, + = right of centre as the player sees it
    double height = 0.0;       // tip offset / R, + = above centre
    double cueMass = 0.567;    // kg
    // kg, the cue tip's "end mass" that squirts the ball (Alciatore TP A-31; pooltool uses m/30, about
    // 5.7 g for a pool ball). 0 = no squirt: the ball leaves along the cue line, as before squirt
    // existed (a file asks for squirt with the shot key "end_mass").
    double endMass = 0.0;
};

}  // namespace cuelab
