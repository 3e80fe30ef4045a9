#pragma once
// The text cuelab-cli prints for a simulation (CONTRACT.md): the event log and ball states as JSON,
// the trajectory as CSV. Numbers use the shortest text that reads back to the same double.

#include "Simulation.h"

#include <string>
#include <vector>

namespace cuelab::cli {

// `simulate`: { "end_time": ..., "events": [...], "balls": [...] }, one event or ball per line.
std::string simulationJson(const SimulationResult& result);

// `state --at T`: { "time": T, "balls": [...] } with the exact state of every ball at t.
std::string stateJson(const SimulationResult& result, double t);

// `trajectory`: the header time,ball,state,x,y,vx,vy,wx,wy,wz, then one row per ball at every
// frame k * frameDt in [0, endTime] and at every event time (the state just after the event).
std::string trajectoryCsv(const SimulationResult& result, double frameDt);

}  // namespace cuelab::cli
