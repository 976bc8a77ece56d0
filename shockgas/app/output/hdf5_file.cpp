// The file, its attributes and reading it back; the datasets written are in
// hdf5_file_write.cpp.
#include "shockgas/app/output/hdf5_file.hpp"

#include <mutex>
#include <optional>
#include <utility>

#include "shockgas/app/files/own_checksum.hpp"
#include "shockgas/app/output/hdf5_file_calls.hpp"
#include "shockgas/app/output/layout_version.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

using namespace hdf5;

namespace {

bool hdf5_says_truncated() {
  bool truncated = false;
  H5Ewalk2(
      H5E_DEFAULT, H5E_WALK_UPWARD,
      [](unsigned, const H5E_error2_t* e, void* out) -> herr_t {
        *static_cast<bool*>(out) |= e->min_num == H5E_TRUNCATED;
        return 0;
      },
      &truncated);
  return truncated;
}

H5Handle string_type() {
  H5Handle t(check(H5Tcopy(H5T_C_S1), "H5Tcopy", "string type"), close_type);
  check(H5Tset_size(t.get(), H5T_VARIABLE), "H5Tset_size", "string type");
  check(H5Tset_cset(t.get(), H5T_CSET_UTF8), "H5Tset_cset", "string type");
  return t;
}

void write_string_attribute(std::int64_t object, const std::string& name, const std::string& value) {
  if (H5Aexists(object, name.c_str()) > 0) check(H5Adelete(object, name.c_str()), "H5Adelete", name);
  H5Handle type = string_type();
  H5Handle space(check(H5Screate(H5S_SCALAR), "H5Screate", name), close_space);
  H5Handle attr(check(H5Acreate2(object, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
                      "H5Acreate2", name),
                close_attr);
  const char* text = value.c_str();
  check(H5Awrite(attr.get(), type.get(), &text), "H5Awrite", name);
}

std::string type_name(hid_t type) {
  switch (H5Tget_class(type)) {
    case H5T_FLOAT:
      return "float" + std::to_string(8 * H5Tget_size(type));
    case H5T_INTEGER:
      return "int" + std::to_string(8 * H5Tget_size(type));
    case H5T_STRING:
      return "string";
    default:
      return "other";
  }
}

std::string read_string_attribute(hid_t object, const char* name) {
  if (check(H5Aexists(object, name), "H5Aexists", name) == 0) return "";  // < 0: unreadable (checksum)
  H5Handle attr(check(H5Aopen(object, name, H5P_DEFAULT), "H5Aopen", name), close_attr);
  H5Handle type(check(H5Aget_type(attr.get()), "H5Aget_type", name), close_type);
  if (H5Tget_class(type.get()) == H5T_FLOAT) {
    double v = 0;
    check(H5Aread(attr.get(), H5T_NATIVE_DOUBLE, &v), "H5Aread", name);
    return to_text(v);
  }
  if (H5Tget_class(type.get()) != H5T_STRING) return "(" + type_name(type.get()) + ")";
  H5Handle mem = string_type();
  char* text = nullptr;
  check(H5Aread(attr.get(), mem.get(), &text), "H5Aread", name);
  std::string value = text ? text : "";
  H5free_memory(text);
  return value;
}

// The attribute's value where the object has it (read_string_attribute), else nothing.
std::optional<std::string> stated_attribute(hid_t object, const char* name) {
  if (check(H5Aexists(object, name), "H5Aexists", name) == 0) return std::nullopt;
  return read_string_attribute(object, name);
}

// Calls visit(path, dataset id) for every dataset, in name order.
template <class F>
void each_dataset(hid_t file, F&& visit) {
  std::vector<std::string> paths;
  auto collect = [](hid_t, const char* name, const H5O_info_t* info, void* out) -> herr_t {
    if (info->type == H5O_TYPE_DATASET) static_cast<std::vector<std::string>*>(out)->push_back(name);
    return 0;
  };
  check(H5Ovisit2(file, H5_INDEX_NAME, H5_ITER_INC, collect, &paths, H5O_INFO_BASIC), "H5Ovisit", "file");
  for (const std::string& name : paths) {
    const std::string path = "/" + name;
    H5Handle set(check(H5Dopen2(file, path.c_str(), H5P_DEFAULT), "H5Dopen2", path), close_dataset);
    visit(path, set.get());
  }
}

std::vector<hsize_t> dims_of(hid_t set, const std::string& path) {
  H5Handle space = space_of(set, path);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  std::vector<hsize_t> dims(rank > 0 ? rank : 0);
  if (rank > 0) H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  return dims;
}

// Reads a dataset block by block along its first dimension, each block whole
// chunks (so every chunk is read, and its checksum checked, once).
void read_in_blocks(hid_t set, const std::string& path) {
  const std::vector<hsize_t> dims = dims_of(set, path);
  if (dims.empty()) return;
  H5Handle dcpl(check(H5Dget_create_plist(set), "H5Dget_create_plist", path), close_plist);
  std::vector<hsize_t> chunk(dims.size(), 1);
  if (H5Pget_layout(dcpl.get()) == H5D_CHUNKED)
    H5Pget_chunk(dcpl.get(), static_cast<int>(chunk.size()), chunk.data());
  std::vector<hsize_t> block = dims;
  block[0] = std::min<hsize_t>(dims[0], std::max<hsize_t>(chunk[0], 1));
  hsize_t per_row = 1;
  for (std::size_t i = 1; i < dims.size(); ++i) per_row *= dims[i];
  std::vector<double> values(block[0] * per_row);
  H5Handle file_space = space_of(set, path);
  for (hsize_t row = 0; row < dims[0]; row += block[0]) {
    std::vector<hsize_t> start(dims.size(), 0), count = block;
    start[0] = row;
    count[0] = std::min(block[0], dims[0] - row);
    check(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr),
          "H5Sselect_hyperslab", path);
    H5Handle memory(check(H5Screate_simple(static_cast<int>(count.size()), count.data(), nullptr),
                          "H5Screate_simple", path),
                    close_space);
    check(H5Dread(set, H5T_NATIVE_DOUBLE, memory.get(), file_space.get(), H5P_DEFAULT, values.data()),
          "H5Dread", path);
  }
}

}  // namespace

