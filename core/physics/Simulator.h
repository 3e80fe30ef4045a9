#pragma once
// Internal to the simulator (not installed, not for other modules): the event loop's state and its
// steps. Simulator.cpp holds the event loop and the predictions, HeldContacts.cpp the groups of held
// contacts (Contact.h), Simulation.cpp the public entry points.

#include "Simulation.h"

#include "AirImpacts.h"
#include "AirborneDetection.h"
#include "BallBallCollision.h"
#include "BallContact.h"
#include "BroadPhase.h"
#include "Contact.h"
#include "ContactTrace.h"
#include "CueImpact.h"
#include "CushionCollision.h"
#include "Detection.h"
#include "EventQueue.h"
#include "BounceSeries.h"
#include "Motion.h"

#include <functional>
#include <optional>
#include <stop_token>
#include <vector>

namespace cuelab::detail {

// m: how far ahead a moving ball's pair predictions look. Predicting pairs only over the next
// kLookahead of travel keeps the box of each ball small, so the grid and the boxes cull almost
// every pair even on a large table with many balls; the price is one internal refresh per
// kLookahead travelled.
constexpr double kLookahead = 1.0;

// m: side of the broad-phase grid's cells, about half the longest window of a moving ball.
constexpr double kCellSize = 0.5;

// A flying ball on a jaw's rim (AirHold.cpp): its contact with the rim as a row of a held group
// (settle) and its gap and normal speed; false when there is no rim there.
bool airRimGeometry(const JawTip& jaw, double R, double h, const BallState& s, ContactLink& link, double& gap, double& vn);

class Simulator {
public:
    // `limit`: s, the time the run ends at if balls still move; the options give the event cap,
    // cancellation and progress.
    Simulator(SimulationResult& result, double limit, const SimulationOptions& options)
        : r_(result), table_(result.table), p_(result.physics), n_(static_cast<int>(result.balls.size())),
          limit_(limit), maxEvents_(options.maxEvents), strikeKeepsElevation_(options.strikeKeepsElevation),
          cancel_(options.cancel), progress_(options.progress), progressInterval_(options.progressInterval)
    {
        init();
    }

    void run(const std::optional<CueStrike>& shot);
    // Records the solves of held groups (ContactTrace.h) into `sink`; null (the default): none.
    void traceHeld(HeldTraceSink* sink) { heldTrace_ = sink; }

private:
    void init()
    {
        const std::size_t n = static_cast<std::size_t>(n_);
        start_.assign(n, 0.0);
        state_.resize(n);
        path_.resize(n);
        end_.assign(n, kNever);
        box_.resize(n);
        own_.resize(n);
        horizon_.assign(n, kNever);
        window_.resize(n);
        pair_.assign(n * n, kNever);
        partners_.assign(n, {});
        rowMin_.assign(n, kNever);
        rowPartner_.assign(n, -1);
        push_.assign(n, Vec2::Zero());
        heldCount_.assign(n, 0);
        regroupAt_.assign(n, kNever);
        quietSolves_.assign(n, 0);
        quietSince_.assign(n, 0.0);
        pushZ_.assign(n, 0.0);
        airHeld_.assign(n, -1);
        airLetGo_.assign(n, kNever);
        airLetGoOf_.assign(n, -1);
        airRide_.assign(n, -1);
        airRideSegments_.assign(n, 0);
        airRidePartnerSegments_.assign(n, 0);
        airEdgeLetGo_.assign(n, kNever);
        airEdgeLetGoOf_.assign(n, -1);
        airEdge_.assign(n, -1);
        series_.assign(n, 0);
        seriesOf_.resize(n);
        airContact_.resize(n);
        bounces_.assign(n, 0);
        queue_.reset(n_);
        double margin = 0.0;  // pockets and jaws lie beyond the cushion noses
        for (const Pocket& k : table_.pockets) margin = std::max(margin, k.radius);
        margin += 0.1;
        grid_.reset(Vec2(-margin, -margin), Vec2(table_.length + margin, table_.width + margin), kCellSize, n_);
        r_.timelines.assign(n, {});
        // Room for a typical run, so that the event loop rarely allocates.
        for (std::size_t i = 0; i < n; ++i) {
            r_.timelines[i].reserve(16);
            partners_[i].reserve(8);
        }
    }
    // The run stops here, unfinished (EventLimit or Cancelled), with the events up to `lastEvent`.
    void stopUnfinished(SimulationStatus status, double lastEvent, const std::string& why);
    double radius(int i) const { return r_.balls[static_cast<std::size_t>(i)].radius; }
    double mass(int i) const { return r_.balls[static_cast<std::size_t>(i)].mass; }
    std::size_t at(int i) const { return static_cast<std::size_t>(i); }
    double& pair(int i, int j) { return pair_[at(i) * at(n_) + at(j)]; }

