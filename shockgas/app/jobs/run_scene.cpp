#include "shockgas/app/jobs/run_scene.hpp"

#include <algorithm>
#include <filesystem>
#include <optional>

#include "shockgas/app/directory/run_directory.hpp"
#include "shockgas/app/directory/run_target.hpp"
#include "shockgas/app/jobs/job.hpp"
#include "shockgas/app/jobs/parallel_run.hpp"
#include "shockgas/app/run/resources.hpp"
#include "shockgas/app/run/run_internal.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

namespace {

// out/<name>.shard-A-B[-vC-D] for a shard without --out, out/<name> for a run.
fs::path output_directory(const Scene& scene, const RunOptions& options) {
  if (!options.out_dir.empty()) return options.out_dir;
  if (options.realizations.empty() && options.variants.empty()) return fs::path("out") / scene.name;
  std::string name = scene.name + ".shard-" + options.realizations +
                     (options.variants.empty() ? "" : "-v" + options.variants);
  std::replace(name.begin(), name.end(), ':', '-');
  return fs::path("out") / name;
}

}  // namespace

std::string run_scene(const Scene& scene, const RunOptions& options) {
  const fs::path out = output_directory(scene, options);
  // Everything that can refuse the scene does so before any work: the
  // resources first, before the initial condition takes its memory, then the
  // output directory, which is locked and staged from now on (by the process
  // that writes it: rank 0 of a job; the other ranks check its path only).
  check_resources(scene, out, options.plots);
  std::optional<RunDirectory> dir;
  if (speaks_for_job())
    dir.emplace(out, scene.name, options.force);
  else
    check_target_path(resolve_target(out), out.string());
  if (runs_in_parallel(options)) {
    try {
      return run_parallel(scene, out, options, dir ? &*dir : nullptr);
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
  return into_run_directory(*dir, out, scene, options, [&](const fs::path& staging) {
    if (sweep)
      run_sweep(scene, *sweep, staging, options);
    else
      run_single(scene, *initial, staging, options);
  });
}

}  // namespace shockgas::app
