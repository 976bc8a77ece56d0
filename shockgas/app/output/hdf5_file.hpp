#pragma once
// The one wrapper of the HDF5 C API in shockgas: RAII handles, every call
// checked (a failure throws RunError naming the call and the object). Every
// call holds hdf5_calls(), so that a child process forked to read a file
// (result_reader.hpp) never starts while another thread is inside the
// library. A result file is read through result_reader.hpp, never opened
// here directly: the library may crash inside a damaged file.
//
// Every file is written in the library's latest format (superblock, object
// headers and chunk indexes with checksums), with every dataset chunked and
// filtered by shuffle, deflate and Fletcher32 (hdf5_file_write.cpp), and its
// first 512 bytes (a user block, which the library leaves to the program) hold
// the SHA-256 of the rest (own_checksum.hpp): a copied file can tell that it
// is damaged, wherever the damage lies.
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "shockgas/app/directory/result_check.hpp"
#include "shockgas/app/output/storage.hpp"

namespace shockgas::app {

// Held by every call into the HDF5 library (above).
std::recursive_mutex& hdf5_calls();

// Owns one HDF5 identifier and closes it with the matching H5*close.
class H5Handle {
 public:
  using Closer = int (*)(std::int64_t);
  H5Handle() = default;
  H5Handle(std::int64_t id, Closer close) : id_(id), close_(close) {}
  H5Handle(H5Handle&& o) noexcept : id_(o.id_), close_(o.close_) { o.id_ = -1; }
  H5Handle& operator=(H5Handle&& o) noexcept;
  H5Handle(const H5Handle&) = delete;
  H5Handle& operator=(const H5Handle&) = delete;
  ~H5Handle() { reset(); }
  std::int64_t get() const { return id_; }
  std::int64_t release();  // gives up ownership: the caller closes
  void reset();            // closes; a failure is ignored (a destructor's close)

 private:
  std::int64_t id_ = -1;
  Closer close_ = nullptr;
};

// One dataset as seen by a reader.
struct DatasetInfo {
  std::string path;                  // "/particles/T"
  std::vector<std::uint64_t> shape;  // dimensions
  std::string type;                  // "float64", "float32", "int64", "string", ...
  std::string unit;                  // attribute "unit", if any
  std::string description;           // attribute "description", if any
};

// Where one chunk of a dataset lies in the file (for the tests of damage).
struct ChunkExtent {
  std::string dataset;
  std::uint64_t offset = 0, bytes = 0;  // from the start of the file
};

// A dataset whose values could not be read back, and the library's reason.
struct UnreadableDataset {
  std::string path, reason;
};

class Hdf5File {
 public:
  // Creates (truncates) a file for writing.
  static Hdf5File create(const std::string& path);
  // Opens an existing file read-only that check_result_file() (result_check.hpp)
  // has passed with this verdict: FileProblem (exit 2) for a file the library
  // refuses, and for a file of a newer layout than this build reads
  // (layout_version.hpp). For result_reader.cpp, which does so where a crash
  // cannot hurt, and tests.
  static Hdf5File open(const std::string& path, Verification checked);
  // The same after check_result_file(): for tests, on files they made.
  static Hdf5File open(const std::string& path);
  // Opens an existing file to add to it (RunError if it cannot be opened); its
  // own checksum is written again on close().
  static Hdf5File update(const std::string& path);
  // How open() checked the file; verified(): against its manifest or its own checksum.
  Verification verification() const { return verification_; }
  bool verified() const { return app::verified(verification_); }
  const std::string& path() const { return path_; }

  // Datasets of `dims` (1 or 2) from doubles in row-major order, stored as
  // `storage` says; intermediate groups are created as needed; unit and
  // description become string attributes of the dataset.
  void write(const std::string& path, const double* data, const std::vector<std::uint64_t>& dims,
             Storage storage, const std::string& unit, const std::string& description);

  // A 1-D dataset of `size` values written in pieces, in order, never held
  // whole: append() each piece, then finish() (RunError unless exactly `size`
  // values were given). The same dataset as write() of them all.
  class Writer {
   public:
    void append(const double* data, std::size_t count);
    void finish();

   private:
    friend class Hdf5File;
    Writer(H5Handle set, std::string path, std::size_t size, Storage storage, std::size_t chunk);
    void write_block();
    H5Handle set_;
    std::string path_;
    std::size_t size_, written_ = 0;
    Storage storage_;
    std::vector<double> block_;  // one chunk's values: every chunk is written whole, once
    std::size_t chunk_;
  };
  Writer start(const std::string& path, std::size_t size, Storage storage, const std::string& unit,
               const std::string& description);

  // Attributes on a group or dataset ("/" for the file); the group is created if missing.
  void set_attribute(const std::string& object, const std::string& name, const std::string& value);
  void set_attribute(const std::string& object, const std::string& name, double value);

  // Reading (for `shockgas info` and tests).
  std::vector<DatasetInfo> datasets() const;
  // Every group, "/" first ("/particles", "/continuum/godunov", ...).
  std::vector<std::string> groups() const;
  std::vector<std::pair<std::string, std::string>> attributes(const std::string& object) const;
  // The values as doubles, whatever the storage (float32 and int64 are exact in a double).
  std::vector<double> read(const std::string& path) const;
  // Reads every chunk of every dataset (their Fletcher32 checksums checked):
  // those that fail, with the library's reason; empty when all read.
  std::vector<UnreadableDataset> unreadable_datasets() const;
  // The same as a verdict: FileProblem "damaged" (exit 2) naming every dataset
  // that does not read back whole. What `info` runs on every file, and any
  // command may run before it trusts a file's values.
  void check_every_chunk() const;
  // Where every chunk of every dataset lies in the file.
  std::vector<ChunkExtent> chunk_extents() const;
  // The SHA-256 of every attribute of the file but /@attributes_sha256 (each
  // group and dataset in name order, "/" first, each attribute in name order:
  // its object, name and value as attributes() reads them). close() stores it
  // as /@attributes_sha256 and open() compares: the library keeps string
  // attributes in its global heap, which carries no checksum of its own.
  std::string attributes_digest() const;
  // The root attribute that holds it.
  static constexpr const char* kAttributesDigest = "attributes_sha256";

  // Closes the file (its last data flushed), then writes its own checksum
  // (own_checksum.hpp) if it was written; RunError if that fails. Without it
  // the destructor closes and ignores a failure (a run that failed anyway).
  void close();

 private:
  Hdf5File(H5Handle file, std::string path, Verification v, bool writes)
      : file_(std::move(file)), path_(std::move(path)), verification_(v), writes_(writes) {}
  H5Handle ensure_group(const std::string& path);
  H5Handle create_dataset(const std::string& path, Storage storage, const std::vector<std::uint64_t>& dims,
                          const std::string& unit, const std::string& description);
  H5Handle file_;
  std::string path_;
  Verification verification_;
  bool writes_;
};

}  // namespace shockgas::app
