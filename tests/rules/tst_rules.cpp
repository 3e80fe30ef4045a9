// The rules of each game on hand-made event lists: every rule, each way it can go. A shot is written
// as a script of events ("hit:cue:1 rail:1 pot:1@pocket-tr"), so that each row says by hand what
// happened and what the verdict must be; nothing is simulated here.

#include "Verdict.h"

#include <QTest>

#include <sstream>

using namespace cuelab;
using namespace cuelab::rules;

namespace {

// A result with the given balls (ids) on a table of `kind`, and the events of `script`, one every
// 0.1 s after the cue strike (event 0) of the ball "cue" (or the first ball):
//   hit:A:B  ball A meets ball B      rail:A  ball A meets a cushion     jaw:A  a jaw tip
//   pot:A@P  ball A falls into P      off:A   ball A leaves the table    stop:A ball A comes to rest
SimulationResult shot(TableKind kind, const QStringList& ids, const QString& script)
{
    SimulationResult r;
    r.table = makeTable(kind);
    for (const QString& id : ids) r.balls.push_back(Ball{id.toStdString(), 0.028575, 0.170097, {}});
    const auto index = [&](const QString& id) {
        const int i = r.ballIndex(id.toStdString());
        if (i < 0) qFatal("no ball %s in the test's shot", qPrintable(id));
        return i;
    };
    Event strike;
    strike.kind = EventKind::CueStrike;
    strike.balls = {r.ballIndex("cue") >= 0 ? r.ballIndex("cue") : 0, -1};
    r.events.push_back(strike);
    double t = 0.0;
    for (const QString& step : script.split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
        const QStringList parts = step.split(QLatin1Char(':'));
        Event e;
        e.time = t += 0.1;
        const QString verb = parts[0];
        if (verb == QLatin1String("hit")) {
            e.kind = EventKind::BallBall;
            e.balls = {index(parts[1]), index(parts[2])};
        } else if (verb == QLatin1String("rail") || verb == QLatin1String("jaw")) {
            e.kind = verb == QLatin1String("rail") ? EventKind::BallCushion : EventKind::BallJaw;
            e.balls = {index(parts[1]), -1};
            (verb == QLatin1String("rail") ? e.cushion : e.jaw) = 0;
        } else if (verb == QLatin1String("pot")) {
            const QStringList at = parts[1].split(QLatin1Char('@'));
            e.kind = EventKind::BallPocket;
            e.balls = {index(at[0]), -1};
            for (std::size_t p = 0; p < r.table.pockets.size(); ++p)
                if (r.table.pockets[p].id == at[1].toStdString()) e.pocket = static_cast<int>(p);
            if (e.pocket < 0) qFatal("no pocket %s", qPrintable(at[1]));
        } else if (verb == QLatin1String("off")) {
            e.kind = EventKind::BallOffTable;
            e.balls = {index(parts[1]), -1};
        } else if (verb == QLatin1String("stop")) {
            e.kind = EventKind::RollToStop;
            e.balls = {index(parts[1]), -1};
        } else {
            qFatal("unknown step %s", qPrintable(step));
        }
        r.events.push_back(e);
    }
    r.endTime = t;
    return r;
}

QString idsOf(const SimulationResult& r, const std::vector<int>& balls)
{
    QStringList out;
    for (const int b : balls) out << QString::fromStdString(r.balls.at(static_cast<std::size_t>(b)).id);
    return out.join(QLatin1Char(','));
}

const QStringList kNine{"cue", "1", "2", "3", "4", "5", "6", "7", "8", "9"};
const QStringList kTen{"cue", "1", "2", "3", "4", "5", "6", "7", "8", "9", "10"};
const QStringList kEight{"cue", "1", "2", "3", "4", "5", "6", "7", "8", "9", "10", "11", "12", "13", "14", "15"};

}  // namespace

