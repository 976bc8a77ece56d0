#pragma once
// Fault injection for the tests of the run directory (tests/app/test_run_faults.cpp).
//
// SHOCKGAS_FAULT=point[:n] kills the process with SIGKILL the n-th time (default:
// the first) it passes the named point, so that a test can show what a run
// killed there leaves behind; SHOCKGAS_FAULT=point[:n]:stop stops it there
// (SIGSTOP) once, for a test to change the world (fill the disk) before it
// continues. The variable is read here and nowhere else; a process without it
// passes every point at the cost of one comparison.
//
// The points: "compute" (each progress report of a computation), "write:result.h5"
// (each dataset), "write:<file>" (half-way through each text file, e.g.
// "write:summary.json"), "plot" (each poll while the plotting process runs),
// "swap" (the finished directory about to replace the previous one),
// "swapped" (replaced, the previous contents not yet removed), "checkpoint"
// (a checkpoint or a running realization's state written in full), "state"
// (a state written in full by a rank other than 0 of an MPI job) and
// "published" (a step of a result that grows in steps in place: a size of
// `shockgas tail`).
#include <string_view>

namespace shockgas::app {

void fault_point(std::string_view point);

}  // namespace shockgas::app