H5Handle& H5Handle::operator=(H5Handle&& o) noexcept {
  if (this != &o) {
    reset();
    id_ = o.id_;
    close_ = o.close_;
    o.id_ = -1;
  }
  return *this;
}

std::int64_t H5Handle::release() { return std::exchange(id_, -1); }

void H5Handle::reset() {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  if (id_ >= 0 && close_) close_(id_);
  id_ = -1;
}

// The latest format (its metadata checksummed) and a user block for the file's own checksum.
Hdf5File Hdf5File::create(const std::string& path) {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  init();
  H5Handle fcpl = plist(H5P_FILE_CREATE, path), fapl = plist(H5P_FILE_ACCESS, path);
  check(H5Pset_userblock(fcpl.get(), kOwnChecksumBytes), "H5Pset_userblock", path);
  check(H5Pset_libver_bounds(fapl.get(), H5F_LIBVER_LATEST, H5F_LIBVER_LATEST), "H5Pset_libver_bounds", path);
  return Hdf5File(
      H5Handle(check(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, fcpl.get(), fapl.get()), "H5Fcreate", path),
               close_file),
      path, Verification::own_checksum, true);
}

Hdf5File Hdf5File::open(const std::string& path) { return open(path, check_result_file(path)); }

Hdf5File Hdf5File::open(const std::string& path, Verification verified) {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  init();
  const hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (id < 0 && hdf5_says_truncated())
    throw result_problem(path, "truncated", "shorter than the end of file its HDF5 superblock records");
  if (id < 0) throw result_problem(path, "unreadable", "the HDF5 library refuses it: " + reason());
  Hdf5File file(H5Handle(id, close_file), path, verified, false);
  // Bytes past the end the superblock records are none of the file's (the library reads past them).
  haddr_t end = 0;
  hsize_t size = 0;
  check(H5Fget_eoa(id, &end), "H5Fget_eoa", path);
  check(H5Fget_filesize(id, &size), "H5Fget_filesize", path);
  if (size > end)
    throw result_problem(path, "damaged",
                         std::to_string(size - end) +
                             " bytes after the end of file its HDF5 superblock records (" +
                             std::to_string(end) + " bytes): appended since it was written");
  H5Handle root(check(H5Gopen2(id, "/", H5P_DEFAULT), "H5Gopen2", "/"), close_group);
  const std::optional<std::string> layout = stated_attribute(root.get(), "layout_version");
  check_layout_version(path, layout);
  // Every object header and attribute is read here, whether or not the file stores their digest.
  const std::string digest = file.attributes_digest();
  const auto stored = stated_attribute(root.get(), kAttributesDigest);
  if (stored && *stored != digest)
    throw result_problem(path, "damaged",
                         std::string("its attributes are not those whose SHA-256 its writer stored (/@") +
                             kAttributesDigest + "): one was changed or damaged after it was written");
  if (verified != Verification::damaged)  // info naming a damage reads whatever is left
    check_layout_marks(path, parse_layout_version(path, layout),
                       {verified == Verification::own_checksum, stored.has_value(),
                        H5Aexists(root.get(), "shockgas_version") > 0});
  return file;
}

