#include "shockgas/particles/live_run.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "shockgas/core/error.hpp"
#include "shockgas/particles/chain_view.hpp"
#include "shockgas/particles/event_engine.hpp"
#include "shockgas/particles/sorted_state.hpp"

namespace shockgas::particles {

struct LiveRun::Impl {
  virtual ~Impl() = default;
  using Step = LiveRun::Step;
  virtual Step advance(double t, std::uint64_t budget) = 0;
  virtual Bodies state() const = 0;
  virtual double time() const = 0;
  virtual std::size_t alive() const = 0;
  virtual std::uint64_t count(CollisionKind kind) const = 0;
  virtual std::uint64_t collisions() const = 0;
  virtual double dissipated() const = 0;
  Step last;
};

namespace {

template <bool Linked>
class Engine final : public LiveRun::Impl {
 public:
  Engine(const Bodies& b, double L, bool ring, const CollisionRule& rule)
      : engine_(b.size(), L, ring, rule,
                [&b](std::size_t first, std::size_t count, double* x, double* v, double* m) {
                  std::copy_n(b.x.begin() + first, count, x);
                  std::copy_n(b.v.begin() + first, count, v);
                  std::copy_n(b.m.begin() + first, count, m);
                }) {
    engine_.use_global_queue();
  }

  Step advance(double t, std::uint64_t budget) override {
    if (last.ended) return last;
    const std::uint64_t start = engine_.collisions();
    auto watch = [&](double, std::uint64_t done) { return budget == 0 || done - start < budget; };
    const detail::EngineStop s = engine_.run_until(t, watch);
    last.time = engine_.now();
    last.reached = s == detail::EngineStop::reached;
    last.ended = s == detail::EngineStop::collapse || s == detail::EngineStop::stall;
    if (last.ended)
      last.stop = {s == detail::EngineStop::collapse ? StopReason::collapse : StopReason::stall,
                   engine_.now(), engine_.last_position()};
    else
      last.stop = {StopReason::completed, engine_.now(), 0.0};
    return last;
  }
  Bodies state() const override {
    const double t = engine_.now();
    return detail::sorted_bodies(detail::engine_chain_view(engine_, t), engine_.length(), engine_.ring());
  }
  double time() const override { return engine_.now(); }
  std::size_t alive() const override { return engine_.alive(); }
  std::uint64_t count(CollisionKind kind) const override { return engine_.count(kind); }
  std::uint64_t collisions() const override { return engine_.collisions(); }
  double dissipated() const override { return engine_.dissipated(); }

 private:
  detail::EventEngine<Linked> engine_;
};

// What simulate() requires of its bodies.
void check_bodies(const Bodies& b, double L, bool ring) {
  require(b.size() >= 2 && b.v.size() == b.size() && b.m.size() == b.size(), "initial.N", b.size(),
          "at least 2 bodies with x, v and m each");
  require(std::isfinite(L) && L > 0, "initial.L", L, "a finite length > 0");
  require_finite_bodies(b, "initial.bodies");
  for (std::size_t i = 0; i < b.size(); ++i) {
    const std::string x = "initial.bodies.x[" + std::to_string(i) + "]";
    require(i == 0 || b.x[i - 1] <= b.x[i], x, b.x[i], "positions sorted ascending");
    require(!ring || (b.x[i] >= 0 && b.x[i] < L), x, b.x[i], "positions in [0, L) on a ring");
  }
}

}  // namespace

LiveRun::LiveRun(const Bodies& initial, double L, const ParticleParams& p) {
  validate(p);
  require(p.solver == ParticleSolver::events, "particles.solver", name_of(p.solver),
          "\"events\" for a run advanced step by step");
  const bool ring = p.geometry == Geometry::ring;
  check_bodies(initial, L, ring);
  const CollisionRule rule = collision_rule(p);
  const bool equal =
      std::all_of(initial.m.begin(), initial.m.end(), [&](double m) { return m == initial.m[0]; });
  // The layout simulate() takes: links and masses where bodies merge or masses differ.
  if (rule.can_merge() || !equal)
    impl_ = std::make_unique<Engine<true>>(initial, L, ring, rule);
  else
    impl_ = std::make_unique<Engine<false>>(initial, L, ring, rule);
}

LiveRun::~LiveRun() = default;
LiveRun::LiveRun(LiveRun&&) noexcept = default;
LiveRun& LiveRun::operator=(LiveRun&&) noexcept = default;

LiveRun::Step LiveRun::advance(double t, std::uint64_t budget) {
  require(std::isfinite(t) && t >= time(), "t", t, "a finite time >= the time reached, " + to_text(time()));
  return impl_->advance(t, budget);
}

double LiveRun::time() const { return impl_->time(); }
bool LiveRun::ended() const { return impl_->last.ended; }
Bodies LiveRun::state() const { return impl_->state(); }
std::size_t LiveRun::alive() const { return impl_->alive(); }
std::uint64_t LiveRun::collisions() const { return impl_->collisions(); }
std::uint64_t LiveRun::count(CollisionKind kind) const { return impl_->count(kind); }
double LiveRun::dissipated() const { return impl_->dissipated(); }

}  // namespace shockgas::particles
