#include "partial_outputs.hpp"

#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <fstream>
#include <mutex>

#include "checkpointer.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/core/interrupt.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

namespace {

// Temporary files of every open PartialOutputs (a sweep nests one per variant
// inside its own), removed if the run is interrupted (SIGINT, SIGTERM).
constexpr int kMaxPartial = 8;
char g_partial[kMaxPartial][4096];
volatile std::sig_atomic_t g_partial_count = 0;

extern "C" void remove_partials_and_exit(int sig) {
  if (signals_take_checkpoints()) {  // the run saves a checkpoint and stops (checkpointer.hpp)
    request_interrupt(InterruptMode::checkpoint, sig);
    return;
  }
  for (int i = 0; i < g_partial_count; ++i) unlink(g_partial[i]);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

// Guards the list above against runs on several threads (the handler only reads it).
std::mutex g_mutex;

}  // namespace

PartialOutputs::PartialOutputs(const fs::path& dir) : dir_(dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InputError("--out", to_text(dir.string()), "a directory that can be created and written");
  const std::string tag = ".partial-" + std::to_string(getpid());
  h5_tmp_ = (dir / "result.h5").string() + tag;
  json_tmp_ = (dir / "summary.json").string() + tag;
  std::lock_guard lock(g_mutex);
  if (g_partial_count + 2 > kMaxPartial) throw RunError("too many nested result directories");
  for (const auto& path : {h5_tmp_, json_tmp_}) {
    const int slot = g_partial_count;
    std::snprintf(g_partial[slot], sizeof g_partial[0], "%s", path.c_str());
    g_partial_count = slot + 1;  // published after the path is complete
  }
}

PartialOutputs::~PartialOutputs() {
  std::error_code ec;
  fs::remove(h5_tmp_, ec);  // no-op once renamed
  fs::remove(json_tmp_, ec);
  std::lock_guard lock(g_mutex);
  // Its slots are emptied (unlink("") fails harmlessly); the list shrinks past
  // empty slots at its top (runs on other threads may hold the ones above).
  for (int i = 0; i < g_partial_count; ++i)
    if (h5_tmp_ == g_partial[i] || json_tmp_ == g_partial[i]) g_partial[i][0] = '\0';
  while (g_partial_count > 0 && g_partial[g_partial_count - 1][0] == '\0')
    g_partial_count = g_partial_count - 1;
}

void remove_partial_outputs_on_signals() {
  std::signal(SIGINT, remove_partials_and_exit);
  std::signal(SIGTERM, remove_partials_and_exit);
}

void PartialOutputs::commit(const nlohmann::ordered_json& summary) {
  {
    std::ofstream out(json_tmp_);
    out << summary.dump(2) << "\n";
    if (!out) throw RunError("cannot write " + json_tmp_);
  }
  fs::rename(h5_tmp_, dir_ / "result.h5");
  fs::rename(json_tmp_, dir_ / "summary.json");
}

}  // namespace shockgas::app
