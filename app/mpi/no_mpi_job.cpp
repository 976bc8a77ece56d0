// shockgas built without MPI: there is never a job of several processes.
#include <iostream>

#include "../job.hpp"

namespace shockgas::app {

struct JobSession::State {};

JobSession::JobSession(int&, char**&) {}
JobSession::~JobSession() = default;
int JobSession::end(int code) { return code; }

Job* current_job() { return nullptr; }
bool speaks_for_job() { return true; }
void report_for_job(const std::string& line) { std::cerr << line; }
bool built_with_mpi() { return false; }

}  // namespace shockgas::app
