// Sustained contact (Contact.h): pushes are held contacts, not cascades of micro-collisions. Closed
// forms of a push derived by hand, the event counts of the push cases, and the invariants (no
// overlap, energy never rising) on pushes along and off the line of centres; a flying ball pressed on
// a ball of a group (a row in space).

#include "Contact.h"
#include "Motion.h"
#include "Simulation.h"
#include "SimulationChecks.h"

#include <QtTest>

#include <cmath>

using namespace cuelab;
using namespace cuelab::testing;

namespace {

Setup emptySetup()
{
    Setup s;
    s.table.kind = TableKind::Pool9ft;
    return s;
}

// Every sampled time (events, segment starts and points between them): the worst overlap and the
// largest rise of the total kinetic energy from one sample to the next.
void sweep(const SimulationResult& r, double& worstOverlap, double& worstRise)
{
    std::vector<double> times;
    for (const Event& e : r.events) times.push_back(e.time);
    for (const auto& timeline : r.timelines)
        for (const MotionSegment& seg : timeline) times.push_back(seg.start);
    for (int k = 0; k <= 200; ++k) times.push_back(r.endTime * k / 200.0);
    std::sort(times.begin(), times.end());
    const std::size_t n = times.size();
    for (std::size_t k = 0; k + 1 < n; ++k) times.push_back(0.5 * (times[k] + times[k + 1]));
    std::sort(times.begin(), times.end());
    worstOverlap = -1.0;
    worstRise = 0.0;
    double energy = totalEnergy(r, r.statesAt(0.0));
    for (double t : times) {
        const std::vector<BallState> s = r.statesAt(t);
        worstOverlap = std::max(worstOverlap, maxOverlap(r, s));
        const double e = totalEnergy(r, s);
        worstRise = std::max(worstRise, e - energy);
        energy = e;
    }
}

// A cue ball at `speed` (stun: no spin; follow: rolling) into five frozen balls in a line.
Setup intoFive(bool follow, BallBallModel model)
{
    Setup s = emptySetup();
    const Table t = makeTable(s.table);
    const double R = t.ballRadius;
    const Vec2 v(2.0, 0.0);
    s.physics.ballBallModel = model;
    s.balls.push_back(ballAt(t, "cue", Vec2(0.6, 0.635), v, follow ? Vec3(0.0, v.x() / R, 0.0) : Vec3::Zero()));
    for (int k = 0; k < 5; ++k) s.balls.push_back(ballAt(t, std::to_string(k + 1), Vec2(1.2 + 2 * R * k, 0.635)));
    return s;
}

int heldEvents(const SimulationResult& r)
{
    int n = 0;
    for (const Event& e : r.events) n += e.held ? 1 : 0;
    return n;
}

}  // namespace

class TestContact : public QObject {
    Q_OBJECT
private slots:
    void pushFromRestHasTheClosedForm();
    void spinIntoARailHoldsTheBall();
    void pushCasesCostFewEvents_data();
    void pushCasesCostFewEvents();
    void pushOffTheLineOfCentres();
    void solverComplementarity();
    void flyingBallOnAGroupMember_data();
    void flyingBallOnAGroupMember();
};

