// The one file of shockgas that calls the MPI C API (Open MPI): the job of
// shockgas/app/jobs/job.hpp on MPI_COMM_WORLD. Every call is checked: MPI's default error
// handler aborts the job on failure (MPI_ERRORS_ARE_FATAL), so a call that
// returns has succeeded.
#include <mpi.h>

#include <chrono>
#include <climits>
#include <csignal>
#include <cstdlib>
#include <iostream>
#include <list>
#include <thread>

#include "shockgas/app/ensemble/checkpointer.hpp"
#include "shockgas/app/jobs/job.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/core/interrupt.hpp"

namespace shockgas::app {

namespace {

// A launcher's environment: Open MPI's mpirun, PMIx (srun --mpi=pmix) or PMI-2 (srun --mpi=pmi2).
bool started_by_launcher() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK"})
    if (std::getenv(name)) return true;
  return false;
}

// Rank 0 of a job that keeps checkpoints saves one and stops (checkpointer.hpp);
// the other ranks, and a job without, stop at once.
extern "C" void interrupt_job(int sig) {
  request_interrupt(signals_take_checkpoints() ? InterruptMode::checkpoint : InterruptMode::abort, sig);
}

// A message on its way out: its bytes stay alive until MPI is done with them.
struct Outgoing {
  std::string bytes;
  MPI_Request request = MPI_REQUEST_NULL;
};

class MpiJob : public Job {
 public:
  MpiJob() {
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  ~MpiJob() override {
    for (auto& m : outgoing_) MPI_Wait(&m.request, MPI_STATUS_IGNORE);
  }
  int rank() const override { return rank_; }
  int size() const override { return size_; }

  void send(int dest, int tag, std::string bytes) override {
    if (bytes.size() > static_cast<std::size_t>(INT_MAX))
      throw RunError("a message of " + std::to_string(bytes.size()) +
                     " bytes exceeds what one MPI message holds");
    complete_sent();
    outgoing_.push_back({std::move(bytes)});
    Outgoing& m = outgoing_.back();
    MPI_Isend(m.bytes.data(), static_cast<int>(m.bytes.size()), MPI_BYTE, dest, tag, MPI_COMM_WORLD,
              &m.request);
  }

  std::optional<JobMessage> receive() override {
    complete_sent();
    int arrived = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &arrived, &status);
    if (!arrived) return std::nullopt;
    int count = 0;
    MPI_Get_count(&status, MPI_BYTE, &count);
    JobMessage m{status.MPI_SOURCE, status.MPI_TAG, std::string(static_cast<std::size_t>(count), '\0')};
    MPI_Recv(m.bytes.data(), count, MPI_BYTE, m.source, m.tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    return m;
  }

  void end_all(int code) override { MPI_Abort(MPI_COMM_WORLD, code); }

 private:
  void complete_sent() {
    for (auto it = outgoing_.begin(); it != outgoing_.end();) {
      int done = 0;
      MPI_Test(&it->request, &done, MPI_STATUS_IGNORE);
      it = done ? outgoing_.erase(it) : std::next(it);
    }
  }
  int rank_ = 0, size_ = 1;
  std::list<Outgoing> outgoing_;
};

Job* g_job = nullptr;

}  // namespace

struct JobSession::State {
  MpiJob job;
};

JobSession::JobSession(int& argc, char**& argv) {
  if (!started_by_launcher()) return;
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  state_ = std::make_unique<State>();
  if (state_->job.size() > 1) {
    g_job = &state_->job;
    // The MPI host owns the signals: a launcher ends a job with SIGTERM (and
    // a user with SIGINT, a closed session with SIGHUP); the run stops
    // cooperatively (shockgas/core/interrupt.hpp).
    std::signal(SIGTERM, interrupt_job);
    std::signal(SIGINT, interrupt_job);
    if (std::signal(SIGHUP, interrupt_job) == SIG_IGN) std::signal(SIGHUP, SIG_IGN);  // nohup
    std::signal(SIGPIPE, SIG_IGN);  // a closed stderr ends no job (signals.hpp)
  }
}

JobSession::~JobSession() {
  if (!state_) return;
  g_job = nullptr;
  state_.reset();  // its sends completed
  MPI_Finalize();
}

int JobSession::end(int code) {
  if (code != 0 && g_job) g_job->abort(code);
  return code;
}

Job* current_job() { return g_job; }

bool speaks_for_job() { return !g_job || g_job->rank() == 0; }

void report_for_job(const std::string& line) {
  if (!speaks_for_job()) {
    std::this_thread::sleep_for(std::chrono::duration<double>(kQuietSeconds));
    std::cerr << "(rank " << g_job->rank() << ") ";
  }
  std::cerr << line;
}

bool built_with_mpi() { return true; }

}  // namespace shockgas::app
