#pragma once
#include <string>

namespace shockgas::app {

// Human-readable listing of a result file: provenance attributes, every dataset
// with shape, unit and description, and the scene text it was run from.
// Throws InputError if the file is not a readable HDF5 file.
std::string describe_result(const std::string& path);

// Every dataset, attribute and summary key a run may write, with unit and
// meaning, as markdown (the generated sections of docs/output.md).
std::string describe_layout();

}  // namespace shockgas::app
