#include "shockgas/app/cli/command.hpp"

#include <CLI/CLI.hpp>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <new>
#include <optional>

#include "shockgas/app/cli/animate.hpp"
#include "shockgas/app/cli/bench_run.hpp"
#include "shockgas/app/cli/info.hpp"
#include "shockgas/app/cli/lab.hpp"
#include "shockgas/app/cli/signals.hpp"
#include "shockgas/app/cli/tail_run.hpp"
#include "shockgas/app/cli/upgrade.hpp"
#include "shockgas/app/directory/result_check.hpp"
#include "shockgas/app/directory/run_directory.hpp"
#include "shockgas/app/ensemble/checkpointer.hpp"
#include "shockgas/app/input/resumed_scene.hpp"
#include "shockgas/app/input/scene_parser.hpp"
#include "shockgas/app/jobs/job.hpp"
#include "shockgas/app/jobs/merge.hpp"
#include "shockgas/app/jobs/run_scene.hpp"
#include "shockgas/app/jobs/statistics_run.hpp"
#include "shockgas/app/records/checkpoint.hpp"
#include "shockgas/app/report/plots.hpp"
#include "shockgas/app/scene/scene.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/core/interrupt.hpp"
#include "shockgas/studies/studies.hpp"
#include "shockgas/studies/tail_study.hpp"
#include "shockgas/version.hpp"

