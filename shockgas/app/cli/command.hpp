#pragma once
// The `shockgas` command: run, info, scene, bench. Exit codes: 0 success, 2 bad
// input (nothing written), 1 failure during a run, 128 + signal after SIGINT
// (130) or SIGTERM (143); a run that does not succeed leaves its output
// directory as it was.
namespace shockgas::app {

int run_command(int argc, char** argv);

}  // namespace shockgas::app
