#pragma once
// The one wrapper of the HDF5 C API in shockgas: RAII handles, every call
// checked (a failure throws RunError naming the call and the object). Every
// call holds hdf5_calls(), so that a child process forked to read a file
// (result_reader.hpp) never starts while another thread is inside the
// library. A result file is read through result_reader.hpp, never opened
// here directly: the library may crash inside a damaged file.
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "shockgas/app/directory/result_check.hpp"

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
  std::string type;                  // "float64", "int64", "string", ...
  std::string unit;                  // attribute "unit", if any
  std::string description;           // attribute "description", if any
};

class Hdf5File {
 public:
  // Creates (truncates) a file for writing.
  static Hdf5File create(const std::string& path);
  // Opens an existing file read-only that check_result_file() (result_check.hpp)
  // has passed with this verdict: FileProblem for a file the library refuses.
  // For result_reader.cpp, which does so where a crash cannot hurt, and tests.
  static Hdf5File open(const std::string& path, Verification checked);
  // The same after check_result_file(): for tests, on files they made.
  static Hdf5File open(const std::string& path);
  // Opens an existing file to add to it (RunError if it cannot be opened; tests).
  static Hdf5File update(const std::string& path);
  // Whether open() checked the file against its manifest.
  bool verified() const { return verification_ == Verification::manifest; }
  const std::string& path() const { return path_; }

  // Datasets; intermediate groups are created as needed. unit and description
  // become string attributes of the dataset.
  void write(const std::string& path, const std::vector<double>& data, const std::string& unit,
             const std::string& description);
  void write(const std::string& path, const std::vector<std::int64_t>& data, const std::string& unit,
             const std::string& description);
  // A rows x cols matrix, row-major.
  void write_matrix(const std::string& path, const std::vector<double>& data, std::size_t rows,
                    std::size_t cols, const std::string& unit, const std::string& description);

  // A 1-D float64 dataset of `size` values written in pieces, in order, never
  // held whole: append() each piece, then finish() (RunError unless exactly
  // `size` values were given). The same dataset as write() of them all.
  class Writer {
   public:
    void append(const double* data, std::size_t count);
    void finish();

   private:
    friend class Hdf5File;
    Writer(H5Handle set, std::string path, std::size_t size)
        : set_(std::move(set)), path_(std::move(path)), size_(size) {}
    H5Handle set_;
    std::string path_;
    std::size_t size_, written_ = 0;
  };
  Writer start(const std::string& path, std::size_t size, const std::string& unit,
               const std::string& description);

  // Attributes on a group or dataset ("/" for the file); the group is created if missing.
  void set_attribute(const std::string& object, const std::string& name, const std::string& value);
  void set_attribute(const std::string& object, const std::string& name, double value);

  // Reading (for `shockgas info` and tests).
  std::vector<DatasetInfo> datasets() const;
  // Every group, "/" first ("/particles", "/continuum/godunov", ...).
  std::vector<std::string> groups() const;
  std::vector<std::pair<std::string, std::string>> attributes(const std::string& object) const;
  std::vector<double> read(const std::string& path) const;

  // Closes the file (its last data flushed); RunError if that fails. Without
  // it the destructor closes and ignores a failure (a run that failed anyway).
  void close();

 private:
  Hdf5File(H5Handle file, std::string path, Verification v)
      : file_(std::move(file)), path_(std::move(path)), verification_(v) {}
  H5Handle ensure_group(const std::string& path);
  void write_raw(const std::string& path, const void* data, std::int64_t type,
                 std::vector<std::uint64_t> dims, const std::string& unit, const std::string& description);
  H5Handle create_dataset(const std::string& path, std::int64_t type, std::vector<std::uint64_t> dims,
                          const std::string& unit, const std::string& description);
  H5Handle file_;
  std::string path_;
  Verification verification_;
};

}  // namespace shockgas::app