// A ball with topspin and no speed touching a ball at rest: its cloth friction mu_s g drives it into
// the other ball, which rolls off (effective mass 7/5 m, rolling resistance mu_r g). By hand, with
// N the contact force: mu_s g - N/m = 5/7 N/m - mu_r g, so N/m = 7/12 (mu_s + mu_r) g and the
// common acceleration is a = (5 mu_s - 7 mu_r) g / 12 = (1 - 0.07) * 9.81 / 12 = 0.760275 m/s^2.
// N/m = 7/12 * 0.21 * 9.81 = 1.201725 m/s^2, and the pusher's slip R w (to 0) shrinks at
// 7/2 mu_s g - N/m = (6.867 - 1.201725) m/s^2 = 5.665275 m/s^2.
void TestContact::pushFromRestHasTheClosedForm()
{
    Setup s = emptySetup();
    const Table t = makeTable(s.table);
    const double R = t.ballRadius;
    const double w = 20.0;  // rad/s of topspin: slip R w = 0.5715 m/s
    s.balls.push_back(ballAt(t, "a", Vec2(1.0, 0.6), Vec2::Zero(), Vec3(0.0, w, 0.0)));
    s.balls.push_back(ballAt(t, "b", Vec2(1.0 + 2 * R, 0.6)));
    const SimulationResult r = simulate(s);
    QVERIFY(r.status == SimulationStatus::AllAtRest);

    const double a = 0.760275;                // m/s^2, by hand above (g = 9.81, mu_s = 0.2, mu_r = 0.01)
    const double slideEnd = R * w / 5.665275;  // s
    QVERIFY(r.events.size() >= 2);
    QVERIFY(r.events[0].kind == EventKind::BallBall);
    QVERIFY(r.events[0].held);
    QCOMPARE(r.events[0].time, 0.0);
    QVERIFY(r.events[1].kind == EventKind::SlideToRoll);
    QVERIFY(std::abs(r.events[1].time - slideEnd) <= 1e-12 * slideEnd);
    for (double f : {0.25, 0.5, 0.9}) {
        const double tau = f * slideEnd;
        const BallState pa = r.stateAt(0, tau), pb = r.stateAt(1, tau);
        QVERIFY(std::abs(pa.position.x() - (1.0 + 0.5 * a * tau * tau)) <= 1e-12);
        QVERIFY(std::abs(pb.position.x() - (1.0 + 2 * R + 0.5 * a * tau * tau)) <= 1e-12);
        QVERIFY(std::abs(pa.velocity.x() - a * tau) <= 1e-12);
        QVERIFY(std::abs(pb.velocity.x() - a * tau) <= 1e-12);
        QCOMPARE(pa.position.y(), 0.6);
        QVERIFY(std::abs((pb.position - pa.position).norm() - 2 * R) <= 1e-12);  // held at contact
    }
    // After the slide both roll at one speed and decelerate alike: they stop at the same instant,
    // still touching, having shared speed a t_s.
    const double v = a * slideEnd;
    const double stop = slideEnd + v / (0.01 * 9.81);
    int stops = 0;
    for (const Event& e : r.events)
        if (e.kind == EventKind::RollToStop) {
            ++stops;
            QVERIFY(std::abs(e.time - stop) <= 1e-9 * stop);
        }
    QCOMPARE(stops, 2);
    QCOMPARE(static_cast<int>(r.events.size()), 4);
    double overlap = 0.0, rise = 0.0;
    sweep(r, overlap, rise);
    QVERIFY(overlap <= 1e-12);
    QVERIFY(rise <= 1e-15);
}

// A ball at rest against a rail with spin that drives it into the rail: the rail holds it; its
// velocity stays zero and its slip decays at 7/2 mu_s g - mu_s g = 5/2 mu_s g (the rail's force
// cancels the friction's push), so the slide ends at R w / (2.5 mu_s g), by hand 0.028575 * 10 /
// 4.905 = 0.058256880733944954 s. With a separation floor this was a long cascade of bounces.
void TestContact::spinIntoARailHoldsTheBall()
{
    Setup s = emptySetup();
    const Table t = makeTable(s.table);
    const double R = t.ballRadius;
    // The bottom rail (y = 0): friction must push towards -y, so the slip points to +y:
    // u_y = v_y + R w_x > 0 with w_x = 10 rad/s.
    s.balls.push_back(ballAt(t, "a", Vec2(t.length / 4, R), Vec2::Zero(), Vec3(10.0, 0.0, 0.0)));
    const SimulationResult r = simulate(s);
    QVERIFY(r.status == SimulationStatus::AllAtRest);
    QCOMPARE(static_cast<int>(r.events.size()), 2);
    QVERIFY(r.events[0].kind == EventKind::BallCushion);
    QVERIFY(r.events[0].held);
    QVERIFY(r.events[1].kind == EventKind::SlideToStop);
    QVERIFY(std::abs(r.events[1].time - 0.058256880733944954) <= 1e-12);
    const BallState mid = r.stateAt(0, 0.03);
    QVERIFY(mid.position == Vec2(t.length / 4, R));
    QVERIFY(mid.velocity.norm() <= 1e-15);
    QVERIFY(std::abs(mid.spin.x() - 10.0 * (1.0 - 0.03 / 0.058256880733944954)) <= 1e-12);
}

void TestContact::pushCasesCostFewEvents_data()
{
    QTest::addColumn<bool>("follow");
    QTest::addColumn<int>("model");
    QTest::addColumn<int>("most");
    // Before (separation floor of 1 mm/s): stun 2023 events, follow 4159.
    QTest::newRow("stun, frictionless") << false << int(BallBallModel::Frictionless) << 40;
    QTest::newRow("follow, frictionless") << true << int(BallBallModel::Frictionless) << 60;
    QTest::newRow("stun, frictional") << false << int(BallBallModel::Frictional) << 60;
    QTest::newRow("follow, frictional") << true << int(BallBallModel::Frictional) << 80;
}