    BallState stateNow(int i, double t) const
    {
        if (series_[at(i)]) return seriesStateAt(seriesOf_[at(i)], t - start_[at(i)]);
        if (heldFlight(i)) return flyHeld(state_[at(i)], p_.gravity, push3(i), t - start_[at(i)]);
        return evolve(state_[at(i)], radius(i), p_, t - start_[at(i)], push_[at(i)]);
    }
    Path pathNow(int i, double t) const;
    void beginSegment(int i, double t, const BallState& s, const Vec2& push = Vec2::Zero());
    // A ball's new segment at t finds it at rest after moving: it came to rest then (at an event, or
    // at a group's solve that finds it still).
    void noteStop(MotionState was, MotionState is, double t);
    void predictOwn(int i, double now);
    void predictPairs(int i, double now);
    void rescanRow(int j);
    void updateQueue(int i);
    double pairTime(int i, int j, double now) const;
    void process(const Candidate& c);
    bool atRest(int i) const;

    // Airborne balls (AirborneLoop.cpp; docs/airborne.md).
    bool flying(int i) const { return state_[at(i)].motion == MotionState::Airborne; }
    // A flying ball's own contacts before its landing: pockets it lands in, cushion faces and noses,
    // the rail it clears, jaws. `best` holds the landing on entry.
    void predictAirContacts(int i, double now, const Path& p, Candidate& best);
    // A pair with a flying ball (neither in a bounce series): the first contact in space.
    double airPairTime(int i, int j, double now) const;
    // Flying ball a rides out a nanometre hop beside b (airBallBall): the pair is not met while
    // neither begins a segment.
    bool riding(int a, int b) const;
    // A pair with a ball in a bounce series: `now` when the other may come near the series (the series
    // is then split into its flights, splitSeries), else kNever.
    double seriesPairTime(int i, int j, double now) const;
    // The box of what is left of ball i's bounce series: where its centre can be until it ends.
    Box seriesBox(const SeriesTail& tail) const;
    // Nothing can meet ball i during the series `b` begun now (conservative: cushions, jaws, pockets,
    // every other ball as far as it can move until the series ends or its own next event).
    bool seriesIsolated(int i, const BounceSeries& b, double now) const;
    // Ball j cannot come near ball i's series tail (which ends at `end`) before j's next event.
    bool seriesClear(int i, const SeriesTail& tail, double end, int j, double now) const;
    void beginSeries(int i, double t, const BallState& landing, const BounceSeries& b);
    void land(int i, double t);       // the landing of a flight: a bounce, or a whole series
    bool overCloth(const Vec2& centre) const;  // a centre coming down here lands on the cloth
    void endSeries(int i, double t);  // the series' closed-form end: on the cloth for good
    void splitSeries(int i, double t);  // the series goes on as one flight at a time (no event)
    void airCushion(const Candidate& c, Event& e);  // face, nose, jaw or off the table
    void airBallBall(const Candidate& c, Event& e);
    // A flying ball coming down on a ball on the cloth that the law leaves parting slower than
    // kHoldSpeed: held (the hold rule in the air, AirHold.cpp); false, and nothing changed, when not.
    bool airHoldRule(Event& e, const AirBallBallResult& res);
    void strike(int i, const CueStrike& shot);

