// The datasets of a file as written: each chunked, its chunks filtered by
// shuffle (the bytes of the values grouped by significance), deflate and
// Fletcher32 (a checksum of the stored chunk, checked on every read), its
// values stored as its declared Storage says.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <mutex>

#include "shockgas/app/output/hdf5_file.hpp"
#include "shockgas/app/output/hdf5_file_calls.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

using namespace hdf5;

namespace {

// Values per chunk: 512 KiB of float64, within HDF5's default chunk cache (1 MiB).
constexpr hsize_t kChunkValues = hsize_t{1} << 16;
// zlib's level: chosen by write time against size (docs/performance.md, "result.h5").
constexpr unsigned kDeflateLevel = 4;

// Rows of whole cols (or a piece of one row) making about kChunkValues values;
// at least 1 in each dimension (an empty dataset has one empty chunk).
std::vector<hsize_t> chunk_shape(const std::vector<hsize_t>& dims) {
  std::vector<hsize_t> chunk(dims.size(), 1);
  if (dims.size() == 1) chunk[0] = std::clamp<hsize_t>(dims[0], 1, kChunkValues);
  if (dims.size() == 2) {
    chunk[1] = std::clamp<hsize_t>(dims[1], 1, kChunkValues);
    chunk[0] = std::clamp<hsize_t>(kChunkValues / chunk[1], 1, std::max<hsize_t>(dims[0], 1));
  }
  return chunk;
}

hid_t file_type(Storage s) {
  switch (s) {
    case Storage::float32:
      return H5T_IEEE_F32LE;
    case Storage::integer:
      return H5T_STD_I64LE;
    case Storage::float64:
      break;
  }
  return H5T_IEEE_F64LE;
}

// The creation properties: chunks, shuffle, deflate, Fletcher32 (last, so that
// it covers the bytes as stored and is checked before anything else on read).
H5Handle creation_properties(const std::vector<hsize_t>& dims, const std::string& path) {
  H5Handle dcpl = plist(H5P_DATASET_CREATE, path);
  const std::vector<hsize_t> chunk = chunk_shape(dims);
  check(H5Pset_chunk(dcpl.get(), static_cast<int>(chunk.size()), chunk.data()), "H5Pset_chunk", path);
  check(H5Pset_shuffle(dcpl.get()), "H5Pset_shuffle", path);
  check(H5Pset_deflate(dcpl.get(), kDeflateLevel), "H5Pset_deflate", path);
  check(H5Pset_fletcher32(dcpl.get()), "H5Pset_fletcher32", path);
  check(H5Pset_obj_track_times(dcpl.get(), false), "H5Pset_obj_track_times",
        path);  // the same bytes for the same run
  return dcpl;
}

// Writes `count` doubles as the file's type of `storage` into the selection
// `file_space` (H5S_ALL: the whole dataset) from memory laid out as `memory`.
void write_values(hid_t set, Storage storage, const double* data, std::size_t count, hid_t memory,
                  hid_t file_space, const std::string& path) {
  if (storage == Storage::float64) {
    check(H5Dwrite(set, H5T_NATIVE_DOUBLE, memory, file_space, H5P_DEFAULT, data), "H5Dwrite", path);
    return;
  }
  if (storage == Storage::float32) {
    std::vector<float> values(data, data + count);  // each rounded to the nearest float32
    check(H5Dwrite(set, H5T_NATIVE_FLOAT, memory, file_space, H5P_DEFAULT, values.data()), "H5Dwrite", path);
    return;
  }
  std::vector<std::int64_t> values(count);
  for (std::size_t i = 0; i < count; ++i) {
    if (!(std::nearbyint(data[i]) == data[i] && std::abs(data[i]) < 0x1p63))
      throw RunError("output layout: " + path + " is declared integer and got " + to_text(data[i]));
    values[i] = static_cast<std::int64_t>(data[i]);
  }
  check(H5Dwrite(set, H5T_NATIVE_INT64, memory, file_space, H5P_DEFAULT, values.data()), "H5Dwrite", path);
}

}  // namespace

H5Handle Hdf5File::create_dataset(const std::string& path, Storage storage,
                                  const std::vector<std::uint64_t>& dims, const std::string& unit,
                                  const std::string& description) {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  const std::vector<hsize_t> hdims(dims.begin(), dims.end());
  std::vector<hsize_t> max = hdims;  // an empty dimension may grow: a chunk of 1 is allowed there
  for (hsize_t& m : max)
    if (m == 0) m = H5S_UNLIMITED;
  H5Handle space(check(H5Screate_simple(static_cast<int>(hdims.size()), hdims.data(), max.data()),
                       "H5Screate_simple", path),
                 close_space);
  H5Handle lcpl = plist(H5P_LINK_CREATE, path);
  check(H5Pset_create_intermediate_group(lcpl.get(), 1), "H5Pset_create_intermediate_group", path);
  H5Handle dcpl = creation_properties(hdims, path);
  H5Handle set(check(H5Dcreate2(file_.get(), path.c_str(), file_type(storage), space.get(), lcpl.get(),
                                dcpl.get(), H5P_DEFAULT),
                     "H5Dcreate2", path),
               close_dataset);
  set_attribute(path, "unit", unit);
  if (!description.empty()) set_attribute(path, "description", description);
  return set;
}

void Hdf5File::write(const std::string& path, const double* data, const std::vector<std::uint64_t>& dims,
                     Storage storage, const std::string& unit, const std::string& description) {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  std::size_t count = 1;
  for (auto d : dims) count *= d;
  H5Handle set = create_dataset(path, storage, dims, unit, description);
  if (count > 0) write_values(set.get(), storage, data, count, H5S_ALL, H5S_ALL, path);
}

Hdf5File::Writer Hdf5File::start(const std::string& path, std::size_t size, Storage storage,
                                 const std::string& unit, const std::string& description) {
  return Writer(create_dataset(path, storage, {size}, unit, description), path, size, storage,
                chunk_shape({size})[0]);
}

Hdf5File::Writer::Writer(H5Handle set, std::string path, std::size_t size, Storage storage, std::size_t chunk)
    : set_(std::move(set)), path_(std::move(path)), size_(size), storage_(storage), chunk_(chunk) {
  block_.reserve(chunk_);
}

// Pieces are gathered into whole chunks, each written once as a hyperslab.
void Hdf5File::Writer::append(const double* data, std::size_t count) {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  if (written_ + block_.size() + count > size_) throw RunError("HDF5: more values than " + path_ + " holds");
  while (count > 0) {
    const std::size_t take = std::min(count, chunk_ - block_.size());
    block_.insert(block_.end(), data, data + take);
    data += take, count -= take;
    if (block_.size() == chunk_) write_block();
  }
}

void Hdf5File::Writer::write_block() {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  if (block_.empty()) return;
  const hsize_t offset = written_, n = block_.size();
  H5Handle file_space = space_of(set_.get(), path_);
  check(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, &offset, nullptr, &n, nullptr),
        "H5Sselect_hyperslab", path_);
  H5Handle memory(check(H5Screate_simple(1, &n, nullptr), "H5Screate_simple", path_), close_space);
  write_values(set_.get(), storage_, block_.data(), block_.size(), memory.get(), file_space.get(), path_);
  written_ += block_.size();
  block_.clear();
}

void Hdf5File::Writer::finish() {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  write_block();
  if (written_ != size_)
    throw RunError("HDF5: " + path_ + " got " + std::to_string(written_) + " of its " +
                   std::to_string(size_) + " values");
  const std::int64_t id = set_.release();
  check(H5Dclose(id), "H5Dclose", path_);
}

}  // namespace shockgas::app
