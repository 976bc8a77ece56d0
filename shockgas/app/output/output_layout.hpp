#pragma once
// The output of a run, declared once (output_datasets.cpp, summary_keys.cpp):
// every dataset and attribute of result.h5 and every key of summary.json, with
// its unit, its meaning and how it is taken from the run's results. The writers
// below, `shockgas info` and docs/output.md follow from these declarations; a
// test holds them against the documentation and against the files of a run.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "shockgas/app/output/declaration.hpp"
#include "shockgas/app/output/hdf5_file.hpp"

namespace shockgas::app {

// The declarations (output_datasets.cpp: datasets and attributes; summary_keys.cpp).
const std::vector<Declaration>& dataset_declarations();
const std::vector<Declaration>& summary_declarations();

// Every declared entry, datasets and attributes first, then summary keys.
std::vector<LayoutEntry> output_layout();

// Writes the datasets and attributes of `part` into h5, from r.
void write_part(Hdf5File& h5, const RunResults& r, Part part);
// Adds the summary keys of `part` to summary, from r.
void summarize_part(nlohmann::ordered_json& summary, const RunResults& r, Part part);

// The declared entry of this kind that a concrete path or key falls under, or nullptr.
const LayoutEntry* find_in_layout(LayoutEntry::Kind kind, const std::string& concrete);

// The declared layout as markdown tables: the generated sections of docs/output.md.
std::string output_layout_markdown();

// The heading of a part's tables ("Particles (when [particles] is present)").
std::string part_title(Part part);

}  // namespace shockgas::app