class TestRules : public QObject {
    Q_OBJECT

private:
    // Columns every table shares: the verdict's fields, "" for no foul.
    static void verdictColumns()
    {
        QTest::addColumn<QString>("foul");      // rule id, "" = legal
        QTest::addColumn<int>("event");         // the deciding event (-1 none)
        QTest::addColumn<QString>("scored");    // ids, comma-separated, time order
        QTest::addColumn<bool>("continues");
        QTest::addColumn<bool>("ballInHand");
        QTest::addColumn<QString>("respotted");
        QTest::addColumn<QString>("ends");      // none | won | lost
    }
    static void check(const std::optional<Verdict>& v, const SimulationResult& r)
    {
        QFETCH(QString, foul);
        QFETCH(int, event);
        QFETCH(QString, scored);
        QFETCH(bool, continues);
        QFETCH(bool, ballInHand);
        QFETCH(QString, respotted);
        QFETCH(QString, ends);
        QVERIFY(v.has_value());
        QCOMPARE(v->foul ? QString::fromUtf8(toString(v->foul->rule).data(), qsizetype(toString(v->foul->rule).size())) : QString(), foul);
        QCOMPARE(v->legal(), foul.isEmpty());
        QCOMPARE(v->event, event);
        if (v->foul) {
            QCOMPARE(v->foul->event, event);
            QVERIFY(!v->foul->text.english().empty());
        }
        QCOMPARE(idsOf(r, v->scored), scored);
        QCOMPARE(v->continues, continues);
        QCOMPARE(v->ballInHand, ballInHand);
        QCOMPARE(idsOf(r, v->respotted), respotted);
        QCOMPARE(QString::fromUtf8(toString(v->ends).data(), qsizetype(toString(v->ends).size())), ends);
        QVERIFY(!v->text.english().empty());
    }

private slots:
    void nineBall_data()
    {
        QTest::addColumn<QStringList>("balls");
        QTest::addColumn<bool>("isBreak");
        QTest::addColumn<QString>("script");
        verdictColumns();
        // Events: 0 is the strike; each script step is the next index.
        QTest::newRow("legal pot") << kNine << false << "hit:cue:1 pot:1@pocket-tr stop:cue" << "" << 2 << "1" << true << false << "" << "none";
        QTest::newRow("safety: contact and a rail") << kNine << false << "hit:cue:1 rail:1 stop:1" << "" << -1 << "" << false << false << "" << "none";
        QTest::newRow("cue ball rail after contact") << kNine << false << "hit:cue:1 rail:cue stop:cue" << "" << -1 << "" << false << false << "" << "none";
        QTest::newRow("jaw counts as a rail") << kNine << false << "hit:cue:1 jaw:1 stop:1" << "" << -1 << "" << false << false << "" << "none";
        QTest::newRow("no rail after contact") << kNine << false << "hit:cue:1 stop:1 stop:cue" << "no-rail" << 3 << "" << false << true << "" << "none";
        QTest::newRow("rail before contact only") << kNine << false << "rail:cue hit:cue:1 stop:cue" << "no-rail" << 3 << "" << false << true << "" << "none";
        QTest::newRow("wrong ball first") << kNine << false << "hit:cue:4 rail:4 hit:4:1 pot:1@pocket-b" << "wrong-ball-first" << 1 << "" << false << true << "" << "none";
        QTest::newRow("no contact") << kNine << false << "rail:cue rail:cue stop:cue" << "no-contact" << 3 << "" << false << true << "" << "none";
        QTest::newRow("scratch") << kNine << false << "hit:cue:1 rail:1 pot:cue@pocket-bl" << "scratch" << 3 << "" << false << true << "" << "none";
        QTest::newRow("scratch with no contact") << kNine << false << "rail:cue pot:cue@pocket-bl" << "scratch" << 2 << "" << false << true << "" << "none";
        QTest::newRow("object ball off the table") << kNine << false << "hit:cue:1 off:1 rail:cue" << "off-table" << 2 << "" << false << true << "" << "none";
        QTest::newRow("cue ball off the table") << kNine << false << "hit:cue:1 rail:1 off:cue" << "off-table" << 3 << "" << false << true << "" << "none";
        QTest::newRow("combination on the 9 wins") << kNine << false << "hit:cue:1 hit:1:9 pot:9@pocket-tl" << "" << 3 << "9" << false << false << "" << "won";
        QTest::newRow("9 and others down") << kNine << false << "hit:cue:1 pot:9@pocket-tl pot:1@pocket-b" << "" << 2 << "9,1" << false << false << "" << "won";
        QTest::newRow("9 down on a scratch is respotted") << kNine << false << "hit:cue:1 pot:9@pocket-tl pot:cue@pocket-b" << "scratch" << 3 << "" << false << true << "9" << "none";
        QTest::newRow("9 down on a wrong first is respotted") << kNine << false << "hit:cue:9 pot:9@pocket-tl" << "wrong-ball-first" << 1 << "" << false << true << "9" << "none";
        QTest::newRow("9 off the table is respotted") << kNine << false << "hit:cue:1 hit:1:9 off:9" << "off-table" << 3 << "" << false << true << "9" << "none";
        QTest::newRow("lowest ball is on") << QStringList{"cue", "3", "5", "9"} << false << "hit:cue:3 hit:3:5 pot:5@pocket-t" << "" << 3 << "5" << true << false << "" << "none";
        QTest::newRow("lowest ball missed") << QStringList{"cue", "3", "5", "9"} << false << "hit:cue:5 pot:5@pocket-t" << "wrong-ball-first" << 1 << "" << false << true << "" << "none";
        QTest::newRow("earliest foul decides") << kNine << false << "off:cue" << "off-table" << 1 << "" << false << true << "" << "none";
        QTest::newRow("break: 9 on the break combo wins") << kNine << true << "hit:cue:1 hit:1:2 hit:2:9 pot:9@pocket-tr rail:1" << "" << 4 << "9" << false << false << "" << "won";
        QTest::newRow("break: four balls to a rail") << kNine << true << "hit:cue:1 rail:2 rail:3 rail:4 rail:5 stop:cue" << "" << -1 << "" << false << false << "" << "none";
        QTest::newRow("break: three balls to a rail") << kNine << true << "hit:cue:1 rail:2 rail:3 rail:4 rail:4 stop:cue" << "illegal-break" << 6 << "" << false << true << "" << "none";
        QTest::newRow("break: a pot keeps the table") << kNine << true << "hit:cue:1 pot:5@pocket-b" << "" << 2 << "5" << true << false << "" << "none";
        QTest::newRow("break: wrong ball first") << kNine << true << "hit:cue:2 pot:5@pocket-b" << "wrong-ball-first" << 1 << "" << false << true << "" << "none";
    }
    void nineBall()
    {
        QFETCH(QStringList, balls);
        QFETCH(bool, isBreak);
        QFETCH(QString, script);
        const SimulationResult r = shot(TableKind::Pool9ft, balls, script);
        GameSpec game{GameRules::NineBall, {}, {}, {}, isBreak};
        check(judgeShot(r, game), r);
    }

