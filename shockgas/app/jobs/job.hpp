#pragma once
// The processes of a job launched by mpirun or srun, and the messages between
// them: what shockgas needs of MPI and nothing more. The MPI C API is called in
// one file only, shockgas/app/jobs/mpi_job.cpp (built when CMake finds MPI: SHOCKGAS_MPI);
// everything else sees this interface. Without MPI, or when the program was not
// started by a launcher, there is no job and shockgas runs as one process.
//
// Only the thread that created the JobSession calls these functions
// (MPI_THREAD_FUNNELED): the workers compute, the main thread talks.
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>

namespace shockgas::app {

struct JobMessage {
  int source = 0;
  int tag = 0;
  std::string bytes;
};

class Job {
 public:
  virtual ~Job() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  // Queues a message to `dest`; returns at once, the message goes out in the
  // background (receive() and the destructor complete it).
  virtual void send(int dest, int tag, std::string bytes) = 0;
  // A message that has arrived from any rank, if one has.
  virtual std::optional<JobMessage> receive() = 0;
  // Ends every process of the job with exit status `code` (the launcher reports it).
  [[noreturn]] void abort(int code) {
    end_all(code);
    std::_Exit(code);  // end_all does not return
  }

 protected:
  virtual void end_all(int code) = 0;
};

// The job of this process: set while a JobSession of more than one process is
// alive, else nullptr.
Job* current_job();

// Joins the job when the program was started by a launcher (mpirun, srun) and
// shockgas was built with MPI; else does nothing. Leaves it on destruction.
class JobSession {
 public:
  JobSession(int& argc, char**& argv);
  ~JobSession();
  JobSession(const JobSession&) = delete;
  JobSession& operator=(const JobSession&) = delete;
  // The process's exit status: on a failure of a job of several processes,
  // every process is ended (a rank that stopped early would leave the others
  // waiting for it); otherwise `code`.
  int end(int code);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// Whether this process speaks for the job (prints errors and results): rank 0,
// or the only process.
bool speaks_for_job();

// Prints an error line (with newline) on stderr for the job: at once from the
// process that speaks for it; another rank waits kQuietSeconds for rank 0,
// which fails the same way on the same input, to say it and end the job, and
// says it itself, naming its rank, only if rank 0 has not (it alone failed: a
// scene file missing on its node, say).
void report_for_job(const std::string& line);
inline constexpr double kQuietSeconds = 2;

// Whether shockgas was built with MPI.
bool built_with_mpi();

}  // namespace shockgas::app
