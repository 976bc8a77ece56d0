# The headers a program outside shockgas includes: shockgas/shockgas.hpp and
# every header it reaches, and nothing else. Installed under include/; the test
# install.headers_alone compiles each on its own against the installed prefix, and
# install.facade_closure checks that the facade reaches exactly these.
set(SHOCKGAS_PUBLIC_HEADERS
    shockgas/shockgas.hpp
    # and shockgas/version.hpp, generated (cmake/version.hpp.in)
    shockgas/app/jobs/run_scene.hpp
    shockgas/app/run/run_options.hpp
    shockgas/app/scene/scene.hpp
    shockgas/compare/cooling_law.hpp
    shockgas/compare/deposit.hpp
    shockgas/compare/matching.hpp
    shockgas/compare/params.hpp
    shockgas/compare/particle_analysis.hpp
    shockgas/compare/sawtooth.hpp
    shockgas/compare/shock_detection.hpp
    shockgas/compare/snapshot_comparison.hpp
    shockgas/compare/statistics.hpp
    shockgas/compare/theory.hpp
    shockgas/compare/velocity_distribution.hpp
    shockgas/continuum/explicit_viscous.hpp
    shockgas/continuum/field.hpp
    shockgas/continuum/godunov.hpp
    shockgas/continuum/hopf_cole.hpp
    shockgas/continuum/hopf_lax.hpp
    shockgas/continuum/params.hpp
    shockgas/continuum/pressureless.hpp
    shockgas/continuum/registry.hpp
    shockgas/continuum/solve.hpp
    shockgas/continuum/viscous_mol.hpp
    shockgas/core/bodies.hpp
    shockgas/core/enum_names.hpp
    shockgas/core/error.hpp
    shockgas/core/initial_condition.hpp
    shockgas/core/parameter_types.hpp
    shockgas/core/parameters.hpp
    shockgas/core/progress.hpp
    shockgas/core/sticky_hull.hpp
    shockgas/particles/cluster_finder.hpp
    shockgas/particles/collision.hpp
    shockgas/particles/params.hpp
    shockgas/particles/run_result.hpp
    shockgas/particles/run_state.hpp
    shockgas/particles/simulate.hpp
    shockgas/particles/state_sink.hpp)
