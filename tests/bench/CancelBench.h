#pragma once
// cuelab-bench --cancel FILE...: how fast a running simulation answers its cancel token (issue 39).

namespace cuelab::bench {

// For each setup file: runs it on a thread, trips its token after 50 ms, 100 ms, ... (TRIALS runs) and
// prints one JSON object with each file's latencies (ms from the request to simulate's return: median,
// max) and the events reached. Exit 1 when a file cannot be read.
int cancelCommand(int argc, char** argv);

}  // namespace cuelab::bench
