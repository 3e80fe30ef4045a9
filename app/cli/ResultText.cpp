#include "ResultText.h"

#include "JsonText.h"

#include <algorithm>
#include <array>
#include <charconv>

namespace cuelab::cli {

namespace {

using io::JsonWriter;
using Layout = JsonWriter::Layout;

const std::string& pocketId(const SimulationResult& result, int pocket)
{
    return result.table.pockets.at(static_cast<std::size_t>(pocket)).id;
}

void writeBallState(JsonWriter& w, const SimulationResult& result, int ball, const BallState& s)
{
    w.beginObject(Layout::Line);
    w.key("id");
    w.value(result.balls.at(static_cast<std::size_t>(ball)).id);
    w.key("state");
    w.value(toString(s.motion));
    if (s.motion == MotionState::Pocketed) {
        w.key("pocket");
        w.value(pocketId(result, s.pocket));
    }
    w.key("position");
    w.numbers(s.position.data(), 2);
    w.key("velocity");
    w.numbers(s.velocity.data(), 2);
    w.key("spin");
    w.numbers(s.spin.data(), 3);
    // CONTRACT.md "Airborne balls": the centre's height above its resting height and its vertical
    // velocity (0 and 0 on the cloth).
    w.key("z");
    w.value(s.z);
    w.key("vz");
    w.value(s.vz);
    w.endObject();
}

void writeEvent(JsonWriter& w, const SimulationResult& result, const Event& e)
{
    const int agents = e.kind == EventKind::BallBall ? 2 : 1;
    w.beginObject(Layout::Line);
    w.key("time");
    w.value(e.time);
    w.key("type");
    w.value(toString(e.kind));
    w.key("balls");
    w.beginArray(Layout::Line);
    for (int i = 0; i < agents; ++i) w.value(result.balls.at(static_cast<std::size_t>(e.balls[i])).id);
    w.endArray();
    // A jaw is a rounded cushion tip: the file format names it as the cushion of a ball-cushion event.
    if (e.kind == EventKind::BallCushion) {
        w.key("cushion");
        w.value(result.table.cushions.at(static_cast<std::size_t>(e.cushion)).id);
    } else if (e.kind == EventKind::BallJaw) {
        w.key("cushion");
        w.value(result.table.jaws.at(static_cast<std::size_t>(e.jaw)).id);
    } else if (e.kind == EventKind::BallPocket) {
        w.key("pocket");
        w.value(pocketId(result, e.pocket));
    }
    auto writeStates = [&](const char* key, const std::array<BallState, 2>& states) {
        w.key(key);
        w.beginArray(Layout::Line);
        for (int i = 0; i < agents; ++i) writeBallState(w, result, e.balls[i], states[i]);
        w.endArray();
    };
    writeStates("before", e.before);
    writeStates("after", e.after);
    w.endObject();
}

void writeBalls(JsonWriter& w, const SimulationResult& result, double t)
{
    const std::vector<BallState> states = result.statesAt(t);
    w.key("balls");
    w.beginArray(Layout::Block);
    for (std::size_t i = 0; i < states.size(); ++i) writeBallState(w, result, static_cast<int>(i), states[i]);
    w.endArray();
}

// RFC 4180: a field holding a comma, a quote or a line break is quoted, its quotes doubled.
std::string csvField(const std::string& text)
{
    if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
    std::string quoted = "\"";
    for (const char c : text) {
        if (c == '"') quoted += '"';
        quoted += c;
    }
    return quoted + '"';
}

}  // namespace

void writeVerdict(JsonWriter& w, const SimulationResult& result, const std::optional<rules::Verdict>& verdict)
{
    if (!verdict) {
        w.null();
        return;
    }
    const rules::Verdict& v = *verdict;
    auto ids = [&](const std::vector<int>& balls) {
        w.beginArray(Layout::Line);
        for (const int b : balls) w.value(result.balls.at(static_cast<std::size_t>(b)).id);
        w.endArray();
    };
    w.beginObject(Layout::Line);
    w.key("rules");
    w.value(std::string(toString(v.rules)));
    w.key("legal");
    w.value(v.legal());
    w.key("foul");
    if (v.foul) {
        w.beginObject(Layout::Line);
        w.key("rule");
        w.value(std::string(toString(v.foul->rule)));
        w.key("event");
        w.value(v.foul->event);
        w.key("text");
        w.value(v.foul->text.english());
        w.endObject();
    } else {
        w.null();
    }
    w.key("scored");
    ids(v.scored);
    w.key("points");
    w.value(v.points);
    w.key("foul_points");
    w.value(v.foulPoints);
    w.key("continues");
    w.value(v.continues);
    w.key("ball_in_hand");
    w.value(v.ballInHand);
    w.key("respotted");
    ids(v.respotted);
    // Beyond the contract's keys: how the rack ends, the deciding event of any verdict, its line.
    w.key("ends");
    if (v.ends == rules::GameEnd::None) w.null();
    else w.value(std::string(toString(v.ends)));
    w.key("event");
    if (v.event >= 0) w.value(v.event);
    else w.null();
    w.key("text");
    w.value(v.text.english());
    w.endObject();
}

void writeOutcome(JsonWriter& w, const SimulationResult& result, const ShotOutcome& o, Layout layout, const GameSpec* game)
{
    auto id = [&](int ball) -> const std::string& { return result.balls.at(static_cast<std::size_t>(ball)).id; };
    w.beginObject(layout);
    w.key("struck_ball");
    if (o.struckBall >= 0)
        w.value(id(o.struckBall));
    else
        w.null();
    w.key("first_contact");
    if (o.firstContact) {
        w.beginObject(Layout::Line);
        w.key("ball");
        w.value(id(o.firstContact->ball));
        w.key("time");
        w.value(o.firstContact->time);
        w.endObject();
    } else {
        w.null();
    }
    w.key("pocketed");
    w.beginArray(Layout::Line);
    for (const PocketedBall& p : o.pocketed) {
        w.beginObject(Layout::Line);
        w.key("ball");
        w.value(id(p.ball));
        w.key("pocket");
        w.value(pocketId(result, p.pocket));
        w.key("time");
        w.value(p.time);
        w.endObject();
    }
    w.endArray();
    w.key("cushion_hits");
    w.beginObject(Layout::Line);
    for (std::size_t b = 0; b < o.cushionHits.size(); ++b) {
        w.key(id(static_cast<int>(b)));
        w.value(o.cushionHits[b]);
    }
    w.endObject();
    w.key("cushions_before_first_contact");
    w.value(o.cushionsBeforeFirstContact);
    w.key("struck_ball_pocketed");
    w.value(o.struckBallPocketed);
    w.key("off_table");  // balls that left the table, in time order (an additive key)
    w.beginArray(Layout::Line);
    for (const OffTableBall& b : o.offTable) {
        w.beginObject(Layout::Line);
        w.key("ball");
        w.value(id(b.ball));
        w.key("time");
        w.value(b.time);
        w.endObject();
    }
    w.endArray();
    if (game) {
        w.key("verdict");
        writeVerdict(w, result, rules::judgeShot(result, *game));
    }
    w.endObject();
}

std::string simulationJson(const SimulationResult& result, const GameSpec* game)
{
    JsonWriter w;
    w.beginObject(Layout::Block);
    w.key("end_time");
    w.value(result.endTime);
    w.key("events");
    w.beginArray(Layout::Block);
    for (const Event& e : result.events) writeEvent(w, result, e);
    w.endArray();
    writeBalls(w, result, result.endTime);
    w.key("outcome");
    writeOutcome(w, result, shotOutcome(result), Layout::Block, game);
    w.endObject();
    return w.text();
}

std::string stateJson(const SimulationResult& result, double t)
{
    JsonWriter w;
    w.beginObject(Layout::Block);
    w.key("time");
    w.value(t);
    writeBalls(w, result, t);
    w.endObject();
    return w.text();
}

namespace {

// Frame times come from k, never from a running sum, so that they do not drift.
std::vector<double> trajectoryTimes(const SimulationResult& result, double frameDt)
{
    std::vector<double> times;
    for (long long k = 0; frameTime(k, frameDt) <= result.endTime; ++k) times.push_back(frameTime(k, frameDt));
    for (const Event& e : result.events) times.push_back(e.time);
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    return times;
}

void appendStateFields(std::string& out, const BallState& s)
{
    out += toString(s.motion);
    for (const double x : {s.position.x(), s.position.y(), s.velocity.x(), s.velocity.y(), s.spin.x(), s.spin.y(),
                           s.spin.z()}) {
        out += ',';
        out += io::roundTripNumber(x);
    }
}

// The trajectory's and the event table's last columns (CONTRACT.md "Airborne balls": added at the
// end of each row, so a reader of the older columns reads them as before).
void appendHeight(std::string& out, const BallState& s)
{
    out += ',';
    out += io::roundTripNumber(s.z);
    out += ',';
    out += io::roundTripNumber(s.vz);
}

// How often a long export asks whether to go on: every this many frames.
constexpr std::size_t kProgressEvery = 256;

}  // namespace

std::string trajectoryCsv(const SimulationResult& result, double frameDt)
{
    return *trajectoryCsv(result, frameDt, Progress{});
}

std::optional<std::string> trajectoryCsv(const SimulationResult& result, double frameDt, const Progress& progress)
{
    const std::vector<double> times = trajectoryTimes(result, frameDt);
    std::vector<std::string> ids;
    for (const Ball& b : result.balls) ids.push_back(csvField(b.id));

    std::string out = "time,ball,state,x,y,vx,vy,wx,wy,wz,z,vz\n";
    for (std::size_t k = 0; k < times.size(); ++k) {
        if (progress && k % kProgressEvery == 0 && !progress(static_cast<double>(k) / static_cast<double>(times.size())))
            return std::nullopt;
        const double t = times[k];
        const std::string time = io::roundTripNumber(t);
        const std::vector<BallState> states = result.statesAt(t);
        for (std::size_t i = 0; i < states.size(); ++i) {
            out += time;
            out += ',';
            out += ids[i];
            out += ',';
            appendStateFields(out, states[i]);
            appendHeight(out, states[i]);
            out += '\n';
        }
    }
    return out;
}

std::optional<std::string> trajectoryJson(const SimulationResult& result, double frameDt, const Progress& progress)
{
    const std::vector<double> times = trajectoryTimes(result, frameDt);
    JsonWriter w;
    w.beginObject(Layout::Block);
    w.key("frame_dt");
    w.value(frameDt);
    w.key("frames");
    w.beginArray(Layout::Block);
    for (std::size_t k = 0; k < times.size(); ++k) {
        if (progress && k % kProgressEvery == 0 && !progress(static_cast<double>(k) / static_cast<double>(times.size())))
            return std::nullopt;
        const std::vector<BallState> states = result.statesAt(times[k]);
        w.beginObject(Layout::Line);
        w.key("time");
        w.value(times[k]);
        w.key("balls");
        w.beginArray(Layout::Line);
        for (std::size_t i = 0; i < states.size(); ++i) writeBallState(w, result, static_cast<int>(i), states[i]);
        w.endArray();
        w.endObject();
    }
    w.endArray();
    w.endObject();
    return w.text();
}

std::string eventsCsv(const SimulationResult& result)
{
    std::string out = "index,time,type,ball,other,cushion,pocket,"
                      "state_before,x_before,y_before,vx_before,vy_before,wx_before,wy_before,wz_before,"
                      "state_after,x_after,y_after,vx_after,vy_after,wx_after,wy_after,wz_after,"
                      "z_before,vz_before,z_after,vz_after\n";
    for (std::size_t n = 0; n < result.events.size(); ++n) {
        const Event& e = result.events[n];
        const int agents = e.kind == EventKind::BallBall ? 2 : 1;
        std::string cushion;
        if (e.kind == EventKind::BallCushion) cushion = result.table.cushions.at(static_cast<std::size_t>(e.cushion)).id;
        if (e.kind == EventKind::BallJaw) cushion = result.table.jaws.at(static_cast<std::size_t>(e.jaw)).id;
        const std::string pocket = e.kind == EventKind::BallPocket ? pocketId(result, e.pocket) : std::string();
        for (int a = 0; a < agents; ++a) {
            out += std::to_string(n) + ',' + io::roundTripNumber(e.time) + ',' + std::string(toString(e.kind)) + ',';
            out += csvField(result.balls.at(static_cast<std::size_t>(e.balls[a])).id) + ',';
            if (agents == 2) out += csvField(result.balls.at(static_cast<std::size_t>(e.balls[1 - a])).id);
            out += ',' + csvField(cushion) + ',' + csvField(pocket) + ',';
            appendStateFields(out, e.before[a]);
            out += ',';
            appendStateFields(out, e.after[a]);
            appendHeight(out, e.before[a]);
            appendHeight(out, e.after[a]);
            out += '\n';
        }
    }
    return out;
}

}  // namespace cuelab::cli
