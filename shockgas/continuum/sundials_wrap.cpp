#include "shockgas/continuum/sundials_wrap.hpp"

#include <arkode/arkode_bandpre.h>
#include <cvode/cvode_bandpre.h>
#include <cvode/cvode_ls.h>
#include <sunlinsol/sunlinsol_spgmr.h>

#include "shockgas/core/error.hpp"

namespace shockgas::continuum::sundials {

template <class... Arguments>
struct Call {
  int (*function)(void*, Arguments...);
  const char* name;
};

struct Package {
  const char* name;  // opens every error message
  void (*free)(void**);
  int normal_task;
  Call<CVErrHandlerFn, void*> set_error_handler;  // ARKErrHandlerFn is the same type
  Call<void*> set_user_data;
  Call<double, double> set_tolerances;
  Call<long> set_max_steps;
  Call<double> set_stop_time;
  Call<SUNLinearSolver, SUNMatrix> set_linear_solver;
  Call<sunindextype, sunindextype, sunindextype> band_preconditioner;
  Call<double, N_Vector, double*, int> evolve;
  Call<long*> steps, nonlinear_iterations, linear_iterations, error_test_failures, preconditioner_setups;
};

namespace {

const Package kCvode = {
    .name = "CVODE",
    .free = CVodeFree,
    .normal_task = CV_NORMAL,
    .set_error_handler = {CVodeSetErrHandlerFn, "CVodeSetErrHandlerFn"},
    .set_user_data = {CVodeSetUserData, "CVodeSetUserData"},
    .set_tolerances = {CVodeSStolerances, "CVodeSStolerances"},
    .set_max_steps = {CVodeSetMaxNumSteps, "CVodeSetMaxNumSteps"},
    .set_stop_time = {CVodeSetStopTime, "CVodeSetStopTime"},
    .set_linear_solver = {CVodeSetLinearSolver, "CVodeSetLinearSolver"},
    .band_preconditioner = {CVBandPrecInit, "CVBandPrecInit"},
    .evolve = {CVode, "CVode"},
    .steps = {CVodeGetNumSteps, "CVodeGetNumSteps"},
    .nonlinear_iterations = {CVodeGetNumNonlinSolvIters, "CVodeGetNumNonlinSolvIters"},
    .linear_iterations = {CVodeGetNumLinIters, "CVodeGetNumLinIters"},
    .error_test_failures = {CVodeGetNumErrTestFails, "CVodeGetNumErrTestFails"},
    .preconditioner_setups = {CVodeGetNumPrecEvals, "CVodeGetNumPrecEvals"},
};

const Package kArkode = {
    .name = "ARKODE",
    .free = ARKStepFree,
    .normal_task = ARK_NORMAL,
    .set_error_handler = {ARKStepSetErrHandlerFn, "ARKStepSetErrHandlerFn"},
    .set_user_data = {ARKStepSetUserData, "ARKStepSetUserData"},
    .set_tolerances = {ARKStepSStolerances, "ARKStepSStolerances"},
    .set_max_steps = {ARKStepSetMaxNumSteps, "ARKStepSetMaxNumSteps"},
    .set_stop_time = {ARKStepSetStopTime, "ARKStepSetStopTime"},
    .set_linear_solver = {ARKStepSetLinearSolver, "ARKStepSetLinearSolver"},
    .band_preconditioner = {ARKBandPrecInit, "ARKBandPrecInit"},
    .evolve = {ARKStepEvolve, "ARKStepEvolve"},
    .steps = {ARKStepGetNumSteps, "ARKStepGetNumSteps"},
    .nonlinear_iterations = {ARKStepGetNumNonlinSolvIters, "ARKStepGetNumNonlinSolvIters"},
    .linear_iterations = {ARKStepGetNumLinIters, "ARKStepGetNumLinIters"},
    .error_test_failures = {ARKStepGetNumErrTestFails, "ARKStepGetNumErrTestFails"},
    .preconditioner_setups = {ARKStepGetNumPrecEvals, "ARKStepGetNumPrecEvals"},
};

// SUNDIALS error handler (CVErrHandlerFn / ARKErrHandlerFn): keep the message.
void keep_message(int error_code, const char* module, const char* function, char* msg, void* data) {
  auto* last = static_cast<std::string*>(data);
  *last = std::string(module ? module : "") + "::" + (function ? function : "") + " (" +
          std::to_string(error_code) + "): " + (msg ? msg : "");
}

template <class T>
T not_null(T p, const char* call, const std::string& solver) {
  if (p == nullptr) throw RunError(solver + ": " + call + " returned NULL (out of memory?)");
  return p;
}

// CVRhsFn / ARKRhsFn: ydot = parts[k](y), parts being the user data.
template <std::size_t k>
int rhs_part(double /*t*/, N_Vector y, N_Vector ydot, void* parts) noexcept {
  const auto n = static_cast<std::size_t>(N_VGetLength(y));
  (*static_cast<const std::vector<Rhs>*>(parts))[k]({N_VGetArrayPointer(y), n},
                                                    {N_VGetArrayPointer(ydot), n});
  return 0;
}

}  // namespace

void check(int flag, const char* call, const std::string& solver, const std::string& message) {
  if (flag >= 0) return;
  std::string text = solver + ": " + call + " failed with code " + std::to_string(flag);
  if (!message.empty()) text += ": " + message;
  throw RunError(text);
}

Context::Context() { check(SUNContext_Create(nullptr, &ctx_), "SUNContext_Create", "sundials"); }
Context::~Context() {
  if (ctx_) SUNContext_Free(&ctx_);
}

Vector::Vector(std::size_t n, SUNContext ctx)
    : v_(not_null(N_VNew_Serial(static_cast<sunindextype>(n), ctx), "N_VNew_Serial", "sundials")) {}
Vector::~Vector() {
  if (v_) N_VDestroy(v_);
}
std::span<double> Vector::data() const {
  return {N_VGetArrayPointer(v_), static_cast<std::size_t>(N_VGetLength(v_))};
}

LinearSolver LinearSolver::spgmr(N_Vector template_vector, int prec_type, int maxl, SUNContext ctx) {
  return LinearSolver(
      not_null(SUNLinSol_SPGMR(template_vector, prec_type, maxl, ctx), "SUNLinSol_SPGMR", "sundials"));
}
LinearSolver::~LinearSolver() {
  if (ls_) SUNLinSolFree(ls_);
}

Integrator::Integrator(const Package& package, std::span<const double> y0, std::vector<Rhs> parts,
                       const Options& o)
    : package_(package),
      options_(o),
      parts_(std::move(parts)),
      y_(y0.size(), ctx_),
      ls_(LinearSolver::spgmr(y_, SUN_PREC_LEFT, o.krylov_dimension, ctx_)) {
  std::copy(y0.begin(), y0.end(), y_.data().begin());
}

Integrator::~Integrator() {
  if (mem_) package_.free(&mem_);
}

template <class... Arguments>
void Integrator::call(const Call<Arguments...>& c, std::type_identity_t<Arguments>... arguments) const {
  check(c.function(mem_, arguments...), c.name);
}

double Integrator::counter(const Call<long*>& c) const {
  long value = 0;
  call(c, &value);
  return static_cast<double>(value);
}

void Integrator::check(int flag, const char* call) const {
  sundials::check(flag, call, package_.name, last_message_);
}

void Integrator::adopt(void* memory, const char* create) {
  mem_ = not_null(memory, create, package_.name);
  call(package_.set_error_handler, keep_message, &last_message_);
}

void Integrator::configure() {
  call(package_.set_user_data, &parts_);
  call(package_.set_tolerances, options_.rtol, options_.atol);
  call(package_.set_max_steps, options_.max_steps);
  call(package_.set_stop_time, options_.stop_time);
  call(package_.set_linear_solver, ls_, nullptr);
  const auto n = static_cast<sunindextype>(y_.data().size());
  const auto band = static_cast<sunindextype>(options_.half_bandwidth);
  call(package_.band_preconditioner, n, band, band);
}

double Integrator::advance(double tout) {
  double t = 0;
  call(package_.evolve, tout, y_, &t, package_.normal_task);
  return t;
}

Statistics Integrator::statistics() const {
  return {{"steps", counter(package_.steps)},
          {"nonlinear_iterations", counter(package_.nonlinear_iterations)},
          {"linear_iterations", counter(package_.linear_iterations)},
          {"error_test_failures", counter(package_.error_test_failures)},
          {"preconditioner_setups", counter(package_.preconditioner_setups)}};
}

Cvode::Cvode(int method, std::span<const double> y0, Rhs f, const Options& o)
    : Integrator(kCvode, y0, {std::move(f)}, o) {
  adopt(CVodeCreate(method, context()), "CVodeCreate");
  check(CVodeInit(memory(), rhs_part<0>, 0.0, state_vector()), "CVodeInit");
  configure();
}

Statistics Cvode::statistics() const {
  Statistics s = Integrator::statistics();
  s["rhs_evaluations"] = counter({CVodeGetNumRhsEvals, "CVodeGetNumRhsEvals"});
  return s;
}

Arkode::Arkode(std::span<const double> y0, Rhs fe, Rhs fi, const Options& o)
    : Integrator(kArkode, y0, {std::move(fe), std::move(fi)}, o) {
  adopt(ARKStepCreate(rhs_part<0>, rhs_part<1>, 0.0, state_vector(), context()), "ARKStepCreate");
  configure();
}

void Arkode::set_implicit_part_linear() {
  check(ARKStepSetLinear(memory(), 0), "ARKStepSetLinear");  // 0: fi independent of t
}

Statistics Arkode::statistics() const {
  Statistics s = Integrator::statistics();
  long explicit_evaluations = 0, implicit_evaluations = 0;
  check(ARKStepGetNumRhsEvals(memory(), &explicit_evaluations, &implicit_evaluations),
        "ARKStepGetNumRhsEvals");
  s["rhs_explicit"] = static_cast<double>(explicit_evaluations);
  s["rhs_implicit"] = static_cast<double>(implicit_evaluations);
  s["step_attempts"] = counter({ARKStepGetNumStepAttempts, "ARKStepGetNumStepAttempts"});
  return s;
}

}  // namespace shockgas::continuum::sundials