    // A flying ball held against a ball on the cloth it presses on with no approach (AirHold.cpp;
    // docs/airborne.md, "Held in the air").
    bool heldFlight(int i) const { return flying(i) && (pushZ_[at(i)] != 0.0 || !push_[at(i)].isZero(0.0)); }
    Vec3 push3(int i) const { return Vec3(push_[at(i)].x(), push_[at(i)].y(), pushZ_[at(i)]); }
    // Ball i's centre in space from `now`: its flight (held or free) or its path on the cloth.
    SpacePath spaceNow(int i, double now) const;
    // Flying ball a and ball b on the cloth may be held together: neither is held by the cloth, in a
    // bounce series or held in the air with a third ball.
    // (`onCloth`: b's state to be held is on the cloth whatever its segment says, a hop the cloth
    // takes, airBallBall's hold rule.)
    bool airHoldable(int a, int b, bool onCloth = false) const;
    // A flying ball a pressed on a ball b (on the cloth or flying) that a group holds (or a itself held
    // on one): their contact joins the group (settle) as a row in space.
    bool groupHoldable(int a, int b) const;
    // Solves the pair at t and begins its held segments; false (and nothing changed) when it is not
    // pressed, has parted or cannot be held.
    bool airHold(int a, int b, double t);
    // The same from the states sa, sb at t (a collision's result: airBallBall's hold rule); b's is on
    // the cloth.
    bool airHold(int a, int b, double t, BallState sa, BallState sb, bool onCloth);
    // Ends ball i's hold in the air at t: both balls go on freely from their states then (no event),
    // but `keep` and `keep2` (an event's balls, whose event at t ends their segments) keep theirs.
    void airRelease(int i, double t, int keep = -1, int keep2 = -1);
    void beginHeldFlight(int i, double t, const BallState& s, const Vec3& push);
    // A flying ball held on cushion k's nose edge (it would bounce on it ever lower, a Zeno run): from
    // its state `s` at t; false (nothing changed) when the edge does not press it or it is off the edge.
    bool airEdgeHold(int a, int k, double t, const BallState& s);
    // A flying ball's contact with a nose edge as a row of a held group (settle): its link (normal from
    // the centre to the edge, tilted: ContactLink::nz; the curvature of its motion about the edge),
    // gap and relative normal speed (> 0 parting); false when its foot is off the segment (past
    // kContactTolerance, as detection) or it is not above the nose in front of the nose line.
    bool airEdgeGeometry(int a, const CushionSegment& seg, const BallState& s, ContactLink& link, double& gap, double& vn) const;
    // The same on jaw k's rim (the circle at the nose height): airEdge_ is then cushions + k.
    bool airRimHold(int a, int k, double t, const BallState& s);
    // Ball a, held on a fixed edge or rim from t, is solved again after `limit` (at least 1e-9 s).
    void heldFixedUntil(int a, double t, double limit);
    bool airHeldAny(int i) const { return airHeld_[at(i)] >= 0 || airEdge_[at(i)] >= 0; }

    // Sustained contact (Contact.h).
    bool heldPair(int i, int j) const;
    bool heldWall(int i, ContactBody body, int index) const;
    // After an event: solves the held group its balls belong to (with a contact that may begin
    // holding, `candidate`, whose bodies carry its collision law's after-states) and gives every ball
    // of that group its new segment.
    enum class Settled {
        Untouched,   // no held group is touched and there is no candidate: the caller segments freely
        Held,        // settled; the candidate (if any) is held
        NotPressed,  // the candidate is not pressed and touches no held group: nothing changed
        SeatedOnly,  // the candidate is not pressed: settled with the group it touches, not held
    };
    // `regroup` (>= 0): a ball whose group is solved again with no event (a frozen direction has
    // turned far enough).
    // `noEvent`: the solve logs no event of its own (a frozen direction has turned: `regroup`, or a
    // pushed state ended without changing its label), so it counts towards a quiet stretch
    // (Contact.h's kQuietSolves).
    Settled settle(double t, const std::vector<int>& eventBalls, const std::vector<BallState>& eventStates,
                   const HeldContact* candidate, bool forceHold, int regroup = -1, bool noEvent = false);
    // The end of a traced settle() (HeldTrace.cpp): what it left, handed to heldTrace_ for `event`.
    void recordHeldTrace(HeldGroupTrace& trace, int event, bool seated, const std::vector<ContactBall>& balls,
                         const std::vector<char>& heldRows, const std::vector<char>& kept, const std::vector<char>& idle);
    void finishEvent(double t, const Event& e);
    // A collision whose law parts its bodies slower than kHoldSpeed (Contact.h's hold rule): logs the
    // event with its hold and settles the group; false when the law's result stands alone (the
    // caller finishes the event as any other).
    bool holdCollision(const Event& e, const HeldContact& candidate, double separation);
    // A held group's quiet stretch (Contact.h's kQuietSolves): counts the solve of `members` at t
    // (`quiet`: without an event of its own; else the stretch ends) and returns the floor of its
    // accuracy limits, 0 within the budget.
    double quietFloor(double t, const std::vector<int>& members, bool quiet);
    // `accuracyFloor` (s): the accuracy limits (turns of frozen directions and normals) are taken no shorter
    // than this (a quiet stretch, Contact.h's kQuietSolves); the limits that keep contacts sound are not.
    double turnLimit(double t, const std::vector<int>& members, const std::vector<HeldContact>& contacts,
                     double accuracyFloor = 0.0) const;

