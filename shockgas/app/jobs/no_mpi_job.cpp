// shockgas built without MPI: there is never a job of several processes. A
// launcher that starts several is refused, lest each run the whole scene into
// the same directory.
#include <cstdlib>
#include <iostream>
#include <string>

#include "shockgas/app/jobs/job.hpp"

namespace shockgas::app {

namespace {

// The processes a launcher started (Open MPI's mpirun, PMIx, PMI-2), or 1.
long launched_processes() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_SIZE", "PMI_SIZE"})
    if (const char* n = std::getenv(name)) return std::atol(n);
  return 1;
}

bool first_process() {
  for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"})
    if (const char* r = std::getenv(name)) return std::atol(r) == 0;
  return true;
}

}  // namespace

struct JobSession::State {};

JobSession::JobSession(int&, char**&) {
  if (launched_processes() <= 1) return;
  if (first_process())
    std::cerr << "shockgas: error: started as " << launched_processes()
              << " processes by an MPI launcher, but built without MPI (install libopenmpi-dev and "
                 "rebuild, or run one process)\n";
  std::exit(2);
}

JobSession::~JobSession() = default;
int JobSession::end(int code) { return code; }

Job* current_job() { return nullptr; }
bool speaks_for_job() { return true; }
void report_for_job(const std::string& line) { std::cerr << line; }
bool built_with_mpi() { return false; }

}  // namespace shockgas::app
