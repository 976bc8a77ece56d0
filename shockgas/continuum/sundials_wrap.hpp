#pragma once
// The one wrapper of SUNDIALS 6 in shockgas (RAII; every return code checked).
// Private to shockgas_continuum: the SUNDIALS headers are not on the public
// include path, so only continuum/*.cpp include this file.
//
//  * Context       SUNContext (SUNDIALS >= 6 needs one per simulation)
//  * Vector        serial N_Vector of n doubles
//  * LinearSolver  SUNLinearSolver (here: SPGMR, Newton-Krylov)
//  * Cvode, Arkode the integrator memory (CVodeCreate / ARKStepCreate), with an
//                  error handler that keeps SUNDIALS' last message for the RunError
//                  instead of printing it.
// check(flag, call, ...) turns a negative return code into a RunError naming the call,
// the code and SUNDIALS' own message.
#include <arkode/arkode_arkstep.h>
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>

#include <cstddef>
#include <span>
#include <string>

namespace shockgas::continuum::sundials {

// Throws RunError("<solver>: <call> failed with code <flag>: <message>") if flag < 0.
void check(int flag, const char* call, const std::string& solver, const std::string& message = "");

class Context {
 public:
  Context();
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;
  operator SUNContext() const { return ctx_; }

 private:
  SUNContext ctx_ = nullptr;
};

class Vector {
 public:
  Vector(std::size_t n, SUNContext ctx);
  ~Vector();
  Vector(const Vector&) = delete;
  Vector& operator=(const Vector&) = delete;
  operator N_Vector() const { return v_; }
  std::span<double> data() const;

 private:
  N_Vector v_ = nullptr;
};

class LinearSolver {
 public:
  // Scaled, preconditioned GMRES; prec_type SUN_PREC_NONE / LEFT / RIGHT / BOTH, maxl Krylov dimension.
  static LinearSolver spgmr(N_Vector template_vector, int prec_type, int maxl, SUNContext ctx);
  ~LinearSolver();
  LinearSolver(LinearSolver&& other) noexcept : ls_(other.ls_) { other.ls_ = nullptr; }
  LinearSolver(const LinearSolver&) = delete;
  LinearSolver& operator=(const LinearSolver&) = delete;
  operator SUNLinearSolver() const { return ls_; }

 private:
  explicit LinearSolver(SUNLinearSolver ls) : ls_(ls) {}
  SUNLinearSolver ls_ = nullptr;
};

// Integrator memory of one of the two packages.
class Cvode {
 public:
  Cvode(int method, SUNContext ctx);  // method: CV_BDF or CV_ADAMS
  ~Cvode();
  Cvode(const Cvode&) = delete;
  Cvode& operator=(const Cvode&) = delete;
  void* get() const { return mem_; }
  // check() with SUNDIALS' last error message for this integrator.
  void check(int flag, const char* call) const;

 private:
  void* mem_ = nullptr;
  std::string last_message_;
};

class Arkode {
 public:
  // ARKStep with explicit part fe and implicit part fi (either may be null).
  Arkode(ARKRhsFn fe, ARKRhsFn fi, double t0, N_Vector y0, SUNContext ctx);
  ~Arkode();
  Arkode(const Arkode&) = delete;
  Arkode& operator=(const Arkode&) = delete;
  void* get() const { return mem_; }
  void check(int flag, const char* call) const;

 private:
  void* mem_ = nullptr;
  std::string last_message_;
};

}  // namespace shockgas::continuum::sundials
