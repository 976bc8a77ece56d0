#pragma once
// The scene a checkpoint was taken of, for `shockgas run --resume DIR`.
#include "shockgas/app/records/checkpoint.hpp"
#include "shockgas/app/scene/scene.hpp"

namespace shockgas::app {

// The scene parsed from the checkpoint's text, path and overrides. given: a
// scene also named on the command line, which must have the same resolved
// parameters but for the thread count (InputError naming the first line that
// differs); nullptr for none.
Scene checkpoint_scene(const Checkpoint& checkpoint, const Scene* given);

}  // namespace shockgas::app
