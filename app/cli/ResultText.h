#pragma once
// The text cuelab-cli prints for a simulation (CONTRACT.md): the event log and ball states as JSON,
// the trajectory as CSV. Numbers use the shortest text that reads back to the same double.

#include "FrameTimes.h"  // frameTime: the one definition of frame times (core/setup)
#include "JsonText.h"
#include "ShotOutcome.h"
#include "Simulation.h"
#include "Verdict.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace cuelab::cli {

// `simulate`: { "end_time": ..., "events": [...], "balls": [...], "outcome": {...} }, one event or
// ball per line. With a game (the setup's), the outcome gains its "verdict" (CONTRACT.md, Extensions
// version 3); without one the text is what it always was.
std::string simulationJson(const SimulationResult& result, const GameSpec* game = nullptr);

// The `outcome` object of CONTRACT.md (Extensions) as the value of a key just written, e.g.
// `w.key("outcome"); writeOutcome(w, result, shotOutcome(result), Layout::Line);` for one line.
// `simulate` lays it out one member per line (Block); inside a Line container it is one line anyway.
void writeOutcome(io::JsonWriter& w, const SimulationResult& result, const ShotOutcome& outcome,
                  io::JsonWriter::Layout layout = io::JsonWriter::Layout::Block, const GameSpec* game = nullptr);

// The `verdict` object (one line) as the value of a key just written; null for no verdict (no shot).
void writeVerdict(io::JsonWriter& w, const SimulationResult& result, const std::optional<rules::Verdict>& verdict);

// `state --at T`: { "time": T, "balls": [...] } with the exact state of every ball at t.
std::string stateJson(const SimulationResult& result, double t);

// `trajectory`: the header time,ball,state,x,y,vx,vy,wx,wy,wz,z,vz, then one row per ball at every
// frame time in [0, endTime] and at every event time (the state just after the event).
std::string trajectoryCsv(const SimulationResult& result, double frameDt);

// The same text for long exports (the window's File > Export): progress(fraction done) is called now
// and then; when it returns false the work stops and the result is empty.
using Progress = std::function<bool(double fraction)>;
std::optional<std::string> trajectoryCsv(const SimulationResult& result, double frameDt, const Progress& progress);

// The same frames as JSON: { "frame_dt": S, "frames": [ { "time": t, "balls": [ ...as simulate... ] } ] },
// one frame per line.
std::optional<std::string> trajectoryJson(const SimulationResult& result, double frameDt, const Progress& progress = {});

// The event log as CSV, one row per event and agent: index,time,type,ball,other,cushion,pocket, then
// the agent's state before and after (state,x,y,vx,vy,wx,wy,wz each), then z,vz before and after.
std::string eventsCsv(const SimulationResult& result);

}  // namespace cuelab::cli
