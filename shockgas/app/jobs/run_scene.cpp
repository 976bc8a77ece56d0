#include "shockgas/app/jobs/run_scene.hpp"

#include <filesystem>
#include <optional>

#include "shockgas/app/directory/run_target.hpp"
#include "shockgas/app/jobs/parallel_run.hpp"
#include "shockgas/app/run/resources.hpp"
#include "shockgas/app/run/run_internal.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

std::string run_scene(const Scene& scene, const RunOptions& options) {
  const fs::path out = options.out_dir.empty() ? fs::path("out") / scene.name : fs::path(options.out_dir);
  // Everything that can refuse the scene does so before any work; the resources
  // first, before the initial condition takes its memory, and the output
  // directory (a shard's is its own, partial_outputs.hpp).
  check_resources(scene, out, options.plots);
  if (options.realizations.empty() && options.variants.empty()) {
    const fs::path target = resolve_target(out);
    check_target_path(target, out.string());
    check_target_contents(target, out.string(), scene.name, options.force);
  }
  if (runs_in_parallel(options)) {
    try {
      return run_parallel(scene, out, options);
    } catch (const InputError& e) {  // a rule checked where the work starts (the engine's own)
      throw located(e, scene);
    }
  }
  std::optional<SweepPlan> sweep;
  std::optional<InitialCondition> initial;
  if (scene.has_sweep)
    sweep = plan_sweep(scene);
  else {
    initial.emplace(build_initial(scene));
    preflight(scene, *initial);
  }
  return into_run_directory(out, scene, options, [&](const fs::path& staging) {
    if (sweep)
      run_sweep(scene, *sweep, staging, options);
    else
      run_single(scene, *initial, staging, options);
  });
}

}  // namespace shockgas::app