    void tenBall_data()
    {
        QTest::addColumn<QString>("nominated");
        QTest::addColumn<bool>("isBreak");
        QTest::addColumn<QString>("script");
        verdictColumns();
        QTest::newRow("called pot") << "pocket-tr" << false << "hit:cue:1 pot:1@pocket-tr" << "" << 2 << "1" << true << false << "" << "none";
        QTest::newRow("pot in another pocket: turn passes") << "pocket-tr" << false << "hit:cue:1 pot:1@pocket-b" << "" << 2 << "1" << false << false << "" << "none";
        QTest::newRow("no call: any pot counts") << "" << false << "hit:cue:1 pot:1@pocket-b" << "" << 2 << "1" << true << false << "" << "none";
        QTest::newRow("10 called wins") << "pocket-tl" << false << "hit:cue:1 hit:1:10 pot:10@pocket-tl" << "" << 3 << "10" << false << false << "" << "won";
        QTest::newRow("10 uncalled is respotted") << "pocket-tr" << false << "hit:cue:1 hit:1:10 pot:10@pocket-tl" << "" << -1 << "" << false << false << "10" << "none";
        QTest::newRow("10 on the break is respotted") << "" << true << "hit:cue:1 pot:10@pocket-tl pot:3@pocket-b" << "" << 3 << "3" << true << false << "10" << "none";
        QTest::newRow("10 on a foul is respotted") << "" << false << "hit:cue:2 pot:10@pocket-tl" << "wrong-ball-first" << 1 << "" << false << true << "10" << "none";
    }
    void tenBall()
    {
        QFETCH(QString, nominated);
        QFETCH(bool, isBreak);
        QFETCH(QString, script);
        const SimulationResult r = shot(TableKind::Pool9ft, kTen, script);
        GameSpec game{GameRules::TenBall, {}, {}, nominated.toStdString(), isBreak};
        check(judgeShot(r, game), r);
    }