    SimulationResult& r_;
    const Table& table_;
    const PhysicsParams& p_;
    int n_;
    double limit_;
    long long maxEvents_;
    bool strikeKeepsElevation_ = false;  // SimulationOptions::strikeKeepsElevation
    std::stop_token cancel_;             // SimulationOptions::cancel
    std::function<void(const SimulationResult&, const SimulationProgress&)> progress_;
    double progressInterval_ = 0.1;      // s of wall time between progress_ calls

    // Flat per-ball arrays: the current motion segment and its predictions.
    std::vector<double> start_;      // s, when the segment began
    std::vector<BallState> state_;   // the state at start_
    std::vector<Path> path_;         // position over the segment, from start_
    std::vector<double> end_;        // s, absolute time of the transition that ends the segment
    std::vector<Box> box_;           // where the centre can be during the segment
    std::vector<Candidate> own_;     // next transition, pocket, cushion or jaw event, or refresh
    std::vector<double> horizon_;    // s, absolute end of the ball's prediction window
    std::vector<Box> window_;        // where the centre can be from the last prediction to horizon_
    std::vector<double> pair_;       // n x n, next contact time of each pair (symmetric), kNever if none
    std::vector<std::vector<int>> partners_;  // per ball, the balls it may have a finite pair_ with
    std::vector<double> rowMin_;     // per ball, the earliest of its row of pair_
    std::vector<int> rowPartner_;    // and the partner (the smallest index among ties)
    BoxGrid grid_;
    EventQueue queue_;

    std::vector<Vec2> push_;          // m/s^2, the contact force over the mass of a held ball's segment
    HeldTraceSink* heldTrace_ = nullptr;  // ContactTrace.h; null in a normal run
    std::vector<HeldContact> held_;   // the contacts held now, in the order they were formed
    std::vector<int> heldCount_;      // per ball, how many of held_ involve it
    std::vector<double> regroupAt_;   // s, when a held group is solved again (kNever if none)
    // Per ball: how many times in a row its held group was solved again without an event (a quiet
    // stretch, Contact.h's kQuietSolves), and since when (s).
    std::vector<int> quietSolves_;
    std::vector<double> quietSince_;
    // The other members whose state the last settle() changed (Event::group), for its event.
    std::vector<Event::GroupChange> lastGroupChanges_;
    double lastStop_ = 0.0;           // s, the last time a ball's new segment found it at rest after moving
    std::size_t lastGroupSize_ = 0;   // how many contacts the last settle() solved
    // Airborne balls: the ball's segment is a bounce series (seriesOf_ holds it), the contact with the
    // cushion its own prediction found (kind and normal), and how many bounces in a row it took as
    // single events.
    std::vector<char> series_;
    std::vector<BounceSeries> seriesOf_;
    std::vector<AirCushionContact> airContact_;
    std::vector<int> bounces_;
    std::vector<double> pushZ_;   // m/s^2, the vertical part of a held flight's contact force per mass
    std::vector<int> airHeld_;    // the ball it is held with in the air (AirHold.cpp), -1 if none
    std::vector<double> airLetGo_;  // s, when its last hold in the air with a ball ended (kNever if none)
    std::vector<int> airLetGoOf_;   // the ball it was held with then
    // A nanometre hop left touching a ball with no force and no impulse, riding out its flight to its
    // own landing (airBallBall): that ball, -1 if none, and both timelines' lengths then (the ride
    // lasts while neither ball begins a segment).
    std::vector<int> airRide_;
    std::vector<std::size_t> airRideSegments_;
    std::vector<std::size_t> airRidePartnerSegments_;
    std::vector<double> airEdgeLetGo_;  // s, when its last hold on a nose edge or rim ended (kNever if none)
    std::vector<int> airEdgeLetGoOf_;   // that edge (airEdge_'s numbering)
    std::vector<int> airEdge_;    // the cushion whose nose edge holds it in the air (cushions + k: jaw k's rim), -1 if none
    double lastCandidateImpulse_ = 0.0;  // N s, the last settle()'s re-seating impulse at its candidate
                                         // (> 0 pushing apart, < 0 drawing together: the hold)
};

// The kind of a pushed state's end, when its label changes (false when the push only turned it).
bool pushedTransitionKind(MotionState before, MotionState after, EventKind& kind);

}  // namespace cuelab::detail
