#pragma once
// `shockgas animate DIR`: the animation of a run, drawn from its result.h5 alone
// (plots/animate.py: animation.mp4, animation.gif, animation.png), and its
// report.html written again with it.
#include <string>

namespace shockgas::app {

// Throws InputError naming output.animation if DIR/result.h5 holds no frames
// (the run did not ask for an animation), or naming DIR if it holds no result.
// A missing ffmpeg, matplotlib or python is a warning, as for the plots.
void animate(const std::string& dir);

// Whether the result file at path holds the frames of an animation.
bool has_frames(const std::string& result_path);

}  // namespace shockgas::app
