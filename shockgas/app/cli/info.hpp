#pragma once
#include <iosfwd>
#include <string>

namespace shockgas::app {

// Human-readable listing of a result file: provenance attributes, every dataset
// with shape, unit and description, and the scene text it was run from. For an
// output directory whose manifest lists no result file (`shockgas bench`), one
// line naming it. Throws InputError if the file is not a readable HDF5 file.
std::string describe_result(const std::string& path);

// The files of the run directory that holds a result file (the path itself, or
// the directory of the file), each checked against the directory's
// manifest.json: a listing for stdout, and what differs in one line (empty when
// every listed file has its recorded size and SHA-256; files the manifest does
// not list are named in the listing only). Both empty without a manifest.
// result_checked: the result file was checked already (describe_result), so it
// is not read a second time.
struct RunFilesCheck {
  std::string listing;
  std::string differences;
  std::string directory;  // the run directory checked
};
RunFilesCheck check_run_files(const std::string& path, bool result_checked = true);

// `shockgas info PATH`: describe_result, then check_run_files, to out. A result
// file that cannot be described (damaged, removed) does not keep the other
// files from being checked and listed; its problem is then thrown.
void print_info(const std::string& path, std::ostream& out);

// Every dataset, attribute and summary key a run may write, with unit and
// meaning, as markdown (the generated sections of docs/output.md).
std::string describe_layout();

}  // namespace shockgas::app
