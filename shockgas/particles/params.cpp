// The declarations of scene table [particles] and the rules between its keys.
#include "shockgas/particles/params.hpp"

#include "shockgas/core/error.hpp"
#include "shockgas/particles/restitution_laws.hpp"

namespace shockgas::particles {

namespace {

ParameterTable<ParticleParams> declare() {
  using P = ParticleParams;
  ParameterTable<P> t("particles");
  t.add(&P::r, "r", "1",
        "restitution coefficient; 0 = aggregation: every collision merges (the sticky gas; delta and "
        "subthreshold do not apply)",
        allowed(between(0, 1)));
  t.add(&P::delta, "delta", "length/time",
        "velocity threshold below which collisions of r > 0 are sub-threshold; 0 = none",
        allowed(at_least(0)));
  t.add(&P::subthreshold, "subthreshold", "", "what a sub-threshold collision does (r > 0)");
  t.add(
      &P::restitution_law, "restitution_law", "",
      "restitution r(g) of the inelastic collisions (approach speed g >= delta; r > 0): a registered law; " +
          to_text(std::string(kConstantRestitution)) + " = r for every g",
      one_of(restitution_law_names));
  t.add(&P::geometry, "geometry", "", "periodic ring of length L, or open line");
  t.add(&P::solver, "solver", "",
        "event-driven simulation, or the exact sticky solution by the convex hull; auto = the hull where it "
        "applies (r = 0 and no max_collisions, max_wall_seconds), else the events, said in a note",
        described(choices_text(enum_choices<ParticleSolver>()) + " (" + name_of(ParticleSolver::hull) +
                  ": r = 0 only)"));
  t.add(&P::schedule, "schedule", "",
        "event order: time windows over stretches of the chain (the same collisions; equal masses without "
        "merges, or r = 0; no collapse), the global queue, or auto = windows where they apply");
  t.add(&P::t_end, "t_end", "time", "final time", allowed(above(0)));
  t.add(&P::samples, "samples", "1",
        "log-spaced sample times in [1, t_end] (in [t_end / 1000, t_end] where t_end <= 1)",
        allowed(at_least(1)));
  t.add(&P::realizations, "realizations", "1", "independent realizations (ensemble)", allowed(at_least(1)));
  t.add(&P::threads, "threads", "1", "worker threads; 0 = all cores", allowed(at_least(0)));
  t.add(&P::snapshots, "snapshots", "time", "times at which x, v, m are stored",
        Allowed{at_least(0), {}, "times in [0, t_end]"});
  t.add(&P::spacetime, "spacetime", "", "record trajectories (space-time diagram)");
  t.add(&P::histogram_bins, "histogram_bins", "1",
        "bins of the mass-weighted histogram of z = (v - <v>) t^(1/3); 0 = none", allowed(at_least(0)));
  t.add(&P::histogram_zmax, "histogram_zmax", "length/time^(2/3)", "histogram range |z| <= zmax",
        allowed(above(0)));
  t.add(&P::spacetime_frames, "spacetime_frames", "1",
        "frames of the space-time record, equally spaced in [0, t_end]", allowed(at_least(2)));
  t.add(&P::spacetime_particles, "spacetime_particles", "1",
        "particles whose world lines the space-time record keeps: at most this many, evenly spaced in "
        "label, the first and the last always (all of them when N is not larger)",
        allowed(at_least(2)));
  t.add(&P::clusters, "clusters", "", "count clusters (default criteria) at the sample times");
  t.add(&P::min_cluster_particles, "min_cluster_particles", "1",
        "the clusters counted at the sample times hold at least this many particles: 2 = every cluster of "
        "two or more (a lone body when heavier than 1.5 M / N), counted as the state streams by; above 2, "
        "those heavier than (k - 1/2) M / N, each sample walking the clusters of the whole state, about 16 "
        "ns per body and sample (5 times the run of 10^6 particles to t = 10 with 40 samples); the exact "
        "shock count drawn beside them counts the shocks above the same mass",
        allowed(at_least(2)));
  t.add(&P::final_clusters, "final_clusters", "",
        "record each realization's clusters of at least two particles at its end (x, v, m; default "
        "criteria) for `shockgas stats`: always, never, or auto (when " +
            final_clusters_auto_rule() + ")");
  t.add(&P::max_collisions, "max_collisions", "1",
        "stop a realization at its first safe point with at least this many collisions (the end of a time "
        "window, or every " +
            std::to_string(kGlobalQueueCheckEvery) +
            " collisions on the global queue), stop = event_limit; one that reaches t_end first has "
            "completed; 0 = "
            "no limit (event engine only)",
        allowed(at_least(0)));
  t.add(&P::max_wall_seconds, "max_wall_seconds", "s",
        "stop a realization after this wall-clock time (and fail a continuum solve of the scene that takes "
        "longer); 0 = no limit (event engine only)",
        allowed(at_least(0)));
  return t;
}

}  // namespace

const ParameterTable<ParticleParams>& parameters() {
  static const ParameterTable<ParticleParams> table = declare();
  return table;
}

double final_clusters_bound(const ParticleParams& p, std::size_t n) {
  return kRecordedClusterBytesPerParticle * static_cast<double>(n) * static_cast<double>(p.realizations);
}

bool records_final_clusters(const ParticleParams& p, std::size_t n) {
  return p.final_clusters == ClusterRecord::always ||
         (p.final_clusters == ClusterRecord::automatic && n <= kRecordedClustersAutoBodies &&
          final_clusters_bound(p, n) <= kRecordedClustersBytes);
}

std::string final_clusters_auto_rule() {
  return "N <= " + to_text(kRecordedClustersAutoBodies) +
         " and N x realizations <= " + to_text(kRecordedClustersAutoParticles, 2) +
         ": at most 1 GB in the worst case of 12 bytes per particle and realization";
}

void validate(const ParticleParams& p) {
  parameters().check(p);
  require(p.solver != ParticleSolver::hull || p.r == 0.0, "particles.solver", name_of(p.solver),
          "\"" + name_of(ParticleSolver::hull) +
              "\" only with particles.r = 0 (the exact sticky solution); \"" +
              name_of(ParticleSolver::automatic) + "\" runs it at r = 0 and the event engine otherwise");
  require(p.restitution_law == kConstantRestitution || p.r > 0, "particles.restitution_law",
          p.restitution_law,
          to_text(std::string(kConstantRestitution)) + " with particles.r = 0 (every collision merges)");
  for (double t : p.snapshots)
    require(t <= p.t_end, "particles.snapshots", t, "times in [0, particles.t_end]");
  // The hull is exact at each sample time: it has no collisions to count and no safe points to stop at.
  const bool hull = p.solver == ParticleSolver::hull;
  require(!hull || p.max_collisions == 0, "particles.max_collisions", p.max_collisions,
          "0 with particles.solver = \"hull\" (the limits stop the event engine only)");
  require(!hull || p.max_wall_seconds == 0, "particles.max_wall_seconds", p.max_wall_seconds,
          "0 with particles.solver = \"hull\" (the limits stop the event engine only)");
}

ParticleSolver chosen_solver(const ParticleParams& p) {
  if (p.solver != ParticleSolver::automatic) return p.solver;
  const bool limited = p.max_collisions != 0 || p.max_wall_seconds != 0;
  return p.r == 0.0 && !limited ? ParticleSolver::hull : ParticleSolver::events;
}

std::string solver_choice_note(const ParticleParams& p) {
  if (p.solver != ParticleSolver::automatic) return "";
  const std::string said = "particles.solver = \"" + name_of(p.solver) + "\": ";
  if (chosen_solver(p) == ParticleSolver::hull)
    return said + "the exact hull, as particles.r = 0 (every collision merges)";
  if (p.r != 0.0) return said + "the event engine, as particles.r = " + to_text(p.r) + " > 0";
  return said + "the event engine, as a limit (max_collisions, max_wall_seconds) stops the engine only";
}

CollisionRule collision_rule(const ParticleParams& p) {
  return {p.r, p.delta, p.subthreshold == Subthreshold::sticky, restitution_law(p)};
}

}  // namespace shockgas::particles