void TestContact::pushCasesCostFewEvents()
{
    QFETCH(bool, follow);
    QFETCH(int, model);
    QFETCH(int, most);
    const SimulationResult r = simulate(intoFive(follow, static_cast<BallBallModel>(model)));
    QVERIFY(r.status == SimulationStatus::AllAtRest);
    qInfo("%zu events, %d of them holding a push", r.events.size(), heldEvents(r));
    QVERIFY(static_cast<int>(r.events.size()) <= most);
    QVERIFY(heldEvents(r) > 0);  // the case does push
    double overlap = 0.0, rise = 0.0;
    sweep(r, overlap, rise);
    QVERIFY2(overlap <= 1e-9, qPrintable(QString::number(overlap)));
    QVERIFY2(rise <= 1e-12, qPrintable(QString::number(rise)));
}

// A ball with side spin driven into a ball at rest off the line of centres: the friction directions
// turn, so the push runs in short frozen segments (Contact.h: kMaxTurn). Honest limits: no overlap,
// no energy rise, the pair stays within kHeldGap while held, and it ends.
void TestContact::pushOffTheLineOfCentres()
{
    Setup s = emptySetup();
    const Table t = makeTable(s.table);
    const double R = t.ballRadius;
    const double angle = 0.5;  // rad between the line of centres and the pusher's drive
    const Vec2 n(std::cos(angle), std::sin(angle));
    // The pusher's slip points against +x (topspin along x), so friction drives it along +x.
    s.balls.push_back(ballAt(t, "a", Vec2(1.0, 0.6), Vec2(0.05, 0.0), Vec3(0.0, 25.0, 0.0)));
    s.balls.push_back(ballAt(t, "b", Vec2(1.0, 0.6) + 2 * R * n));
    const SimulationResult r = simulate(s);
    QVERIFY(r.status == SimulationStatus::AllAtRest);
    QVERIFY(heldEvents(r) > 0);
    QVERIFY(r.events.size() < 200);
    double overlap = 0.0, rise = 0.0;
    sweep(r, overlap, rise);
    QVERIFY2(overlap <= 1e-9, qPrintable(QString::number(overlap)));
    QVERIFY2(rise <= 1e-12, qPrintable(QString::number(rise)));
    // While a held segment runs, the distance stays in [2R - 1e-12, 2R + kHeldGap].
    for (const MotionSegment& seg : r.timelines[0]) {
        if (seg.push.isZero(0.0)) continue;
        const double d = (r.stateAt(1, seg.start).position - r.stateAt(0, seg.start).position).norm();
        QVERIFY(d >= 2 * R - 1e-12);
        QVERIFY(d <= 2 * R + kHeldGap + 1e-12);
    }
}

