#pragma once
// The one wrapper of SUNDIALS 6 in shockgas (RAII; every return code checked).
// Private to shockgas_continuum: the SUNDIALS headers are not on the public
// include path, so only continuum/*.cpp include this file.
//
//  * Context       SUNContext (SUNDIALS >= 6 needs one per simulation)
//  * Vector        serial N_Vector of n doubles
//  * LinearSolver  SUNLinearSolver (here: SPGMR, Newton-Krylov)
//  * Integrator    what CVODE and ARKStep share: the state y(t) from y(0) = y0, the
//                  right-hand side on spans of doubles, scalar tolerances, the stop time,
//                  Newton-Krylov SPGMR preconditioned (left) by a band LU of the
//                  difference-quotient Jacobian (CVBandPre / ARKBandPre), the march to an
//                  output time, the counters; an error handler that keeps SUNDIALS' last
//                  message for the RunError instead of printing it.
//  * Cvode, Arkode the integrator's creation (CVodeCreate / ARKStepCreate), its own
//                  options and counters.
// check(flag, call, ...) turns a negative return code into a RunError naming the call,
// the code and SUNDIALS' own message.
#include <arkode/arkode_arkstep.h>
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>

#include <cstddef>
#include <functional>
#include <map>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

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

// ydot = f(y) of an autonomous system, on the state's doubles. Called from C: must not throw.
using Rhs = std::function<void(std::span<const double> y, std::span<double> ydot)>;

// The options CVODE and ARKStep share.
struct Options {
  double rtol = 0, atol = 0;  // |local error_i| <= rtol |y_i| + atol
  double stop_time = 0;       // never stepped past
  long max_steps = 0;         // per call to advance
  int krylov_dimension = 0;   // SPGMR restart length
  long half_bandwidth = 0;    // upper = lower, of the preconditioner's band Jacobian
};

// Counters by name: "steps", "nonlinear_iterations", "linear_iterations",
// "error_test_failures", "preconditioner_setups", and each package's own.
using Statistics = std::map<std::string, double>;

struct Package;  // the calls in which CVODE and ARKStep differ by name only
template <class... Arguments>
struct Call;  // one of them: the function and its name

// y' = f(y) from y(0) = y0, marched by CVODE or ARKStep with the Options.
class Integrator {
 public:
  virtual ~Integrator();
  Integrator(const Integrator&) = delete;
  Integrator& operator=(const Integrator&) = delete;
  std::span<const double> state() const { return y_.data(); }
  // y(tout) in state() (normal mode: stepped past tout and interpolated back, never
  // past the stop time); returns the time reached.
  double advance(double tout);
  virtual Statistics statistics() const;

 protected:
  // parts: the right-hand side(s), rhs_part<k> calls parts[k].
  Integrator(const Package& package, std::span<const double> y0, std::vector<Rhs> parts, const Options& o);
  // Takes the memory just created by the call create (NULL: out of memory), keeps its error messages.
  void adopt(void* memory, const char* create);
  // Applies the options, after the package's own initialisation.
  void configure();
  template <class... Arguments>
  void call(const Call<Arguments...>& c, std::type_identity_t<Arguments>... arguments) const;
  double counter(const Call<long*>& c) const;
  void check(int flag, const char* call) const;
  void* memory() const { return mem_; }
  SUNContext context() const { return ctx_; }
  N_Vector state_vector() const { return y_; }

 private:
  const Package& package_;
  const Options options_;
  std::string last_message_;
  std::vector<Rhs> parts_;  // the user data
  Context ctx_;
  Vector y_;
  LinearSolver ls_;  // freed after the integrator memory that uses it
  void* mem_ = nullptr;
};

class Cvode final : public Integrator {
 public:
  // CVODE on y' = f(y); method CV_BDF or CV_ADAMS.
  Cvode(int method, std::span<const double> y0, Rhs f, const Options& o);
  Statistics statistics() const override;  // and "rhs_evaluations"
};

class Arkode final : public Integrator {
 public:
  // ARKStep on y' = fe(y) + fi(y), fe explicit and fi implicit (IMEX, the default ARK 4(3) pair).
  Arkode(std::span<const double> y0, Rhs fe, Rhs fi, const Options& o);
  // fi is linear in y and independent of t: one Newton iteration per stage (ARKStepSetLinear).
  void set_implicit_part_linear();
  Statistics statistics() const override;  // and "rhs_explicit", "rhs_implicit", "step_attempts"
};

}  // namespace shockgas::continuum::sundials
