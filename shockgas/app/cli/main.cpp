#include "shockgas/app/cli/command.hpp"
#include "shockgas/app/cli/signals.hpp"
#include "shockgas/app/jobs/job.hpp"

int main(int argc, char** argv) {
  int code = 0;
  bool one_process = true;
  {
    shockgas::app::JobSession job(argc, argv);  // an MPI job when started by mpirun or srun
    one_process = shockgas::app::current_job() == nullptr;
    code = job.end(shockgas::app::run_command(argc, argv));
  }
  // After SIGINT, SIGTERM: end as killed by it (status 128 + signal); the
  // ranks of an MPI job end as their launcher expects (job.hpp).
  if (one_process) shockgas::app::end_as_signalled();
  return code;
}
