#pragma once
// The messages between the ranks of a job (job_ensembles.hpp, JobTag), as
// bytes: numbers as doubles, a work item as its ensemble and index; the clock
// both sides keep; and the side of the ranks other than 0 (job_rank.cpp).
#include <chrono>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "shockgas/app/ensemble/ensemble_plan.hpp"
#include "shockgas/app/jobs/job.hpp"

namespace shockgas::app {

class Checkpointer;

namespace job_messages {

using Clock = std::chrono::steady_clock;

inline constexpr auto kPoll = std::chrono::milliseconds(50);
inline constexpr double kBeatSeconds = 0.2;

inline double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

inline std::string pack(const std::vector<double>& numbers) {
  return std::string(reinterpret_cast<const char*>(numbers.data()), numbers.size() * sizeof(double));
}
inline std::vector<double> unpack(const std::string& bytes) {
  std::vector<double> numbers(bytes.size() / sizeof(double));
  if (!numbers.empty()) std::memcpy(numbers.data(), bytes.data(), numbers.size() * sizeof(double));
  return numbers;
}

// [head..., e0, k0, e1, k1, ...]
inline std::string pack_items(std::vector<double> head, const std::vector<WorkItem>& items) {
  for (const WorkItem& w : items)
    head.push_back(static_cast<double>(w.ensemble)), head.push_back(static_cast<double>(w.index));
  return pack(head);
}
inline std::vector<WorkItem> unpack_items(const std::vector<double>& numbers, std::size_t head) {
  std::vector<WorkItem> items;
  for (std::size_t i = head; i + 1 < numbers.size(); i += 2)
    items.push_back({static_cast<std::size_t>(numbers[i]), static_cast<std::uint64_t>(numbers[i + 1])});
  return items;
}

inline std::string describe(const EnsemblePlan& plan, const std::vector<WorkItem>& items) {
  if (items.empty()) return "between realizations";
  std::string text = "while running ";
  for (std::size_t i = 0; i < items.size(); ++i) text += (i ? ", " : "") + plan.describe(items[i]);
  return text;
}

}  // namespace job_messages

// Ranks 1..K-1: runs the share rank 0 deals this rank (kItems), each record sent
// as it finishes, until rank 0 says every record arrived (kDone) or ends the job.
// checkpoints: this rank's (job_rank, checkpointer.hpp), or nullptr.
void serve_job_rank(Job& job, std::shared_ptr<const EnsemblePlan> plan, std::size_t threads,
                    Checkpointer* checkpoints);

}  // namespace shockgas::app