    void eightBall_data()
    {
        QTest::addColumn<QStringList>("balls");
        QTest::addColumn<QString>("group");
        QTest::addColumn<QString>("nominated");
        QTest::addColumn<bool>("isBreak");
        QTest::addColumn<QString>("script");
        verdictColumns();
        QTest::newRow("open: a stripe") << kEight << "open" << "" << false << "hit:cue:12 pot:12@pocket-b" << "" << 2 << "12" << true << false << "" << "none";
        QTest::newRow("open: the 8 first") << kEight << "open" << "" << false << "hit:cue:8 rail:8" << "wrong-ball-first" << 1 << "" << false << true << "" << "none";
        QTest::newRow("solids: a solid") << kEight << "solids" << "" << false << "hit:cue:3 pot:3@pocket-b" << "" << 2 << "3" << true << false << "" << "none";
        QTest::newRow("solids: a stripe first") << kEight << "solids" << "" << false << "hit:cue:11 hit:11:3 pot:3@pocket-b" << "wrong-ball-first" << 1 << "" << false << true << "" << "none";
        QTest::newRow("solids: only a stripe down") << kEight << "solids" << "" << false << "hit:cue:3 hit:3:11 pot:11@pocket-b" << "" << -1 << "" << false << false << "" << "none";
        QTest::newRow("solids: 8 early loses") << kEight << "solids" << "" << false << "hit:cue:3 hit:3:8 pot:8@pocket-b" << "wrong-ball-pocketed" << 3 << "" << false << true << "" << "lost";
        QTest::newRow("open: 8 early loses") << kEight << "open" << "" << false << "hit:cue:3 hit:3:8 pot:8@pocket-b" << "wrong-ball-pocketed" << 3 << "" << false << true << "" << "lost";
        QTest::newRow("on the 8: called pocket wins") << QStringList{"cue", "8", "12"} << "solids" << "pocket-b" << false << "hit:cue:8 pot:8@pocket-b" << "" << 2 << "8" << false << false << "" << "won";
        QTest::newRow("on the 8: other pocket loses") << QStringList{"cue", "8", "12"} << "solids" << "pocket-t" << false << "hit:cue:8 pot:8@pocket-b" << "wrong-pocket" << 2 << "" << false << true << "" << "lost";
        QTest::newRow("on the 8: scratch loses") << QStringList{"cue", "8", "12"} << "solids" << "" << false << "hit:cue:8 pot:8@pocket-b pot:cue@pocket-t" << "scratch" << 3 << "" << false << true << "" << "lost";
        QTest::newRow("on the 8: a stripe first") << QStringList{"cue", "8", "12"} << "solids" << "" << false << "hit:cue:12 rail:12" << "wrong-ball-first" << 1 << "" << false << true << "" << "none";
        QTest::newRow("break: 8 respotted") << kEight << "open" << "" << true << "hit:cue:1 pot:8@pocket-b pot:2@pocket-t" << "" << 3 << "2" << true << false << "8" << "none";
        QTest::newRow("break: scratch, 8 respotted") << kEight << "open" << "" << true << "hit:cue:1 pot:8@pocket-b pot:cue@pocket-t" << "scratch" << 3 << "" << false << true << "8" << "none";
    }
    void eightBall()
    {
        QFETCH(QStringList, balls);
        QFETCH(QString, group);
        QFETCH(QString, nominated);
        QFETCH(bool, isBreak);
        QFETCH(QString, script);
        const SimulationResult r = shot(TableKind::Pool9ft, balls, script);
        PoolGroup g{};
        QVERIFY(parsePoolGroup(group.toStdString(), g));
        GameSpec game{GameRules::EightBall, g, {}, nominated.toStdString(), isBreak};
        check(judgeShot(r, game), r);
    }

