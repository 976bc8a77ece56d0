#include "shockgas/app/input/resumed_scene.hpp"

#include "shockgas/app/input/scene_parser.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

Scene checkpoint_scene(const Checkpoint& checkpoint, const Scene* given) {
  if (!given) return parse_scene(checkpoint.scene_text, checkpoint.scene_path, checkpoint.overrides);
  const std::string ours = physics_of(resolved_scene_text(*given)), theirs = physics_of(checkpoint.resolved);
  if (ours != theirs)
    throw InputError(
        "--resume", to_text(given->path),
        "the scene the checkpoint was taken of (it differs in " + first_difference(ours, theirs) + ")");
  return *given;
}

}  // namespace shockgas::app
