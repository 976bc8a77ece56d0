#pragma once
// The one way shockgas reads a result file (info, animate, merge, resume, the
// report and the Python module's load): what it holds, read into memory.
//
// The HDF5 library is not safe on a hostile file: a damaged one can make it
// crash, loop or claim more memory than there is. A file is therefore first
// checked (result_check.hpp: missing, truncated, not HDF5, other than its
// manifest records), then read by the library in a child process
// (isolated_call.hpp), its contents streamed back. The layout is read first,
// by a child whose memory is sized by the file's bytes; then the values asked
// for, by a child sized by their declared (uncompressed) size: a file that
// declares more than deflate can pack into its bytes is "damaged", one whose
// values cannot be held in the memory available "too large to read" (both
// FileProblem, exit 2, before a value is read). A crash, a refusal or any
// failure of the library there is a FileProblem "damaged" (exit 2, from
// Python an InputError) naming the file, and this process never runs the
// library on it. A manifest can be edited along with the file it lists, and
// a file's own checksum (own_checksum.hpp) along with the file, so neither
// is proof that the file is sound: read_result() is where the choice to read
// in this process would be made (reads_in_process()).
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "shockgas/app/directory/result_check.hpp"
#include "shockgas/app/output/hdf5_file.hpp"

namespace shockgas::app {

struct ResultContents {
  std::string path;                   // the result file
  Verification verification;          // how it was checked before it was read
  std::vector<DatasetInfo> datasets;  // every dataset, in name order
  std::vector<std::string> groups;    // every group, "/" first
  // The attributes of each group, by name order ("/" for the file).
  std::map<std::string, std::vector<std::pair<std::string, std::string>>> attributes;
  std::map<std::string, std::vector<double>> values;  // the datasets asked for

  // Checked against its manifest or its own checksum.
  bool verified() const { return app::verified(verification); }
  // The attributes of a group (none for a group the file does not have).
  const std::vector<std::pair<std::string, std::string>>& attributes_of(const std::string& group) const;
  // One attribute; "" where the group or the attribute is missing.
  std::string attribute(const std::string& group, const std::string& name) const;
};

// Which datasets' values to read, by path ({}: none).
using ValueFilter = std::function<bool(const std::string& path)>;

// The contents of the result file `file` names (the file, or the result.h5 of
// a run directory), checked (check_result_file) and read as above.
ResultContents read_result(const std::filesystem::path& file, const ValueFilter& values = {});
// The same for a file check_result_file() has passed with this verdict (read
// again: a shard's records after its header; it is not hashed a second time).
ResultContents read_result(const std::filesystem::path& file, Verification checked,
                           const ValueFilter& values = {});

// The contents of the result file this process is writing, from its open
// handle (no reading process and no check: it holds what this process wrote),
// as read_result will read them once it is closed, but for the attribute
// close() adds (/@attributes_sha256). For what the run writes beside it
// (result.xdmf, report.html), so that it never reads back the file it wrote.
ResultContents written_contents(const Hdf5File& writing, const ValueFilter& values = {});

// The same, every chunk of every dataset read first in the child process, its
// Fletcher32 checked (Hdf5File::check_every_chunk): FileProblem "damaged"
// naming the datasets that do not read back whole. What `info` reads.
ResultContents read_every_chunk(const std::filesystem::path& file, Verification checked);

// Whether a file checked so is read in this process: one whose own checksums
// were verified (none: every file is read in a child process).
bool reads_in_process(Verification checked);

}  // namespace shockgas::app
