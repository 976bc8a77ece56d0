#pragma once
// One declaration of the output layout: a dataset or attribute of result.h5, or
// a key of summary.json, with its unit and meaning (LayoutEntry), and how its
// values are taken from a run's results and handed to a file or a summary
// (Emitter). The declarations themselves are in output_datasets.cpp,
// output_fields.cpp, summary_keys.cpp, ... (layout_declarations.hpp); the
// layout they make, its writers and its documentation in output_layout.hpp.
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "shockgas/app/output/run_results.hpp"
#include "shockgas/app/output/storage.hpp"

namespace shockgas::app {

// The parts of a run, in the order they are written.
enum class Part {
  provenance,
  initial,
  particles,
  analysis,
  continuum,
  compare,
  animation,
  theory,
  sweep,
  shard
};

// One thing theory says of a value: the value and a word of where it holds
// ("-2/3 (sticky gas)"), or another key's value ("~ {analysis.t_dissip_theory}"),
// under the law `law` (an id of compare::theory_declarations(): the summary's
// theory.<law> says whether it holds for a scene). An empty law: a property of
// the numerics that holds for every scene ("0 to rounding").
struct Theory {
  std::string law;
  std::string value;
};

struct LayoutEntry {
  enum class Kind { dataset, attribute, summary };
  Kind kind = Kind::dataset;
  Part part = Part::provenance;
  // dataset "/particles/T"; attribute "/particles@stop_reason" (object@name);
  // summary key "particles.collisions". {solver}: a continuum solver's name,
  // {k}: an index (snapshot, sweep variant).
  std::string path;
  std::string unit;  // "1" for a pure number, "" for text
  std::string description;
  std::string when;  // the condition under which it is written; "" = always (for its part)
  // What theory says the value should be, where it says anything (Theory).
  // Reports show each beside the value where its law holds for the scene.
  std::vector<Theory> theory = {};
  Storage storage = Storage::float64;  // a dataset's values in the file (storage.hpp)
};

// Hands the values of one declaration to the file or the summary: each call
// fills the placeholders of the declared path, in order, with `at`.
class Emitter {
 public:
  virtual ~Emitter() = default;
  virtual void values(const std::vector<double>& data, const std::vector<std::string>& at = {}) = 0;
  // A 1-D dataset of `size` values handed over in pieces, in order, without a
  // whole copy where the receiver can take them so (the file): put(put_piece)
  // calls put_piece(data, count) until all `size` are given. Else collected
  // and handed to values().
  using PutPiece = std::function<void(const double* data, std::size_t count)>;
  virtual void pieces(std::size_t size, const std::function<void(const PutPiece&)>& put,
                      const std::vector<std::string>& at = {});
  virtual void matrix(const std::vector<double>& data, std::size_t rows, std::size_t cols,
                      const std::vector<std::string>& at = {}) = 0;
  virtual void text(const std::string& value, const std::vector<std::string>& at = {}) = 0;
  virtual void number(double value, const std::vector<std::string>& at = {}) = 0;
  virtual void json(const nlohmann::ordered_json& value, const std::vector<std::string>& at = {}) = 0;
};

struct Declaration {
  LayoutEntry entry;
  std::function<void(const RunResults&, Emitter&)> emit;  // emits nothing where the entry does not apply
};

// A declared path with each {placeholder} filled, in order, by `at`
// ("/continuum/{solver}/v", {"godunov"} -> "/continuum/godunov/v").
std::string fill_path(const std::string& path, const std::vector<std::string>& at);

}  // namespace shockgas::app