Hdf5File Hdf5File::update(const std::string& path) {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  init();
  return Hdf5File(
      H5Handle(check(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), "H5Fopen", path), close_file), path,
      Verification::no_manifest, true);
}

void Hdf5File::close() {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  if (file_.get() < 0) return;
  if (writes_) set_attribute("/", kAttributesDigest, attributes_digest());
  const std::int64_t id = file_.release();
  hsize_t user_block = 0;
  if (writes_) {
    H5Handle fcpl(check(H5Fget_create_plist(id), "H5Fget_create_plist", path_), close_plist);
    check(H5Pget_userblock(fcpl.get(), &user_block), "H5Pget_userblock", path_);
  }
  check(H5Fclose(id), "H5Fclose", path_);
  if (user_block == kOwnChecksumBytes) write_own_checksum(path_);
}

H5Handle Hdf5File::ensure_group(const std::string& path) {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  if (path == "/" || path.empty())
    return H5Handle(check(H5Gopen2(file_.get(), "/", H5P_DEFAULT), "H5Gopen2", "/"), close_group);
  if (H5Lexists(file_.get(), path.c_str(), H5P_DEFAULT) > 0)
    return H5Handle(check(H5Oopen(file_.get(), path.c_str(), H5P_DEFAULT), "H5Oopen", path), close_object);
  H5Handle lcpl = plist(H5P_LINK_CREATE, path);
  check(H5Pset_create_intermediate_group(lcpl.get(), 1), "H5Pset_create_intermediate_group", path);
  return H5Handle(
      check(H5Gcreate2(file_.get(), path.c_str(), lcpl.get(), H5P_DEFAULT, H5P_DEFAULT), "H5Gcreate2", path),
      close_group);
}

void Hdf5File::set_attribute(const std::string& object, const std::string& name, const std::string& value) {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  H5Handle obj = ensure_group(object);
  write_string_attribute(obj.get(), name, value);
}

