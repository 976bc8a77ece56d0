#pragma once
// Which directories a run may replace. A run replaces its output directory as
// a whole (run_directory.hpp), so it refuses a directory whose loss would hurt
// or surprise: the root, the current, home or source directory or one above
// them, a mount point, a directory holding files shockgas did not write, and,
// unless forced, the results of another scene. Every refusal is an InputError
// naming --out, before any work.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace shockgas::app {

// The target as the run will use it: absolute, with symbolic links resolved.
std::filesystem::path resolve_target(const std::filesystem::path& out);

// The refusals that need only the path (the root, protected directories, not a
// directory, a mount point, another user's directory in a sticky directory);
// out is the --out as given, for the message.
void check_target_path(const std::filesystem::path& target, const std::string& out);

// The refusals that need the contents (foreign files, another scene's results
// without force). Called with the directory's lock held.
void check_target_contents(const std::filesystem::path& target, const std::string& out,
                           const std::string& scene, bool force);

// Refuses a target that is, or holds, one of the inputs a command reads (the
// shards of a merge: replacing the output directory would replace them), or
// lies inside one (it would change that input). what names an input in the
// message ("shard being merged").
void check_target_spares(const std::filesystem::path& target, const std::string& out,
                         const std::vector<std::string>& inputs, const std::string& what);

// What a run keeps in its output directory while it computes (relative: a
// path in it): the checkpoint and the running realizations' saved states (with
// the temporary files of killed writes), realization 0's state files.
bool run_in_progress_file(const std::filesystem::path& relative);

// Whether a file (a path relative to a run directory) has a name that a run
// writes there: result.h5, summary.json, the reports, a picture or movie, a
// plotting log, `shockgas tail`'s tables, a variant's manifest.json.
bool run_output_name(const std::filesystem::path& relative);

// The scene whose results dir holds: from its manifest.json, or the
// summary.json of an older version; nullopt if neither names one.
std::optional<std::string> scene_of_results(const std::filesystem::path& dir);

}  // namespace shockgas::app
