#include "job.hpp"
#include "shockgas/app/command.hpp"

int main(int argc, char** argv) {
  shockgas::app::JobSession job(argc, argv);  // an MPI job when started by mpirun or srun
  return job.end(shockgas::app::run_command(argc, argv));
}
