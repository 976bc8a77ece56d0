#pragma once
// The sections of `shockgas bench`, each writing its CSV files into ctx.out_dir
// and adding what failed to the failure log (docs/performance.md lists the files).
#include "shockgas/studies/common.hpp"

namespace shockgas::studies {

// wp_inviscid.csv, wp_viscous.csv: error against the exact solution and median
// wall time of every continuum method and setting on the reference problems.
void continuum_work_precision(const Context& ctx, FailureLog& failures);

// particles_cost.csv, particles_statistics.csv: cost against N and collisions per
// particle; statistical error of T(t) and of the fitted exponent against CPU time.
void particle_work_precision(const Context& ctx, FailureLog& failures);

// stability_cfl.csv, stability_viscous.csv, stability_hopf_cole.csv (stability.hpp).
void continuum_stability(const Context& ctx, FailureLog& failures);

// stability_collapse.csv, stability_threshold.csv (stability.hpp).
void particle_stability(const Context& ctx, FailureLog& failures);

}  // namespace shockgas::studies
