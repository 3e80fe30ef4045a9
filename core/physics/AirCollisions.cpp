// A flying ball's collisions (issue 23; docs/airborne.md, "Wired into the event loop" and "Held in
// the air"): with a cushion's face, nose edge or end, a jaw's side, top or rim (airCushion), and
// with another ball (airBallBall), by the laws of AirImpacts.h, and the holds a contact that the law
// leaves pressed begins instead: pairwise in the air (AirHold.cpp) or as rows in space of a held
// group (HeldContacts.cpp). Split from AirborneLoop.cpp, whose predictions find these events.

#include "Simulator.h"

#include "AirImpacts.h"

#include <algorithm>
#include <cmath>

namespace cuelab::detail {

void Simulator::airCushion(const Candidate& c, Event& e)
{
    const int i = c.ball;
    const double R = radius(i);
    const BallState& before = e.before[0];
    Vec3 normal;  // from the body towards the centre
    if (c.agent == Agent::Cushion && c.index < 0) {
        // Its centre leaves the table's outline beyond a pocket (outlineExitTime): out of play there.
        e.kind = EventKind::BallOffTable;
        e.after[0] = BallState{};
        e.after[0].position = before.position;
        e.after[0].z = before.z;
        e.after[0].motion = MotionState::OffTable;
        e.contactPoint = before.position;
        finishEvent(e.time, e);
        return;
    }
    if (c.agent == Agent::Cushion) {
        const CushionSegment& seg = table_.cushions[at(c.index)];
        const AirCushionContact& contact = airContact_[at(i)];
        e.cushion = c.index;
        if (contact.kind == CushionContactKind::OffTable) {
            // Over a pocket's circle with its bottom below the rail's top it met the rail's end (or
            // top) inside the pocket: it drops in. (Higher up it clears the rail, as below.)
            for (std::size_t k = 0; k < table_.pockets.size() && before.z < table_.cushionHeight; ++k) {
                const Pocket& pk = table_.pockets[k];
                if ((before.position - pk.centre).squaredNorm() > pk.radius * pk.radius) continue;
                e.kind = EventKind::BallPocket;
                e.cushion = -1;
                e.pocket = static_cast<int>(k);
                e.after[0] = BallState{};
                e.after[0].position = pk.centre;
                e.after[0].motion = MotionState::Pocketed;
                e.after[0].pocket = static_cast<int>(k);
                e.contactPoint = before.position;
                finishEvent(e.time, e);
                return;
            }
            // It clears the rail: out of play where it crossed the nose line, like a pocketed ball.
            e.kind = EventKind::BallOffTable;
            e.after[0] = BallState{};
            e.after[0].position = before.position;
            e.after[0].z = before.z;
            e.after[0].motion = MotionState::OffTable;
            e.contactPoint = before.position;
            e.normal = -seg.normal;
            finishEvent(e.time, e);
            return;
        }
        e.kind = EventKind::BallCushion;
        normal = contact.kind == CushionContactKind::Nose || contact.kind == CushionContactKind::End
                     ? contact.normal
                     : Vec3(seg.normal.x(), seg.normal.y(), 0.0);
    } else {
        // Its side, top or rim, along the normal its prediction found.
        e.kind = EventKind::BallJaw;
        e.jaw = c.index;
        normal = airContact_[at(i)].normal;
    }
    // A flying ball meets the cushion along the 3-D normal (a nose edge's is tilted up), with the
    // cushion's restitution and friction (AirImpacts.h). The cushion models of the cloth assume a ball
    // on the cloth, so they are not used here.
    const FixedImpactResult res = resolveFixedImpact(before, R, mass(i), normal, p_.cushionRestitution, p_.cushionFriction);
    e.after[0] = res.after;
    e.after[0].motion = classify(e.after[0], R);
    // A flying ball that a held group presses on a cushion's face, or that a ball's hold in the air
    // let go at this instant (its push pressed it there): the face would answer each press alone, the
    // group (or the other ball, met again at once) press it back, and the two hand it back and forth
    // at this instant until the event cap. The face is held as a row of the ball's group instead (a
    // horizontal normal, HeldContacts.cpp), solved with its other contacts, when the law leaves it
    // parting slower than kHoldSpeed (Contact.h's hold rule).
    // The same for a jaw's side (its vertical cylinder below the nose; seed21-shot106191).
    if (airContact_[at(i)].kind == CushionContactKind::Face && e.after[0].motion == MotionState::Airborne &&
        (heldCount_[at(i)] > 0 || airLetGo_[at(i)] == e.time) && normal.head<2>().norm() > 0.0) {
        const Vec2 out = c.agent == Agent::Cushion ? table_.cushions[at(c.index)].normal : Vec2(normal.head<2>().normalized());
        const double separation = e.after[0].velocity.dot(out);
        if (separation < kHoldSpeed) {
            e.normal = -out;
            e.contactPoint = before.position - R * out;
            e.approachSpeed = res.approachSpeed;
            e.impulse = res.impulse;
            const ContactBody body = c.agent == Agent::Cushion ? ContactBody::Cushion : ContactBody::Jaw;
            if (holdCollision(e, HeldContact{i, body, c.index}, separation)) return;
        }
    }
    // A bounce on a nose edge that leaves the ball parting slower than kHoldSpeed while gravity
    // presses it on: it would bounce ever lower (a Zeno run of impacts that the clock cannot resolve).
    // The edge holds it instead (AirHold.cpp), the rebound taken away (which only removes energy), as
    // the cloth's hold rule does for a collision on the cloth.
    // The same on a jaw's rim (its top is flat: a ball on it is not held).
    const bool rim = c.agent == Agent::Jaw && normal.head<2>().norm() > 0.0;
    // (A segment's bare end: its top corner, the nose edge's end, is held as the edge is, in a group.)
    const bool topCorner = c.agent == Agent::Cushion && airContact_[at(i)].kind == CushionContactKind::End && normal.z() > 0.0;
    if ((((rim || c.agent == Agent::Cushion) && airContact_[at(i)].kind == CushionContactKind::Nose) || topCorner) &&
        e.after[0].motion == MotionState::Airborne) {
        const double separation = Vec3(e.after[0].velocity.x(), e.after[0].velocity.y(), e.after[0].vz).dot(normal);
        // (A jaw's rim too: seed16-shot363458, a flying ball on a rim and a hopping ball, the rim's
        // hold and the ball handing it back and forth.)
        const int edgeId = c.agent == Agent::Cushion ? c.index : static_cast<int>(table_.cushions.size()) + c.index;
        if (separation < kHoldSpeed &&
            (topCorner || heldCount_[at(i)] > 0 || airLetGo_[at(i)] == e.time ||
             (airEdgeLetGo_[at(i)] == e.time && airEdgeLetGoOf_[at(i)] != edgeId))) {
            // Held in a group (on a ball, or on another edge), or let go at this instant by a hold on
            // another body that presses it on this edge too: it is wedged between the two, and pairwise
            // holds would hand it back and forth (seed12-shot988364: two nose edges in a corner;
            // seed14-shot652328: a ball on the cloth and a nose edge), each time a little into the
            // other, until a root was lost and the ball sank through the nose. The edge becomes a row
            // in space of a group (HeldContacts.cpp, airEdgeGeometry); the other contact, met at once,
            // joins it (groupHoldable, or this branch), and the rows are solved together.
            const Vec2 flat = normal.head<2>();
            e.normal = flat.norm() > 0.0 ? Vec2(-flat.normalized()) : Vec2(Vec2::Zero());
            e.contactPoint = before.position - R * flat;
            e.approachSpeed = res.approachSpeed;
            e.impulse = res.impulse;
            const ContactBody body = c.agent == Agent::Cushion ? ContactBody::Cushion : ContactBody::Jaw;
            if (holdCollision(e, HeldContact{i, body, c.index}, std::max(0.0, separation))) return;
        }
        if (separation < kHoldSpeed && !topCorner) {
            BallState seated = e.after[0];
            if (separation > 0.0) {
                seated.velocity -= separation * normal.head<2>();
                seated.vz -= separation * normal.z();
            }
            const std::size_t index = r_.events.size();
            Event held = e;
            held.after[0] = seated;
            held.held = true;
            const Vec2 flat = normal.head<2>();
            held.normal = flat.norm() > 0.0 ? Vec2(-flat.normalized()) : Vec2(Vec2::Zero());
            held.contactPoint = before.position - R * flat;
            held.approachSpeed = res.approachSpeed;
            held.impulse = res.impulse - mass(i) * std::max(0.0, separation) * normal;
            r_.events.push_back(held);
            if (c.agent == Agent::Cushion ? airEdgeHold(i, c.index, e.time, seated) : airRimHold(i, c.index, e.time, seated)) {
                r_.events[index].after[0] = state_[at(i)];
                return;
            }
            r_.events.pop_back();
        }
    }
    const Vec2 flat = normal.head<2>();
    e.normal = flat.norm() > 0.0 ? Vec2(-flat.normalized()) : Vec2(Vec2::Zero());
    e.contactPoint = before.position - R * flat;
    e.approachSpeed = res.approachSpeed;
    e.impulse = res.impulse;
    finishEvent(e.time, e);
}

void Simulator::airBallBall(const Candidate& c, Event& e)
{
    const int i = c.ball, j = c.index;
    e.kind = EventKind::BallBall;
    e.balls[1] = j;
    e.before[1] = stateNow(j, e.time);
    // The line of centres is tilted: both balls free in 3-D, and a ball on the cloth driven into it
    // answered by the cloth at once (AirImpacts.h).
    const AirBallBallResult res = resolveAirBallBall(e.before[0], radius(i), mass(i), e.before[1], radius(j), mass(j), p_);
    // Touching with no approach while gravity presses the flying ball on the other (a ball sliding
    // down a ball's side): the law gives no impulse and the same contact would be met again at this
    // instant, for ever. The pair is held instead (AirHold.cpp): the event marks where the hold
    // begins and changes no velocity.
    // So is an approach within kRestingSpeed whose impulse is lost in rounding: the law changes no
    // velocity (seed21-shot5186: a ball on the cloth whose friction presses it on a ball rising off
    // the cloth beside it, approaching at 8e-20 m/s, the law's 1e-20 N s lost, met again at that
    // instant until the event cap). (A law that does change them stands: seed19-shot723846's
    // 4e-12 m/s joins the group its balls are held in, as a collision.)
    const bool resting = airTouchRests(res, e.before[0], e.before[1]);
    if (resting) {
        const int a = flying(i) ? i : j, b = a == i ? j : i;
        // A held event marks where the hold begins and changes no velocity (the fall-through below
        // sets every one of these fields again for the law's result).
        e.after[0] = e.before[0];
        e.after[1] = e.before[1];
        e.normal = res.normal.head<2>().norm() > 0.0 ? Vec2(res.normal.head<2>().normalized()) : Vec2(Vec2::Zero());
        e.contactPoint = e.before[0].position + radius(i) * res.normal.head<2>();
        e.approachSpeed = res.approachSpeed;
        e.impulse = Vec3::Zero();
        // A flying ball that another ball let go at this instant (this event's, Simulator.cpp's
        // process) and that is pressed on this one too is wedged between them: the pairwise air holds
        // would hand it back and forth at this instant until the event cap (seed12-shot655830: a
        // ball dropping between two rolling balls). It is held with this contact as a row in space
        // of a group instead (HeldContacts.cpp); the other contact, met at once, joins that group
        // (groupHoldable), and the two rows are solved together.
        // The same for a flying b let go at this instant by its hold on a third ball that presses it
        // on a (seed21-shot102774, a break: three balls nearly in a line, the middle one 0.1 mm up,
        // held on the ball on the cloth and pressed by that hold on the third, itself in the air;
        // the air hold and this contact handed the middle ball back and forth at one instant).
        // And for either ball let go at this instant by a nose edge or a jaw's rim that presses it on
        // the other (seed16-shot363458: a flying ball on a rim and a hopping ball); the edge or rim,
        // met at once, joins the group (airCushion).
        const bool wedged = (airLetGo_[at(a)] == e.time && airLetGoOf_[at(a)] != b) ||
                            (flying(b) && airLetGo_[at(b)] == e.time && airLetGoOf_[at(b)] != a) ||
                            airEdgeLetGo_[at(a)] == e.time || (flying(b) && airEdgeLetGo_[at(b)] == e.time);
        if (wedged && holdCollision(e, HeldContact{i, ContactBody::Ball, j}, 0.0)) return;
        if (!wedged && airHoldable(a, b)) {
            e.held = true;  // (with no hold impulse: a pressed pair may part by a few nm/s, Detection.h)
            const std::size_t index = r_.events.size();
            r_.events.push_back(e);
            if (airHold(a, b, e.time)) {
                r_.events[index].after[0] = state_[at(i)];
                r_.events[index].after[1] = state_[at(j)];
                return;
            }
            r_.events.pop_back();
            e.held = false;
        }
        if (!heldFlight(a) && apexHeight(e.before[a == i ? 0 : 1], p_.gravity) <= kHeldGap) {
            // Not held (b is held by the cloth in a group, or the air hold finds no force: the cloth's
            // friction presses b on a level a, seed11-shot4654's 9.4e-12 m hop), and a's hop
            // stays within kHeldGap of the cloth (a frictional law's vertical throw of a few
            // nanometres: seed7-shot190, 1.9e-9 m): the cloth takes the hop, as a landing does, and
            // the pair meets again on the cloth, where the group holds it. The event is that landing.
            // First, the hop rides out its flight to its own landing (no jump in height) when the
            // two paths, left unanswered, press no deeper than kContactTolerance into each other
            // until then or until either ball's next segment (seed15-shot244191: a ball thrown up
            // 4 nm beside a ball it nudges along at a few nm/s, whose rolling resistance brings it
            // back within nanoseconds). Nothing changes and there is no event: the pair is not met
            // again while the ride lasts (riding), and after it the paths are predicted again.
            const double rideEnd = std::min({end_[at(a)], end_[at(b)], horizon_[at(a)], horizon_[at(b)]}) - e.time;
            if (spaceBallBallWithin(spaceNow(a, e.time), radius(a), spaceNow(b, e.time), radius(b), kContactTolerance, rideEnd)) {
                airRide_[at(a)] = b;
                airRideSegments_[at(a)] = r_.timelines[at(a)].size();
                airRidePartnerSegments_[at(a)] = r_.timelines[at(b)].size();
                predictPairs(a, e.time);
                return;
            }
            const BallState before = e.before[a == i ? 0 : 1];
            Event land;
            land.kind = EventKind::BallTable;
            land.time = e.time;
            land.balls[0] = a;
            land.before[0] = before;
            land.after[0] = before;
            land.after[0].z = 0.0;
            land.after[0].vz = 0.0;
            land.after[0].motion = classify(land.after[0], radius(a));
            land.contactPoint = before.position;
            land.impulse = Vec3(0.0, 0.0, -mass(a) * before.vz);
            finishEvent(e.time, land);
            return;
        } else if (groupHoldable(a, b)) {
            // b is held by the cloth in a group (or a is held on one): a's contact joins that group as
            // a row in space (Contact.h's ContactLink::nz), held as the group's others are (its
            // re-seating may take away a rounding's approach).
            if (holdCollision(e, HeldContact{i, ContactBody::Ball, j}, 0.0)) return;
        }
    }
    if (!resting && airHoldRule(e, res)) return;
    // Contact.h's hold rule for any collision with a flying ball and a held group's member (issue 40):
    // the law leaves them parting slower than kHoldSpeed, so the contact is the group's to solve, a row
    // in space of its problem (settle: held when its forces press it, else re-seated with the group and
    // let go). The law alone answered one contact at a time while the group's re-seating, which does not
    // see a flying ball's contact, pushed the member back into the ball: a cascade at one instant whose
    // approach shrank to rounding (1e-18 m/s) and whose every event changed nothing, to the event cap
    // (seed41-shot193948: a ball lifted off the cloth by a frictional law's throw beside a pressed
    // cluster; airHoldRule above takes only a ball that is above the cloth and weighs on the other).
    if (!resting && (heldCount_[at(i)] > 0 || heldCount_[at(j)] > 0) && !airHeldAny(i) && !airHeldAny(j)) {
        const double separation = (velocity3(res.b) - velocity3(res.a)).dot(res.normal);
        if (separation < kHoldSpeed) {
            e.after[0] = res.a;
            e.after[1] = res.b;
            const Vec2 flat = res.normal.head<2>();
            e.normal = flat.norm() > 0.0 ? Vec2(flat.normalized()) : Vec2(Vec2::Zero());
            e.contactPoint = e.before[0].position + radius(i) * flat;
            e.approachSpeed = res.approachSpeed;
            e.impulse = res.impulse;
            if (holdCollision(e, HeldContact{i, ContactBody::Ball, j}, separation)) return;
        }
    }
    e.after[0] = res.a;
    e.after[1] = res.b;
    if (resting) {
        // Touching with no approach and not held: the ball on the cloth goes on as the air hold
        // judged it, a slip of rounding rolled out (as airRelease's). Left sliding, its friction
        // would press it back at once on the flying ball the hold found no force for: met again at
        // this instant until the event cap (seed14-shot150029).
        // So too a ball rolling slower than kRollOffSpeed, which the hold takes as at rest: it
        // stops (its rolling resistance would end it within nanoseconds, a micrometre's billionth
        // on). Left rolling, that resistance pressed it on the flying ball until then, and the pair
        // was met again at this instant until the event cap (seed18-shot346856: 6e-10 m/s).
        for (std::size_t k = 0; k < 2; ++k) {
            if (e.before[k].motion == MotionState::Airborne) continue;
            BallState& s = e.after[k];
            rollOutRounding(s, radius(e.balls[k]), p_);
            if (classify(s, radius(e.balls[k])) == MotionState::Rolling && s.velocity.norm() <= kRollOffSpeed) {
                s.velocity = Vec2::Zero();
                s.spin.x() = 0.0;
                s.spin.y() = 0.0;
            }
        }
    }
    e.after[0].motion = classify(e.after[0], radius(i));
    e.after[1].motion = classify(e.after[1], radius(j));
    const Vec2 flat = res.normal.head<2>();
    e.normal = flat.norm() > 0.0 ? Vec2(flat.normalized()) : Vec2(Vec2::Zero());
    e.contactPoint = e.before[0].position + radius(i) * flat;
    e.approachSpeed = res.approachSpeed;
    e.impulse = res.impulse;
    finishEvent(e.time, e);
}

}  // namespace cuelab::detail
