#pragma once
// `shockgas animate DIR`: the animation of a run, drawn from its result.h5 alone
// (plots/animate.py: animation.mp4, animation.gif, animation.png), and its
// report.html written again with it.
#include <cstddef>
#include <string>

namespace shockgas::app {

// The options of `shockgas animate`, as given ("": the default).
struct AnimationRequest {
  std::string fps;     // frames per second, 1 to 60 (default: the frames over 8 s, 4 to 24)
  std::string size;    // WxH in pixels, each even (H.264 halves the colour planes), 160x90 to 3840x2160
  std::string frames;  // how many of the recorded frames, spread evenly: 2 to all of them
};

// Throws InputError naming output.animation if DIR/result.h5 holds no frames
// (the run did not ask for an animation), naming DIR if it holds no result, or
// naming the option (--fps, --size, --frames) whose value is not allowed, with
// what is. A missing ffmpeg, matplotlib or python is a warning, as for the plots.
void animate(const std::string& dir, const AnimationRequest& request = {});

// How many frames of an animation the result file at path holds (0: none).
std::size_t recorded_frames(const std::string& result_path);

}  // namespace shockgas::app