    void snooker_data()
    {
        QTest::addColumn<QStringList>("balls");
        QTest::addColumn<QString>("on");
        QTest::addColumn<QString>("script");
        verdictColumns();
        QTest::addColumn<int>("points");
        QTest::addColumn<int>("foulPoints");
        const QStringList full{"cue", "red-1", "red-2", "yellow", "green", "brown", "blue", "pink", "black"};
        const QStringList colours{"cue", "yellow", "green", "brown", "blue", "pink", "black"};
        QTest::newRow("red potted") << full << "red" << "hit:cue:red-1 pot:red-1@pocket-tr" << "" << 2 << "red-1" << true << false << "" << "none" << 1 << 0;
        QTest::newRow("plant: two reds") << full << "red" << "hit:cue:red-1 hit:red-1:red-2 pot:red-2@pocket-t pot:red-1@pocket-b" << "" << 4 << "red-2,red-1" << true << false << "" << "none" << 2 << 0;
        QTest::newRow("red missed: nothing potted") << full << "red" << "hit:cue:red-1 rail:red-1" << "" << -1 << "" << false << false << "" << "none" << 0 << 0;
        QTest::newRow("no rail needed") << full << "red" << "hit:cue:red-1 stop:red-1" << "" << -1 << "" << false << false << "" << "none" << 0 << 0;
        QTest::newRow("colour on red: blue first") << full << "red" << "hit:cue:blue rail:blue" << "wrong-ball-first" << 1 << "" << false << false << "" << "none" << 0 << 5;
        QTest::newRow("colour on red: yellow first, 4 minimum") << full << "red" << "hit:cue:yellow" << "wrong-ball-first" << 1 << "" << false << false << "" << "none" << 0 << 4;
        QTest::newRow("colour potted on a red") << full << "red" << "hit:cue:red-1 hit:red-1:pink pot:pink@pocket-t" << "wrong-ball-pocketed" << 3 << "" << false << false << "pink" << "none" << 0 << 6;
        QTest::newRow("in-off on a red") << full << "red" << "hit:cue:red-1 pot:cue@pocket-t" << "scratch" << 2 << "" << false << true << "" << "none" << 0 << 4;
        QTest::newRow("miss on a red") << full << "red" << "rail:cue stop:cue" << "no-contact" << 2 << "" << false << false << "" << "none" << 0 << 4;
        QTest::newRow("red and black down") << full << "red" << "hit:cue:red-1 hit:red-1:black pot:red-1@pocket-t pot:black@pocket-b" << "wrong-ball-pocketed" << 4 << "" << false << false << "black" << "none" << 0 << 7;
        QTest::newRow("colour after a red: black") << full << "colour" << "hit:cue:black pot:black@pocket-t" << "" << 2 << "black" << true << false << "black" << "none" << 7 << 0;
        QTest::newRow("colour after a red: a red first") << full << "colour" << "hit:cue:red-1" << "wrong-ball-first" << 1 << "" << false << false << "" << "none" << 0 << 7;
        QTest::newRow("colour: pink hit, blue potted") << full << "colour" << "hit:cue:pink hit:pink:blue pot:blue@pocket-t" << "wrong-ball-pocketed" << 3 << "" << false << false << "blue" << "none" << 0 << 6;
        QTest::newRow("nominated blue, blue potted") << full << "blue" << "hit:cue:blue pot:blue@pocket-t" << "" << 2 << "blue" << true << false << "blue" << "none" << 5 << 0;
        QTest::newRow("clearing: yellow stays down") << colours << "yellow" << "hit:cue:yellow pot:yellow@pocket-bl" << "" << 2 << "yellow" << true << false << "" << "none" << 2 << 0;
        QTest::newRow("clearing: green first on the yellow") << colours << "yellow" << "hit:cue:green pot:green@pocket-bl" << "wrong-ball-first" << 1 << "" << false << false << "green" << "none" << 0 << 4;
        QTest::newRow("clearing: black off the table") << colours << "pink" << "hit:cue:pink hit:pink:black off:black" << "off-table" << 3 << "" << false << false << "black" << "none" << 0 << 7;
        QTest::newRow("cue off the table") << full << "red" << "hit:cue:red-1 off:cue" << "off-table" << 2 << "" << false << true << "" << "none" << 0 << 4;
    }
    void snooker()
    {
        QFETCH(QStringList, balls);
        QFETCH(QString, on);
        QFETCH(QString, script);
        QFETCH(int, points);
        QFETCH(int, foulPoints);
        const SimulationResult r = shot(TableKind::Snooker, balls, script);
        SnookerOn o{};
        QVERIFY(parseSnookerOn(on.toStdString(), o));
        GameSpec game{GameRules::Snooker, {}, o, {}, false};
        const std::optional<Verdict> v = judgeShot(r, game);
        check(v, r);
        QCOMPARE(v->points, points);
        QCOMPARE(v->foulPoints, foulPoints);
    }

