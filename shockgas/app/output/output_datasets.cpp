// The datasets and attributes of result.h5 that describe the run and the
// particles, declared once: path, unit, meaning, and where each comes from.
#include <ctime>

#include "shockgas/app/output/layout_declarations.hpp"
#include "shockgas/app/output/layout_version.hpp"
#include "shockgas/app/records/state_file.hpp"
#include "shockgas/continuum/field.hpp"
#include "shockgas/core/initial_stream.hpp"
#include "shockgas/version.hpp"

namespace shockgas::app::layout {

namespace {

std::string utc_now() {
  std::time_t now = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return buf;
}

std::string overrides_text(const Scene& s) {
  std::string text;
  for (const auto& o : s.overrides) text += (text.empty() ? "" : " ") + std::string("--set ") + o;
  return text;
}

template <class F>
Emit scene_text(F field) {
  return [field](const RunResults& r, Emitter& out) { out.text(field(*r.scene)); };
}

// Emits f(particle results) when particles ran.
template <class F>
Emit from_particles(F f) {
  return [f](const RunResults& r, Emitter& out) {
    if (r.particles) f(*r.particles, out);
  };
}

// A time series of the ensemble: its mean and its standard error.
struct Series {
  const char* name;
  particles::SeriesStats particles::EnsembleResult::*stats;
  const char* unit;
  const char* description;
};

const Series kSeries[] = {
    {"T", &particles::EnsembleResult::T, "length^2/time^2", "temperature <v^2> - <v>^2, mass weighted"},
    {"mean_v", &particles::EnsembleResult::mean_v, "length/time",
     "mass-weighted mean velocity (momentum check)"},
    {"n_bodies", &particles::EnsembleResult::n_bodies, "1", "bodies (clusters after merges)"},
    {"n_clusters", &particles::EnsembleResult::n_clusters, "1",
     "clusters of at least k = particles.min_cluster_particles particles (summary.json; 2 by default): "
     "the default cluster criteria at the sample's time; k = 2: a lone body counted only when heavier than "
     "1.5 M / N (merged particles); k > 2: the clusters heavier than (k - 1/2) M / N"},
    {"collisions", &particles::EnsembleResult::collisions, "1", "cumulative collisions, all kinds"},
    {"inelastic", &particles::EnsembleResult::inelastic, "1", "cumulative inelastic collisions"},
    {"elastic", &particles::EnsembleResult::elastic, "1", "cumulative elastic sub-threshold collisions"},
    {"merges", &particles::EnsembleResult::merges, "1", "cumulative merges"},
    {"dissipated", &particles::EnsembleResult::dissipated, "mass length^2/time^2",
     "cumulative kinetic energy dissipated"},
};

std::vector<Declaration> series() {
  const Part p = Part::particles;
  std::vector<Declaration> d;
  for (const Series& s : kSeries) {
    const auto stats = s.stats;
    d.push_back(dataset(p, std::string("/particles/") + s.name, s.unit,
                        std::string(s.description) + " (ensemble mean)", "",
                        from_particles([stats](const ParticleResults& pr, Emitter& out) {
                          if (!(pr.ensemble.*stats).mean.empty()) out.values((pr.ensemble.*stats).mean);
                        })));
    d.push_back(dataset(p, std::string("/particles/") + s.name + "_stderr", s.unit,
                        std::string("standard error of ") + s.name, "",
                        from_particles([stats](const ParticleResults& pr, Emitter& out) {
                          if (!(pr.ensemble.*stats).mean.empty()) out.values((pr.ensemble.*stats).stderr_);
                        })));
  }
  return d;
}

// A state's columns (0: x, 1: v, 2: m) handed to an emitter: bodies held whole
// as they are, a state of the state file (state_file.hpp) in pieces.
class StateColumns {
 public:
  virtual void emit(int column, Emitter& out, const std::vector<std::string>& at) const = 0;

 protected:
  ~StateColumns() = default;
};

class HeldColumns final : public StateColumns {
 public:
  explicit HeldColumns(const Bodies& b) : b_(b) {}
  void emit(int column, Emitter& out, const std::vector<std::string>& at) const override {
    out.values(column == 0 ? b_.x : column == 1 ? b_.v : b_.m, at);
  }