void Hdf5File::set_attribute(const std::string& object, const std::string& name, double value) {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  H5Handle obj = ensure_group(object);
  if (H5Aexists(obj.get(), name.c_str()) > 0) check(H5Adelete(obj.get(), name.c_str()), "H5Adelete", name);
  H5Handle space(check(H5Screate(H5S_SCALAR), "H5Screate", name), close_space);
  H5Handle attr(
      check(H5Acreate2(obj.get(), name.c_str(), H5T_NATIVE_DOUBLE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
            "H5Acreate2", name),
      close_attr);
  check(H5Awrite(attr.get(), H5T_NATIVE_DOUBLE, &value), "H5Awrite", name);
}

std::vector<DatasetInfo> Hdf5File::datasets() const {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  std::vector<DatasetInfo> list;
  each_dataset(file_.get(), [&](const std::string& path, hid_t set) {
    H5Handle type(check(H5Dget_type(set), "H5Dget_type", path), close_type);
    const std::vector<hsize_t> dims = dims_of(set, path);
    list.push_back({path,
                    {dims.begin(), dims.end()},
                    type_name(type.get()),
                    read_string_attribute(set, "unit"),
                    read_string_attribute(set, "description")});
  });
  return list;
}

std::vector<std::string> Hdf5File::groups() const {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  std::vector<std::string> list;
  auto collect = [](hid_t, const char* name, const H5O_info_t* info, void* out) -> herr_t {
    if (info->type != H5O_TYPE_GROUP) return 0;
    const std::string path(name);
    static_cast<std::vector<std::string>*>(out)->push_back(path == "." ? "/" : "/" + path);
    return 0;
  };
  check(H5Ovisit2(file_.get(), H5_INDEX_NAME, H5_ITER_INC, collect, &list, H5O_INFO_BASIC), "H5Ovisit",
        "file");
  return list;
}

std::vector<std::pair<std::string, std::string>> Hdf5File::attributes(const std::string& object) const {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  std::vector<std::pair<std::string, std::string>> out;
  H5Handle obj(check(H5Oopen(file_.get(), object.c_str(), H5P_DEFAULT), "H5Oopen", object), close_object);
  H5O_info_t info;
  check(H5Oget_info2(obj.get(), &info, H5O_INFO_NUM_ATTRS), "H5Oget_info2", object);
  for (hsize_t i = 0; i < info.num_attrs; ++i) {
    char name[256];
    check(H5Aget_name_by_idx(obj.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, name, sizeof name, H5P_DEFAULT),
          "H5Aget_name_by_idx", object);
    out.emplace_back(name, read_string_attribute(obj.get(), name));
  }
  return out;
}

std::vector<double> Hdf5File::read(const std::string& path) const {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  H5Handle set(check(H5Dopen2(file_.get(), path.c_str(), H5P_DEFAULT), "H5Dopen2", path), close_dataset);
  H5Handle space = space_of(set.get(), path);
  const auto n = H5Sget_simple_extent_npoints(space.get());
  std::vector<double> data(n > 0 ? n : 0);
  if (n > 0)
    check(H5Dread(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), "H5Dread", path);
  return data;
}

std::vector<UnreadableDataset> Hdf5File::unreadable_datasets() const {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  std::vector<UnreadableDataset> out;
  each_dataset(file_.get(), [&](const std::string& path, hid_t set) {
    try {
      read_in_blocks(set, path);
    } catch (const RunError& e) {
      out.push_back({path, e.what()});
    }
  });
  return out;
}

void Hdf5File::check_every_chunk() const {
  std::string names;
  for (const UnreadableDataset& d : unreadable_datasets())
    names += (names.empty() ? "dataset " : ", dataset ") + d.path + " (" + d.reason + ")";
  if (!names.empty()) throw result_problem(path_, "damaged", names + " does not read back whole");
}

std::vector<ChunkExtent> Hdf5File::chunk_extents() const {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  std::vector<ChunkExtent> out;
  H5Handle fcpl(check(H5Fget_create_plist(file_.get()), "H5Fget_create_plist", path_), close_plist);
  hsize_t base = 0;  // chunk addresses count from the superblock, after the user block
  check(H5Pget_userblock(fcpl.get(), &base), "H5Pget_userblock", path_);
  each_dataset(file_.get(), [&](const std::string& path, hid_t set) {
    hsize_t n = 0;
    const H5Handle space = space_of(set, path);  // H5S_ALL is refused here (HDF5 1.10.8)
    check(H5Dget_num_chunks(set, space.get(), &n), "H5Dget_num_chunks", path);
    for (hsize_t i = 0; i < n; ++i) {
      haddr_t addr = 0;
      hsize_t size = 0;
      unsigned mask = 0;
      check(H5Dget_chunk_info(set, space.get(), i, nullptr, &mask, &addr, &size), "H5Dget_chunk_info", path);
      out.push_back({path, base + addr, size});
    }
  });
  return out;
}

}  // namespace shockgas::app