// The contact solver against a brute force: for a line of three pressed balls and a wall, every
// link either carries a force with zero relative acceleration or none with a parting one.
void TestContact::solverComplementarity()
{
    PhysicsParams p;
    const double R = 0.028575, m = 0.170097;
    std::vector<ContactBall> balls(3);
    for (int k = 0; k < 3; ++k) {
        balls[static_cast<std::size_t>(k)].radius = R;
        balls[static_cast<std::size_t>(k)].mass = m;
        balls[static_cast<std::size_t>(k)].state.position = Vec2(0.5 + 2 * R * k, 0.5);
    }
    // Ball 0 sliding with a slip that drives it along +x; 1 rolling along +x; 2 at rest against a wall at +x.
    balls[0].state.velocity = Vec2(0.1, 0.0);
    balls[0].state.spin = Vec3(0.0, 30.0, 0.0);
    balls[0].state.motion = MotionState::Sliding;
    balls[1].state.velocity = Vec2(0.1, 0.0);
    balls[1].state.spin = Vec3(0.0, 0.1 / R, 0.0);
    balls[1].state.motion = MotionState::Rolling;
    balls[2].state.motion = MotionState::Stationary;
    const std::vector<ContactLink> links = {{0, 1, Vec2(1, 0)}, {1, 2, Vec2(1, 0)}, {2, -1, Vec2(1, 0)}};
    const ContactSolution sol = solveContacts(balls, links, p);
    QVERIFY(sol.converged);
    for (std::size_t k = 0; k < links.size(); ++k) {
        QVERIFY(sol.force[k] >= 0.0);
        QVERIFY(sol.accel[k] >= -1e-12);
        QVERIFY(sol.force[k] * sol.accel[k] <= 1e-12);
    }
    // Everything is pressed into the wall, so nothing moves along x. By hand: ball 0 (sliding, driven
    // at +mu_s g) needs a push of -mu_s g; ball 1 (rolling, 5/7 of its push against -mu_r g) one of
    // +7/5 mu_r g; so N01 = mu_s g m and N12 = N01 - 7/5 mu_r g m.
    QVERIFY(std::abs(sol.push[0].x() + p.muSlide * p.gravity) <= 1e-12);
    QVERIFY(std::abs(sol.push[1].x() - 1.4 * p.muRoll * p.gravity) <= 1e-12);
    QVERIFY(std::abs(sol.force[0] - p.muSlide * p.gravity * m) <= 1e-12);
    QVERIFY(std::abs(sol.force[1] - (p.muSlide - 1.4 * p.muRoll) * p.gravity * m) <= 1e-12);
    // And nobody accelerates along x: each ball's pushed motion (Motion.h) has a = 0. (Ball 2's
    // share between the ball behind and the wall is not unique; any share gives it no motion.)
    for (std::size_t k = 0; k < 3; ++k) {
        BallState s = balls[k].state;
        s.motion = sol.label[k];
        const Path path = pathOf(s, R, p, sol.push[k]);
        QVERIFY2(std::abs(path.c2.x()) <= 1e-12, qPrintable(QString::number(k)));
    }
}

void TestContact::flyingBallOnAGroupMember_data()
{
    QTest::addColumn<double>("angle");  // degrees of the line from b's centre to a's above the cloth
    QTest::newRow("30") << 30.0;
    QTest::newRow("60") << 60.0;
    QTest::newRow("90 (on top)") << 90.0;
}

// A flying ball a pressed on the shoulder of a ball b at rest on the cloth, b against a wall on the
// far side (issue 23: the flying ball's contact as a row in space, ContactLink::nz). The wall and the
// cloth hold b, so a slides down b's surface as down a fixed sphere: by hand, with the line from b to
// a at angle theta above the cloth, N = m g sin(theta) and a's acceleration -g cos(theta) (sin, cos)
// in the (x, z) plane, along the tangent (no normal part: the pair stays in contact).
void TestContact::flyingBallOnAGroupMember()
{
    QFETCH(double, angle);
    const double theta = angle * M_PI / 180.0, c = std::cos(theta), s = std::sin(theta);
    PhysicsParams p;
    const double R = 0.028575, m = 0.170097;
    std::vector<ContactBall> balls(2);
    for (ContactBall& b : balls) {
        b.radius = R;
        b.mass = m;
    }
    balls[1].state.position = Vec2(0.5, 0.5);
    balls[1].state.motion = MotionState::Stationary;
    balls[0].state.position = Vec2(0.5 - 2 * R * c, 0.5);
    balls[0].state.z = 2 * R * s;
    balls[0].state.motion = MotionState::Airborne;
    ContactLink onShoulder{0, 1, Vec2(c, 0.0)};  // from a towards b: (cos, 0, -sin)
    onShoulder.nz = -s;
    const std::vector<ContactLink> links = {onShoulder, {1, -1, Vec2(1, 0)}};
    const ContactSolution sol = solveContacts(balls, links, p);
    QVERIFY(sol.converged);
    const double g = p.gravity;
    QVERIFY2(std::abs(sol.force[0] - m * g * s) <= 1e-12, qPrintable(QString::number(sol.force[0], 'g', 17)));
    QVERIFY(std::abs(sol.push[0].x() + g * s * c) <= 1e-12);
    QVERIFY(std::abs(sol.push[0].y()) <= 1e-15);
    QVERIFY(std::abs(sol.pushZ[0] - g * s * s) <= 1e-12);
    QVERIFY(sol.label[0] == MotionState::Airborne);
    // b does not move: the wall and the cloth take the push.
    QVERIFY(sol.push[1].isZero(0.0));
    QCOMPARE(sol.pushZ[1], 0.0);
    QVERIFY(sol.accel[0] >= -1e-12 && sol.accel[0] <= 1e-12);
}

QTEST_APPLESS_MAIN(TestContact)
#include "tst_contact.moc"
