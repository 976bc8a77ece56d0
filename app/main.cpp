#include "job.hpp"
#include "shockgas/app/command.hpp"
#include "signals.hpp"

int main(int argc, char** argv) {
  int code = 0;
  {
    shockgas::app::JobSession job(argc, argv);  // an MPI job when started by mpirun or srun
    code = job.end(shockgas::app::run_command(argc, argv));
  }
  shockgas::app::end_as_signalled();  // after SIGINT, SIGTERM: end as killed by it (status 128 + signal)
  return code;
}
