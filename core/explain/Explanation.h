#pragma once
// The derivation of one event of a simulation, as plain data: ordered steps (each a law in words, a
// formula, named inputs and named results), the time-of-impact polynomial of collisions and pockets,
// and the bodies' states, energies and momenta before and after. Built by explain() (Explain.h) from
// the simulator's own functions, so every result equals the simulator's number; rendered for people
// by ExplainText.h (Markdown, HTML) and as JSON by `cuelab-cli explain`.
//
// Formulas and symbols use a small markup that every renderer understands: `_{...}` a subscript,
// `^{...}` a superscript (a single character needs no braces: `v_a`, `τ^2`); everything else is
// plain Unicode text (Greek letters, ·, ×, √, ′).
//
// Every word a person reads is a Text (Text.h): an English template and its arguments, which the
// command-line tool prints in English and the window in its own language.

#include "Event.h"
#include "Text.h"
#include "Types.h"

#include <optional>
#include <string>
#include <vector>

namespace cuelab::explain {

struct Quantity {
    std::string key;     // unique within its list, ASCII (a JSON key): "v_a_x", "P_n", "mu_b"
    Text symbol;         // markup for people: "v_{a,x}", "P_n", "μ_b" (a word, such as "steps", translated)
    double value = 0.0;
    std::string unit;    // "m/s", "N s", "" for a pure number
    // The size of what the value is compared with (a vector's length for its components, the
    // energy before for a change of energy): a value within 1e-12 of it is rounding noise, which a
    // person reads as 0 (JSON keeps the exact value). 0: the value alone.
    double scale = 0.0;
};

struct Step {
    Text title;    // "Normal impulse"
    Text law;      // the law in words
    Text formula;  // markup (a literal, unless it holds words)
    std::vector<Quantity> inputs;
    std::vector<Quantity> results;

    const Quantity* result(const std::string& key) const;
    const Quantity* input(const std::string& key) const;
};

// One real root of the time-of-impact polynomial and whether it can be the contact.
struct ToiRoot {
    double tau = 0.0;        // s, from t0
    bool inWindow = false;   // 0 < tau <= horizon (the polynomial describes the motion there)
    bool closing = false;    // f'(tau) < 0: the bodies approach (a root where they part is passed over)
    bool onSegment = true;   // a straight cushion only: the contact lies between the segment's ends
    bool chosen = false;     // the root that gave the event
};

// f(tau) = c0 + c1 tau + ... + c4 tau^4, tau = t - t0: the gap function whose root is the contact.
struct TimeOfImpact {
    Text gap;                          // markup: what f measures
    std::string unit = "m²";           // f's unit (a squared distance, or a distance: "m")
    double t0 = 0.0;                   // s, the common start of the bodies' present closed-form paths
    std::vector<double> coefficients;  // c0, c1, ... lowest degree first, trailing zeros dropped
    double horizon = 0.0;              // s from t0: where the paths end (the next transition); may be inf
    double root = 0.0;                 // s, the chosen tau: t0 + root is the event time
    bool touching = false;             // the bodies touched at t0 and approached: contact at tau = 0
    bool rootOfF = true;               // the chosen tau is a root of f (not: touching, or a segment's end)
    std::vector<ToiRoot> roots;        // every real root, ascending
    Text why;                          // why this root, in words

    double at(double tau) const;       // f(tau)
    double slopeAt(double tau) const;  // f'(tau)
};

// A body of the event, for the momenta diagram, the energy bars and the arrows in the table view.
struct Body {
    int ball = -1;
    std::string id;
    double mass = 0.0, radius = 0.0;
    BallState before, after;
    double translationBefore = 0.0, rotationBefore = 0.0;  // J
    double translationAfter = 0.0, rotationAfter = 0.0;    // J
    // J, just after the ball's previous event (or as set up): the cloth took this minus the energy
    // before the event since then (core/aim/Frames.h, energyParts).
    double energyAfterPrevious = 0.0;
    Vec2 momentumBefore() const { return mass * before.velocity; }  // N s
    Vec2 momentumAfter() const { return mass * after.velocity; }
};

struct Explanation {
    int event = -1;
    EventKind kind = EventKind::CueStrike;
    double time = 0.0;              // s
    Text title;                     // "Ball-ball collision of cue and 1"
    Text model;                     // the collision model used ("frictionless", "han2005", ...), or empty
    std::vector<Step> steps;
    std::optional<TimeOfImpact> toi;
    std::vector<Body> bodies;       // the event's balls, in the event's order
    // Collisions and the cue strike: where the bodies touch, the normal (from the first ball towards
    // the other body, or the cue's heading) and the impulse on the first ball, as the event holds them.
    bool hasContact = false;
    Vec2 contactPoint = Vec2::Zero();  // m
    Vec2 normal = Vec2::Zero();
    Vec3 impulse = Vec3::Zero();       // N s

    const Step* step(const std::string& name) const;  // by its English title
};

}  // namespace cuelab::explain
