#include "shockgas/continuum/sundials_wrap.hpp"

#include <sunlinsol/sunlinsol_spgmr.h>

#include "shockgas/core/error.hpp"

namespace shockgas::continuum::sundials {

namespace {

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

Cvode::Cvode(int method, SUNContext ctx) : mem_(not_null(CVodeCreate(method, ctx), "CVodeCreate", "CVODE")) {
  try {
    check(CVodeSetErrHandlerFn(mem_, keep_message, &last_message_), "CVodeSetErrHandlerFn");
  } catch (...) {
    CVodeFree(&mem_);
    throw;
  }
}
Cvode::~Cvode() {
  if (mem_) CVodeFree(&mem_);
}
void Cvode::check(int flag, const char* call) const { sundials::check(flag, call, "CVODE", last_message_); }

Arkode::Arkode(ARKRhsFn fe, ARKRhsFn fi, double t0, N_Vector y0, SUNContext ctx)
    : mem_(not_null(ARKStepCreate(fe, fi, t0, y0, ctx), "ARKStepCreate", "ARKODE")) {
  try {
    check(ARKStepSetErrHandlerFn(mem_, keep_message, &last_message_), "ARKStepSetErrHandlerFn");
  } catch (...) {
    ARKStepFree(&mem_);
    throw;
  }
}
Arkode::~Arkode() {
  if (mem_) ARKStepFree(&mem_);
}
void Arkode::check(int flag, const char* call) const { sundials::check(flag, call, "ARKODE", last_message_); }

}  // namespace shockgas::continuum::sundials