namespace shockgas::app {

namespace {

constexpr int kExitOk = 0, kExitFailure = 1, kExitBadInput = 2;

// A directory as the messages show it: with one trailing "/" ("out/default/").
std::string as_directory(std::string dir) {
  while (dir.size() > 1 && dir.back() == '/') dir.pop_back();
  return dir == "/" ? dir : dir + "/";
}

struct Arguments {
  std::string scene_path, out_dir, result_path, realizations, variants, resume, lab_dir = "out/lab";
  std::vector<std::string> shards;  // merge: shard directories; stats: run, merged run or shard directories
  std::vector<std::string> overrides;
  bool defaults = false, markdown = false, layout = false, quiet = false, no_plots = false, force = false;
  studies::StudyOptions bench;
  studies::TailStudyOptions tail;
  std::vector<double> tail_sizes;  // --N, read as numbers so that 1e7 is allowed
  AnimationRequest animation;      // read as text: animate() says what is allowed
};

// --out "" would name no directory: a run took its default, bench the root.
const CLI::Validator kDirectoryName(
    [](const std::string& value) {
      return value.empty() ? std::string("\"\" is not allowed; allowed: a directory name (not empty)") : "";
    },
    "");

void add_run(CLI::App& app, Arguments& args) {
  auto* run =
      app.add_subcommand("run", "Run a scene (TOML) and write result.h5, summary.json, report.md, plots");
  run->add_option("SCENE", args.scene_path, "scene file, e.g. data/scenes/default.toml");
  auto* out = run->add_option("--out", args.out_dir, "results directory (default out/<scene name>/)")
                  ->check(kDirectoryName);
  run->add_option("--set", args.overrides, "override a scene key: --set particles.r=0.5 (value read as TOML)")
      ->allow_extra_args(false);
  run->add_flag("--quiet,-q", args.quiet, "no progress output");
  run->add_flag("--no-plots", args.no_plots, "skip the PNG plots");
  auto* realizations = run->add_option(
      "--realizations", args.realizations,
      "only realizations A..B-1 of each ensemble (A:B), written as a shard for `shockgas merge`");
  auto* variants = run->add_option("--variants", args.variants,
                                   "only variants A..B-1 of a sweep (A:B), written as a shard");
  run->add_option(
         "--resume", args.resume,
         "continue the interrupted run in DIR from its checkpoint (its scene; SCENE, if given, must match)")
      ->excludes(out)
      ->excludes(realizations)
      ->excludes(variants);
  run->add_flag("--force", args.force, "replace an output directory that holds another scene's results");
}

void add_stats(CLI::App& app, Arguments& args) {
  auto* stats = app.add_subcommand(
      "stats", "Shock statistics over every realization of runs, merged runs or shards (docs/statistics.md)");
  stats
      ->add_option("DIR", args.shards,
                   "run, merged run or shard directories of one gas (other seeds are more realizations)")
      ->required();
  stats->add_option("--out", args.out_dir, "output directory (default out/<scene name>-stats/)")
      ->check(kDirectoryName);
  stats->add_flag("--force", args.force, "replace an output directory that holds another scene's results");
  stats->add_flag("--quiet,-q", args.quiet, "print only where the results are");
  stats->add_flag("--no-plots", args.no_plots, "skip statistics.png");
}

void add_merge(CLI::App& app, Arguments& args) {
  auto* merge =
      app.add_subcommand("merge", "Merge the shards of one run into its result, as if it had run whole");
  merge->add_option("SHARD", args.shards, "shard directories (shockgas run --realizations A:B --out SHARD)")
      ->required();
  merge->add_option("--out", args.out_dir, "results directory (default out/<scene name>/)")
      ->check(kDirectoryName);
  merge->add_flag("--force", args.force, "replace an output directory that holds another scene's results");
  merge->add_flag("--quiet,-q", args.quiet, "no progress output");
  merge->add_flag("--no-plots", args.no_plots, "skip the PNG plots");
}

RunOptions run_options(const Arguments& args) {
  RunOptions options;
  options.out_dir = args.out_dir;
  options.progress = !args.quiet;
  options.plots = !args.no_plots;
  options.realizations = args.realizations;
  options.variants = args.variants;
  options.force = args.force;
  return options;
}

// The scene of `shockgas run --resume DIR [SCENE]`, and the options of the run
// it continues (checkpoint.hpp); InputError for a missing, damaged or foreign checkpoint.
Scene resumed_scene(const Arguments& args, RunOptions& options) {
  const Checkpoint checkpoint = read_checkpoint(args.resume);
  if (args.scene_path.empty() && !args.overrides.empty())
    throw InputError("--set", to_text(args.overrides.front()),
                     "with --resume, only together with the scene file (which must match the checkpoint's)");
  std::optional<Scene> given;
  if (!args.scene_path.empty()) given = load_scene(args.scene_path, args.overrides);
  options.out_dir = args.resume;
  options.realizations = checkpoint.realizations;
  options.variants = checkpoint.variants;
  options.resume = true;
  return checkpoint_scene(checkpoint, given ? &*given : nullptr);
}

int do_run(const Arguments& args) {
  RunOptions options = run_options(args);
  options.checkpoint = true;
  if (args.scene_path.empty() && args.resume.empty())
    throw InputError("run", "", "a scene file (shockgas run SCENE), or --resume DIR");
  const Scene scene = args.resume.empty()
                          ? load_scene(args.scene_path, args.overrides)  // InputError: nothing written
                          : resumed_scene(args, options);
  if (speaks_for_job())  // rank 0 speaks for an MPI job
    for (const Scene& s : scene.has_sweep ? expand_sweep(scene) : std::vector<Scene>{scene})
      if (!s.solver_note.empty())
        std::cerr << "shockgas: note: " << (scene.has_sweep ? s.name + ": " : "") << s.solver_note << "\n";
  const std::string dir = run_scene(scene, options);
  if (!speaks_for_job()) return kExitOk;  // rank 0 writes and speaks for an MPI job
  std::cout << "results in " << as_directory(dir) << "\n";
  return kExitOk;
}

void add_tail(CLI::App& app, Arguments& args) {
  auto* tail =
      app.add_subcommand("tail", "The tail of Phi(z) at sizes beyond a scene: CSV files (docs/paper.md)");
  studies::TailStudyOptions& o = args.tail;
  tail->add_option("--N", args.tail_sizes, "particles per realization, e.g. 1e5,1e6,1e7")->delimiter(',');
  tail->add_option("--realizations", o.realizations, "realizations per size (default 100)");
  tail->add_option("--times", o.times, "increasing times, e.g. 1e3,1e4,1e5")->delimiter(',');
  tail->add_option("--r", o.r, "restitution: 0 = the exact hull (default), > 0 = the event engine");
  tail->add_option("--delta", o.delta, "the engine's threshold (default 1e-2)");
  tail->add_option("--seed", o.seed, "seed of the initial velocities (default 1999)");
  tail->add_option("--bin-width", o.bin_width, "bin width in |z| (default 0.05)");
  tail->add_option("--min-clusters", o.min_clusters, "clusters a bin must hold to count (default 25)");
  tail->add_option("--threads", o.threads, "realizations at once (default 0: every core)");
  tail->add_option("--out", o.out_dir, "output directory (default out/tail)")->check(kDirectoryName);
  tail->add_flag("--force", args.force, "replace an output directory that holds another scene's results");
  tail->add_flag(
      "--quiet,-q", [&o](std::int64_t) { o.progress = false; }, "no progress output");
}

int do_tail(Arguments args) {
  if (!args.tail_sizes.empty()) args.tail.sizes.clear();
  for (const double N : args.tail_sizes) {
    if (!(N >= 0 && N <= studies::kTailMaxN && N == std::floor(N)))
      throw InputError("tail.N", to_text(N), studies::tail_sizes_allowed());
    args.tail.sizes.push_back(static_cast<std::size_t>(N));
  }
  const std::string out = run_tail(args.tail, args.force);  // nothing printed before it returns
  std::cout << "tail results in " << as_directory(out) << "\n";
  return kExitOk;
}

int dispatch(const CLI::App& app, const Arguments& args) {
  if (app.got_subcommand("tail")) return do_tail(args);
  if (app.got_subcommand("run")) return do_run(args);
  if (app.got_subcommand("merge")) {
    const std::string dir = merge_shards(args.shards, run_options(args));
    std::cout << "results in " << as_directory(dir) << "\n";
    return kExitOk;
  }
  if (app.got_subcommand("stats")) {
    const std::string dir =
        run_statistics({args.shards, args.out_dir, args.force, !args.no_plots, args.quiet});
    if (args.quiet) std::cout << "statistics in " << as_directory(dir) << "\n";
    return kExitOk;
  }
  if (app.got_subcommand("info")) {
    if (args.layout) return std::cout << describe_layout(), kExitOk;
    print_info(args.result_path, std::cout);
    return kExitOk;
  }
  if (app.got_subcommand("upgrade")) {
    std::cout << upgrade_answer(args.result_path);
    return kExitOk;
  }
  if (app.got_subcommand("animate")) {
    animate(args.result_path, args.animation);
    std::cout << "animation in " << as_directory(args.result_path) << "\n";
    return kExitOk;
  }
  if (app.got_subcommand("bench")) {
    const BenchOutcome bench = run_bench(args.bench, args.force);
    std::cerr << bench.warnings;
    std::cout << "bench results in " << as_directory(bench.dir) << "\n";
    return kExitOk;
  }
  if (app.got_subcommand("lab")) {
    try {
      std::cout << write_lab(args.lab_dir);
    } catch (const LabMissing& e) {
      std::cerr << "shockgas: " << e.what() << "\n";
      return kExitFailure;
    }
    return kExitOk;
  }
  if (app.got_subcommand("scene")) {
    std::cout << (args.markdown ? scene_reference_markdown() : default_scene_text());
    return kExitOk;
  }
  std::cout << app.help();
  return kExitBadInput;
}

}  // namespace

int run_command(int argc, char** argv) {
  CLI::App app{"shockgas: the 1-D inelastic/sticky gas and the Burgers equation, side by side"};
  app.set_version_flag("--version", std::string("shockgas ") + kVersion + " (commit " + kGitCommit +
                                        ", built for " + kBuildTarget + ")");
  app.require_subcommand(0, 1);
  Arguments args;
  add_run(app, args);
  add_merge(app, args);
  add_stats(app, args);
  auto* info = app.add_subcommand("info", "What a result file holds, its scene and its provenance");
  info->add_option(
      "RESULT", args.result_path,
      "result file or run directory, e.g. out/default (every file its manifest.json lists is checked); "
      "the directory of a stopped run: how far its checkpoint got");
  info->add_flag("--layout", args.layout,
                 "print every dataset and summary key a run may write (docs/output.md)");
  info->require_option(1);
  auto* upgrade = app.add_subcommand(
      "upgrade",
      "Check a result of an older layout: it is read as it is, nothing is rewritten (docs/output.md)");
  upgrade->add_option("RESULT", args.result_path, "result file or run directory, e.g. out/default")
      ->required();
  auto* scene =
      app.add_subcommand("scene", "Print the complete commented scene with every key and its default");
  scene->add_flag("--defaults", args.defaults, "print every key with default, unit and allowed range");
  scene->add_flag("--markdown", args.markdown,
                  "print the reference of every key as markdown (docs/scenes.md)");
  scene->require_option(1);
  auto* anim = app.add_subcommand("animate", "Draw a run's animation (MP4, GIF) from its result.h5");
  anim->add_option("DIR", args.result_path,
                   "a run's output directory (its scene has [output] animation = true)")
      ->required();
  anim->add_option("--fps", args.animation.fps, "frames per second, 1 to 60 (default: 8 s in all, 4 to 24)");
  anim->add_option("--size", args.animation.size, "WxH in pixels, each even (default 1280x720)");
  anim->add_option("--frames", args.animation.frames,
                   "how many of the recorded frames, spread evenly (default: all)");
  auto* bench =
      app.add_subcommand("bench", "Work-precision charts and stability maps of every method (CSV + PNG)");
  bench->add_option("--out", args.bench.out_dir, "output directory (default out/bench)")
      ->check(kDirectoryName);
  bench->add_flag("--full", args.bench.full, "the record size (long) instead of the quick one");
  bench->add_flag("--force", args.force, "replace an output directory that holds another scene's results");
  bench->add_flag(
      "--quiet,-q", [&args](std::int64_t) { args.bench.progress = false; }, "no progress output");
  add_tail(app, args);
  auto* lab = app.add_subcommand("lab", "Write the lab: a page that runs the engine live in a browser");
  lab->add_option("--out", args.lab_dir, "directory of the page (default out/lab); open its index.html")
      ->check(kDirectoryName);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitBadInput;
  }
  // A run that stops early, for whatever reason, leaves its output directory
  // as it was (run_directory.hpp).
  const std::string unchanged = app.got_subcommand("run") || app.got_subcommand("merge") ||
                                        app.got_subcommand("bench") || app.got_subcommand("stats")
                                    ? " (the results in the output directory are as they were)"
                                : app.got_subcommand("tail")
                                    ? " (the output directory is as the last finished size left it, or as it "
                                      "was before the first, each file whole)"
                                    : "";
  try {
    // SIGINT, SIGTERM -> request_interrupt, restored on return; in an MPI job
    // its session owns them (shockgas/app/jobs/mpi_job.cpp) and does the same.
    std::optional<InterruptHandlers> handlers;
    if (!current_job()) handlers.emplace();
    return dispatch(app, args);
  } catch (const InputError& e) {
    report_for_job(std::string("shockgas: error: ") + e.what() + "\n");
    return kExitBadInput;
  } catch (const Interrupted& e) {
    const int sig = e.signal_number();
    const auto* checkpoint = dynamic_cast<const CheckpointTaken*>(&e);
    report_for_job(std::string("shockgas: interrupted") +
                   (sig ? " by signal " + std::to_string(sig) + " (SIG" + sigabbrev_np(sig) + ")" : "") +
                   (checkpoint ? "; " + checkpoint->note() : unchanged) + "\n");
    return sig ? 128 + sig : kExitFailure;
  } catch (const std::bad_alloc&) {
    report_for_job("shockgas: run failed: out of memory" + unchanged + "\n");
    return kExitFailure;
  } catch (const std::exception& e) {
    report_for_job("shockgas: run failed: " + printable(with_staging_as_target(e.what())) + unchanged + "\n");
    return kExitFailure;
  }
}

}  // namespace shockgas::app