 private:
  const Bodies& b_;
};

class StoredColumns final : public StateColumns {
 public:
  explicit StoredColumns(const StoredStates::State& s) : s_(s) {}
  void emit(int column, Emitter& out, const std::vector<std::string>& at) const override {
    out.pieces(
        s_.size(), [&](const Emitter::PutPiece& put) { s_.read_column(column, put); }, at);
  }

 private:
  const StoredStates::State& s_;
};

// Hands each state of a run to `put`, with the values of the group's placeholders.
using PutState = std::function<void(const StateColumns&, std::vector<std::string>)>;
using EachState = std::function<void(const RunResults&, const PutState& put)>;

// x, v, m of the states `each` finds (`what`: whose) under group.
std::vector<Declaration> bodies(const std::string& group, const std::string& what, const std::string& when,
                                EachState each) {
  struct Column {
    const char* name;
    const char* unit;
    const char* what;
  };
  const Column columns[] = {{"x", "length", ": positions (ring: in [0, L))"},
                            {"v", "length/time", ": velocities"},
                            {"m", "mass", ": masses"}};
  std::vector<Declaration> d;
  for (int c = 0; c < 3; ++c)
    d.push_back(
        dataset(Part::particles, group + "/" + columns[c].name, columns[c].unit, what + columns[c].what, when,
                [each, c](const RunResults& r, Emitter& out) {
                  each(r, [&](const StateColumns& s, std::vector<std::string> at) { s.emit(c, out, at); });
                }));
  return d;
}

std::vector<Declaration> records() {
  const Part p = Part::particles;
  std::vector<Declaration> d;
  append(d, bodies("/particles/final", "state at t_end (realization 0)", "as output.final says",
                   [](const RunResults& r, const auto& put) {
                     if (!r.particles) return;
                     const KeepState keep = r.scene->output.final_state;
                     if (const auto& stored = r.particles->states) {
                       const auto* final_state = stored->final_state();
                       if (final_state && keeps_state(keep, final_state->size()))
                         put(StoredColumns(*final_state), {});
                     } else if (keeps_state(keep, r.particles->ensemble.first.final_state.size())) {
                       put(HeldColumns(r.particles->ensemble.first.final_state), {});
                     }
                   }));
  append(d, bodies("/particles/snapshots/{k}", "snapshot (realization 0)", "at particles.snapshots",
                   [](const RunResults& r, const auto& put) {
                     if (!r.particles) return;
                     if (const auto& stored = r.particles->states) {
                       for (std::size_t k = 0; k < stored->snapshots().size(); ++k)
                         put(StoredColumns(stored->snapshots()[k]), {std::to_string(k)});
                       return;
                     }
                     const auto& snaps = r.particles->ensemble.first.snapshots;
                     for (std::size_t k = 0; k < snaps.size(); ++k)
                       put(HeldColumns(snaps[k].bodies), {std::to_string(k)});
                   }));
  d.push_back(attribute(p, "/particles/snapshots/{k}@t", "time", "time of snapshot k", "",
                        from_particles([](const ParticleResults& pr, Emitter& out) {
                          if (pr.states) {
                            for (std::size_t k = 0; k < pr.states->snapshots().size(); ++k)
                              out.number(pr.states->snapshots()[k].time(), {std::to_string(k)});
                            return;
                          }
                          const auto& snaps = pr.ensemble.first.snapshots;
                          for (std::size_t k = 0; k < snaps.size(); ++k)
                            out.number(snaps[k].t, {std::to_string(k)});
                        })));
  const char* hist = "when particles.histogram_bins > 0";
  auto histogram = [](auto f) {
    return from_particles([f](const ParticleResults& pr, Emitter& out) {
      if (pr.histogram.bins > 0 && !pr.histogram.t.empty()) f(pr.histogram, out);
    });
  };
  d.push_back(
      dataset(p, "/particles/histogram/z", "length/time^(2/3)", "bin centres of z = (v - <v>) t^(1/3)", hist,
              histogram([](const compare::ZHistogram& h, Emitter& out) { out.values(h.centres()); })));
  d.push_back(dataset(p, "/particles/histogram/t", "time", "sample times", hist,
                      histogram([](const compare::ZHistogram& h, Emitter& out) { out.values(h.t); })));
  d.push_back(dataset(p, "/particles/histogram/density", "time^(2/3)/length",
                      "mass-weighted density of z, ensemble mean (rows: times)", hist,
                      histogram([](const compare::ZHistogram& h, Emitter& out) {
                        out.matrix(h.density, h.t.size(), h.bins);
                      })));
  d.push_back(
      dataset(p, "/particles/histogram/exact", "time^(2/3)/length",
              "the exact mass-weighted law of z of the sticky gas (r = 0) from this white noise, "
              "averaged over each bin (shockgas/compare/cluster_velocity_law.hpp): the fixed point the gas "
              "approaches at every r",
              "when particles.histogram_bins > 0 and the start is white noise on a lattice",
              from_particles([](const ParticleResults& pr, Emitter& out) {
                if (!pr.histogram_exact.empty()) out.values(pr.histogram_exact);
              })));
  const char* st = "when particles.spacetime";
  auto spacetime = [](auto f) {
    return [f](const RunResults& r, Emitter& out) {
      if (r.particles && r.scene->particles.spacetime && !r.particles->ensemble.first.spacetime.t.empty())
        f(r.particles->ensemble.first.spacetime, out);
    };
  };
  d.push_back(dataset(p, "/particles/spacetime/t", "time", "frame times", st,
                      spacetime([](const particles::SpaceTime& s, Emitter& out) { out.values(s.t); })));
  d.push_back(stored_as(
      Storage::integer,
      dataset(p, "/particles/spacetime/label", "1",
              "the labels (0 .. N-1, in initial order) of the particles whose world lines x holds, one per "
              "column: at most particles.spacetime_particles, evenly spaced, the first and the last always",
              st, spacetime([](const particles::SpaceTime& s, Emitter& out) {
                out.values(std::vector<double>(s.labels.begin(), s.labels.end()));
              }))));
  d.push_back(stored_as(Storage::float32,
                        dataset(p, "/particles/spacetime/x", "length",
                                "position of each recorded particle (columns: /particles/spacetime/label) at "
                                "each frame (realization 0), for drawing its world line",
                                st, spacetime([](const particles::SpaceTime& s, Emitter& out) {
                                  out.matrix(s.x, s.t.size(), s.labels.size());
                                }))));
  return d;
}

std::vector<Declaration> stop() {
  const Part p = Part::particles;
  auto stop_of = [](auto f) {
    return from_particles([f](const ParticleResults& pr, Emitter& out) { f(pr.ensemble.first.stop, out); });
  };
  using particles::StopReason;
  return {
      attribute(p, "/particles@stop_reason", "",
                "how realization 0 ended: completed, collapse, rounding_stall, event_limit, wall_limit", "",
                stop_of([](const particles::RunStop& s, Emitter& out) { out.text(to_string(s.reason)); })),
      attribute(p, "/particles@stop_time", "time", "when it ended", "",
                stop_of([](const particles::RunStop& s, Emitter& out) { out.number(s.time); })),
      attribute(p, "/particles@collapse_x", "length", "where the inelastic collapse happened",
                "after a collapse", stop_of([](const particles::RunStop& s, Emitter& out) {
                  if (s.reason == StopReason::collapse) out.number(s.position);
                })),
      attribute(p, "/particles@stall_x", "length", "where time stopped advancing through rounding",
                "after a rounding stall", stop_of([](const particles::RunStop& s, Emitter& out) {
                  if (s.reason == StopReason::stall) out.number(s.position);
                })),
  };
}

}  // namespace

std::vector<Declaration> provenance_datasets() {
  const Part p = Part::provenance;
  return {
      attribute(p, "/@layout_version", "",
                "the layout of this file, major.minor: a reader reads its major and below (docs/output.md, "
                "Layout version); absent in layout 1.0",
                "", [](const RunResults&, Emitter& out) { out.text(layout_version_text()); }),
      attribute(p, "/@attributes_sha256", "",
                "SHA-256 of every other attribute of the file (each group and dataset in name order, each "
                "attribute in name order: object, name, value), stored when the file is closed; every reader "
                "compares it (layout 3.1 on)",
                "", [](const RunResults&, Emitter&) {}),  // written by Hdf5File::close()
      attribute(p, "/@shockgas_version", "", "the program that wrote the file", "",
                [](const RunResults&, Emitter& out) { out.text(kVersion); }),
      attribute(p, "/@git_commit", "", "its commit (-dirty: with uncommitted changes)", "",
                [](const RunResults&, Emitter& out) { out.text(kGitCommit); }),
      attribute(p, "/@created_utc", "", "when, ISO 8601", "",
                [](const RunResults&, Emitter& out) { out.text(utc_now()); }),
      attribute(p, "/@scene_name", "", "the scene", "", scene_text([](const Scene& s) { return s.name; })),
      attribute(p, "/@scene_path", "", "the scene file", "",
                scene_text([](const Scene& s) { return s.path; })),
      attribute(p, "/@overrides", "", "the --set overrides, as given", "", scene_text(overrides_text)),
      attribute(p, "/@scene_text", "", "the scene file as given", "",
                scene_text([](const Scene& s) { return s.text; })),
      attribute(p, "/@resolved_parameters", "", "every key after defaults and overrides, as TOML", "",
                scene_text([](const Scene& s) { return resolved_scene_text(s); })),
  };
}

std::vector<Declaration> particle_datasets() {
  const Part p = Part::initial;
  // A column of realization 0's bodies (0: x, 1: v, 2: m), drawn in chunks. Only
  // the positions' column draws and sorts random positions; v and m skip them.
  auto initial = [](int column) {
    return [column](const RunResults& r, Emitter& out) {
      if (!r.scene->has_particles || !r.initial || !keeps_state(r.scene->output.initial, r.scene->initial.N))
        return;
      InitialStream bodies = stream_realization(
          *r.initial, 0, column == 0 ? InitialStream::Parts::all : InitialStream::Parts::velocities);
      out.pieces(bodies.size(), [&](const Emitter::PutPiece& put) {
        read_in_chunks(bodies, [&](const double* x, const double* v, const double* m, std::size_t count) {
          put(column == 0 ? x : column == 1 ? v : m, count);
        });
      });
    };
  };
  // The continuum's initial cell averages (continuum::cell_averages), when a solver runs.
  const char* cells = "when [continuum] runs";
  const char* bodies = "when [particles] runs, as output.initial says";
  enum class Cells { centres, velocity, density };
  auto initial_cells = [](Cells column) {
    return [column](const RunResults& r, Emitter& out) {
      if (!r.scene->has_continuum || !r.initial) return;
      const auto& f = r.initial->field();
      if (column == Cells::centres)
        return out.values(continuum::cell_centres(f.length, r.scene->continuum.cells));
      const continuum::CellAverages a = continuum::cell_averages(f, r.scene->continuum.cells);
      out.values(column == Cells::velocity ? a.v : a.rho);
    };
  };
  std::vector<Declaration> d = {
      dataset(p, "/initial/x", "length", "initial positions (realization 0)", bodies, initial(0)),
      dataset(p, "/initial/v", "length/time", "initial velocities (realization 0)", bodies, initial(1)),
      dataset(p, "/initial/m", "mass", "initial masses (realization 0)", bodies, initial(2)),
      dataset(p, "/initial/cells/x", "length", "cell centres of the continuum's grid", cells,
              initial_cells(Cells::centres)),
      dataset(p, "/initial/cells/v", "length/time",
              "the initial velocity averaged over each cell: what every solver starts from", cells,
              initial_cells(Cells::velocity)),
      dataset(p, "/initial/cells/rho", "mass/length", "the initial density averaged over each cell", cells,
              initial_cells(Cells::density)),
      dataset(Part::particles, "/particles/t", "time", "log-spaced sample times", "",
              from_particles([](const ParticleResults& pr, Emitter& out) { out.values(pr.ensemble.t); })),
      stored_as(Storage::integer,
                dataset(Part::particles, "/particles/count", "1", "realizations that reached each sample", "",
                        from_particles(
                            [](const ParticleResults& pr, Emitter& out) { out.values(pr.ensemble.count); }))),
  };
  append(d, series());
  append(d, records());
  append(d, stop());
  return d;
}

}  // namespace shockgas::app::layout
