#pragma once
// The `shockgas` command: run, info, scene. Exit codes: 0 success, 2 bad
// input (nothing written), 1 failure during a run.
namespace shockgas::app {

int run_command(int argc, char** argv);

}  // namespace shockgas::app
