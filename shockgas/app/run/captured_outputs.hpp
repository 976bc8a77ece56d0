#pragma once
// The outputs of a run held in memory, named and shaped as the declared layout
// writes them to result.h5 and summary.json (output_layout.hpp): for a host that
// wants the values rather than the files (a Python session), and read back from
// the files of a finished run the same way.
#include <cstddef>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <variant>
#include <vector>

#include "shockgas/app/output/storage.hpp"
#include "shockgas/app/run/run_internal.hpp"

namespace shockgas::app {

struct CapturedDataset {
  std::vector<double> data;            // row-major
  std::vector<std::size_t> shape;      // {n}, or {rows, cols}
  std::string unit, description;       // as declared
  Storage storage = Storage::float64;  // as declared: the type the file (and Python) gives the values
};

// Its implicit move is noexcept, as VariantResult's (run_results.hpp).
// NOLINTNEXTLINE(bugprone-exception-escape)
struct CapturedOutputs {
  std::map<std::string, CapturedDataset> datasets;  // "/particles/T"
  // "/particles@stop_reason": text for attributes declared without a unit, else a number.
  std::map<std::string, std::variant<std::string, double>> attributes;
  nlohmann::ordered_json summary;  // summary.json
};

// A sink (run_internal.hpp) that adds each part's datasets, attributes and
// summary keys to `out`, exactly as the writers would put them in the files.
PartSink capture_into(CapturedOutputs& out);

// The outputs of a finished run from its result.h5 (`path`: the file or its
// directory) and, if present beside it, its summary.json. Attributes declared
// with a unit are numbers (written in shortest round-trip form, so read back
// exactly). InputError naming RESULT.h5 if the file cannot be read.
CapturedOutputs read_outputs(const std::string& path);

}  // namespace shockgas::app
