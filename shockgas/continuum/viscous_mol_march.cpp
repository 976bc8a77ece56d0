#include "shockgas/continuum/viscous_mol_march.hpp"

namespace shockgas::continuum {

namespace {

constexpr int kKrylovDimension = 30;  // SPGMR restart length
constexpr long kMaxStepsPerOutput = 200000;

}  // namespace

sundials::Options mol_integrator_options(const MolProblem& m, long half_bandwidth) {
  sundials::Options o;
  o.rtol = m.rtol;
  o.atol = m.atol;
  o.stop_time = m.t_end;
  o.max_steps = kMaxStepsPerOutput;
  o.krylov_dimension = kKrylovDimension;
  o.half_bandwidth = half_bandwidth;
  return o;
}

ContinuumResult march_mol(const MolProblem& m, sundials::Integrator& integrator,
                          const ProgressCallback& progress) {
  for (int k = 1; k <= kMolOutputs; ++k) {
    const double t = integrator.advance(m.t_end * k / kMolOutputs);
    require_finite_state(m, integrator.state(), t);
    if (progress) progress(static_cast<double>(k) / kMolOutputs, t, 0);
  }
  ContinuumResult r = mol_result(m, integrator.state());
  r.stats = integrator.statistics();
  return r;
}

}  // namespace shockgas::continuum