    // The cushions are counted by hand in each script: the cue ball's rails before it meets the second
    // object ball.
    void threeCushion_data()
    {
        QTest::addColumn<QString>("script");
        verdictColumns();
        QTest::addColumn<int>("points");
        QTest::newRow("point: red, 3 rails, yellow") << "hit:cue:red rail:cue rail:cue rail:cue hit:cue:yellow" << "" << 5 << "" << true << false << "" << "none" << 1;
        QTest::newRow("point: 3 rails first (ticky-free)") << "rail:cue rail:cue rail:cue hit:cue:red hit:cue:yellow" << "" << 5 << "" << true << false << "" << "none" << 1;
        QTest::newRow("point: one rail twice counts twice") << "hit:cue:red rail:cue rail:cue rail:cue rail:cue hit:cue:yellow" << "" << 6 << "" << true << false << "" << "none" << 1;
        QTest::newRow("near miss: two rails") << "hit:cue:red rail:cue rail:cue hit:cue:yellow rail:cue" << "" << 4 << "" << false << false << "" << "none" << 0;
        QTest::newRow("object ball rails do not count") << "hit:cue:red rail:red rail:red rail:cue hit:cue:yellow" << "" << 5 << "" << false << false << "" << "none" << 0;
        QTest::newRow("red twice, no yellow") << "hit:cue:red rail:cue rail:cue rail:cue hit:cue:red" << "" << -1 << "" << false << false << "" << "none" << 0;
        QTest::newRow("kiss between object balls is no contact") << "hit:red:yellow rail:cue rail:cue rail:cue hit:cue:red" << "" << -1 << "" << false << false << "" << "none" << 0;
        QTest::newRow("no ball") << "rail:cue rail:cue rail:cue" << "" << -1 << "" << false << false << "" << "none" << 0;
        QTest::newRow("cushions after the second do not count") << "hit:cue:red rail:cue hit:cue:yellow rail:cue rail:cue" << "" << 3 << "" << false << false << "" << "none" << 0;
        QTest::newRow("off the table") << "hit:cue:red off:red rail:cue rail:cue rail:cue hit:cue:yellow" << "off-table" << 2 << "" << false << false << "red" << "none" << 0;
    }
    void threeCushion()
    {
        QFETCH(QString, script);
        QFETCH(int, points);
        const SimulationResult r = shot(TableKind::Carom, {"cue", "red", "yellow"}, script);
        const std::optional<Verdict> v = judgeShot(r, GameSpec{GameRules::ThreeCushion, {}, {}, {}, false});
        check(v, r);
        QCOMPARE(v->points, points);
    }

    void noStrikeNoVerdict()
    {
        SimulationResult r = shot(TableKind::Pool9ft, kNine, "");
        r.events.clear();
        QVERIFY(!judgeShot(r, GameSpec{}).has_value());
    }

    void texts()
    {
        const SimulationResult r = shot(TableKind::Pool9ft, kNine, "hit:cue:4 rail:4");
        const std::optional<Verdict> v = judgeShot(r, GameSpec{});
        QVERIFY(v && v->foul);
        QCOMPARE(QString::fromStdString(v->foul->text.english()), QStringLiteral("the cue ball first touched 4, not 1"));
        QCOMPARE(QString::fromStdString(v->text.english()),
                 QStringLiteral("foul (wrong-ball-first): the cue ball first touched 4, not 1; ball in hand for the opponent"));
    }
};

QTEST_GUILESS_MAIN(TestRules)
#include "tst_rules.moc"
