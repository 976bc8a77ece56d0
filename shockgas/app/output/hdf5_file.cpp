#include "shockgas/app/output/hdf5_file.hpp"

#include <hdf5.h>

#include <mutex>
#include <utility>

#include "shockgas/core/error.hpp"

namespace shockgas::app {

std::recursive_mutex& hdf5_calls() {
  static std::recursive_mutex calls;
  return calls;
}

namespace {

// Once per process, before any other HDF5 call: HDF5's own error printing
// silenced (failures are reported by check()), and no clean-up at exit: the
// identifier of a file whose closing flush failed (a full disk) stays
// registered, and HDF5's exit handler crashes closing it again (HDF5 1.10.8:
// SIGSEGV in H5F__close_cb). shockgas closes every file itself (a failed close
// is a RunError), so an exit handler has nothing to do.
void init_hdf5() {
  static const bool done = [] {
    H5dont_atexit();
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    return true;
  }();
  (void)done;
}

// Walks HDF5's error stack, innermost entry first.
template <class F>
void walk_errors(F&& visit) {
  auto cb = [](unsigned, const H5E_error2_t* e, void* data) -> herr_t {
    (*static_cast<F*>(data))(*e);
    return 0;
  };
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, cb, &visit);
}

// Why the last HDF5 call failed, from its error stack: the system's reason where
// HDF5 gives one ("No space left on device"), else the innermost description.
std::string hdf5_reason() {
  std::string system, innermost;
  walk_errors([&](const H5E_error2_t& e) {
    const std::string desc = e.desc ? e.desc : "";
    if (innermost.empty()) innermost = desc;
    const auto at = desc.find("error message = '");
    if (system.empty() && at != std::string::npos) {
      const auto start = at + 17;
      system = desc.substr(start, desc.find('\'', start) - start);
    }
  });
  return system.empty() ? innermost : system;
}

bool hdf5_says_truncated() {
  bool truncated = false;
  walk_errors([&](const H5E_error2_t& e) { truncated |= e.min_num == H5E_TRUNCATED; });
  return truncated;
}

std::int64_t check(std::int64_t id, const char* call, const std::string& object) {
  if (id < 0) {
    const std::string reason = hdf5_reason();
    throw RunError(std::string("HDF5: ") + call + " failed on " + object +
                   (reason.empty() ? "" : " (" + reason + ")"));
  }
  return id;
}

int close_file(std::int64_t id) { return H5Fclose(id); }
int close_group(std::int64_t id) { return H5Gclose(id); }
int close_dataset(std::int64_t id) { return H5Dclose(id); }
int close_space(std::int64_t id) { return H5Sclose(id); }
int close_type(std::int64_t id) { return H5Tclose(id); }
int close_attr(std::int64_t id) { return H5Aclose(id); }
int close_plist(std::int64_t id) { return H5Pclose(id); }
int close_object(std::int64_t id) { return H5Oclose(id); }

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
  if (H5Aexists(object, name) <= 0) return "";
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

Hdf5File Hdf5File::create(const std::string& path) {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  init_hdf5();
  return Hdf5File(
      H5Handle(check(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), "H5Fcreate", path),
               close_file),
      path, Verification::manifest);
}

Hdf5File Hdf5File::open(const std::string& path) { return open(path, check_result_file(path)); }

Hdf5File Hdf5File::open(const std::string& path, Verification verified) {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  init_hdf5();
  const hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (id < 0 && hdf5_says_truncated())
    throw result_problem(path, "truncated", "shorter than the end of file its HDF5 superblock records");
  if (id < 0) throw result_problem(path, "unreadable", "the HDF5 library refuses it: " + hdf5_reason());
  return Hdf5File(H5Handle(id, close_file), path, verified);
}

void Hdf5File::close() {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  const std::int64_t id = file_.release();
  if (id >= 0) check(H5Fclose(id), "H5Fclose", path_);
}

Hdf5File Hdf5File::update(const std::string& path) {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  init_hdf5();
  return Hdf5File(
      H5Handle(check(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), "H5Fopen", path), close_file), path,
      Verification::no_manifest);
}

H5Handle Hdf5File::ensure_group(const std::string& path) {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  if (path == "/" || path.empty())
    return H5Handle(check(H5Gopen2(file_.get(), "/", H5P_DEFAULT), "H5Gopen2", "/"), close_group);
  if (H5Lexists(file_.get(), path.c_str(), H5P_DEFAULT) > 0)
    return H5Handle(check(H5Oopen(file_.get(), path.c_str(), H5P_DEFAULT), "H5Oopen", path), close_object);
  H5Handle lcpl(check(H5Pcreate(H5P_LINK_CREATE), "H5Pcreate", path), close_plist);
  check(H5Pset_create_intermediate_group(lcpl.get(), 1), "H5Pset_create_intermediate_group", path);
  return H5Handle(
      check(H5Gcreate2(file_.get(), path.c_str(), lcpl.get(), H5P_DEFAULT, H5P_DEFAULT), "H5Gcreate2", path),
      close_group);
}

H5Handle Hdf5File::create_dataset(const std::string& path, std::int64_t type, std::vector<std::uint64_t> dims,
                                  const std::string& unit, const std::string& description) {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  std::vector<hsize_t> hdims(dims.begin(), dims.end());
  H5Handle space(check(H5Screate_simple(static_cast<int>(hdims.size()), hdims.data(), nullptr),
                       "H5Screate_simple", path),
                 close_space);
  H5Handle lcpl(check(H5Pcreate(H5P_LINK_CREATE), "H5Pcreate", path), close_plist);
  check(H5Pset_create_intermediate_group(lcpl.get(), 1), "H5Pset_create_intermediate_group", path);
  H5Handle set(
      check(H5Dcreate2(file_.get(), path.c_str(), type, space.get(), lcpl.get(), H5P_DEFAULT, H5P_DEFAULT),
            "H5Dcreate2", path),
      close_dataset);
  write_string_attribute(set.get(), "unit", unit);
  if (!description.empty()) write_string_attribute(set.get(), "description", description);
  return set;
}

void Hdf5File::write_raw(const std::string& path, const void* data, std::int64_t type,
                         std::vector<std::uint64_t> dims, const std::string& unit,
                         const std::string& description) {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  std::size_t count = 1;
  for (auto d : dims) count *= d;
  H5Handle set = create_dataset(path, type, std::move(dims), unit, description);
  if (count > 0) check(H5Dwrite(set.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "H5Dwrite", path);
}

Hdf5File::Writer Hdf5File::start(const std::string& path, std::size_t size, const std::string& unit,
                                 const std::string& description) {
  return Writer(create_dataset(path, H5T_NATIVE_DOUBLE, {size}, unit, description), path, size);
}

// Each piece a hyperslab of the file's dataset, written from the caller's memory.
void Hdf5File::Writer::append(const double* data, std::size_t count) {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  if (count == 0) return;
  if (written_ + count > size_) throw RunError("HDF5: more values than " + path_ + " holds");
  const hsize_t offset = written_, n = count;
  H5Handle file_space(check(H5Dget_space(set_.get()), "H5Dget_space", path_), close_space);
  check(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, &offset, nullptr, &n, nullptr),
        "H5Sselect_hyperslab", path_);
  H5Handle memory(check(H5Screate_simple(1, &n, nullptr), "H5Screate_simple", path_), close_space);
  check(H5Dwrite(set_.get(), H5T_NATIVE_DOUBLE, memory.get(), file_space.get(), H5P_DEFAULT, data),
        "H5Dwrite", path_);
  written_ += count;
}

void Hdf5File::Writer::finish() {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  if (written_ != size_)
    throw RunError("HDF5: " + path_ + " got " + std::to_string(written_) + " of its " +
                   std::to_string(size_) + " values");
  const std::int64_t id = set_.release();
  check(H5Dclose(id), "H5Dclose", path_);
}

void Hdf5File::write(const std::string& path, const std::vector<double>& data, const std::string& unit,
                     const std::string& description) {
  write_raw(path, data.data(), H5T_NATIVE_DOUBLE, {data.size()}, unit, description);
}

void Hdf5File::write(const std::string& path, const std::vector<std::int64_t>& data, const std::string& unit,
                     const std::string& description) {
  write_raw(path, data.data(), H5T_NATIVE_INT64, {data.size()}, unit, description);
}

void Hdf5File::write_matrix(const std::string& path, const std::vector<double>& data, std::size_t rows,
                            std::size_t cols, const std::string& unit, const std::string& description) {
  if (data.size() != rows * cols) throw RunError("HDF5: matrix " + path + " has the wrong size");
  write_raw(path, data.data(), H5T_NATIVE_DOUBLE, {rows, cols}, unit, description);
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

namespace {
herr_t collect_dataset(hid_t root, const char* name, const H5O_info_t* info, void* out) {
  if (info->type != H5O_TYPE_DATASET) return 0;
  auto& list = *static_cast<std::vector<DatasetInfo>*>(out);
  H5Handle set(H5Dopen2(root, name, H5P_DEFAULT), close_dataset);
  if (set.get() < 0) return -1;
  H5Handle space(H5Dget_space(set.get()), close_space);
  H5Handle type(H5Dget_type(set.get()), close_type);
  DatasetInfo d;
  d.path = std::string("/") + name;
  const int rank = H5Sget_simple_extent_ndims(space.get());
  std::vector<hsize_t> dims(rank > 0 ? rank : 0);
  if (rank > 0) H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  d.shape.assign(dims.begin(), dims.end());
  d.type = type_name(type.get());
  d.unit = read_string_attribute(set.get(), "unit");
  d.description = read_string_attribute(set.get(), "description");
  list.push_back(std::move(d));
  return 0;
}
}  // namespace

std::vector<DatasetInfo> Hdf5File::datasets() const {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  std::vector<DatasetInfo> list;
  check(H5Ovisit2(file_.get(), H5_INDEX_NAME, H5_ITER_INC, collect_dataset, &list, H5O_INFO_BASIC),
        "H5Ovisit", "file");
  return list;
}

namespace {
herr_t collect_group(hid_t, const char* name, const H5O_info_t* info, void* out) {
  if (info->type != H5O_TYPE_GROUP) return 0;
  const std::string path(name);
  static_cast<std::vector<std::string>*>(out)->push_back(path == "." ? "/" : "/" + path);
  return 0;
}
}  // namespace

std::vector<std::string> Hdf5File::groups() const {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  std::vector<std::string> list;
  check(H5Ovisit2(file_.get(), H5_INDEX_NAME, H5_ITER_INC, collect_group, &list, H5O_INFO_BASIC), "H5Ovisit",
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
    H5Aget_name_by_idx(obj.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, name, sizeof name, H5P_DEFAULT);
    out.emplace_back(name, read_string_attribute(obj.get(), name));
  }
  return out;
}

std::vector<double> Hdf5File::read(const std::string& path) const {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  H5Handle set(check(H5Dopen2(file_.get(), path.c_str(), H5P_DEFAULT), "H5Dopen2", path), close_dataset);
  H5Handle space(check(H5Dget_space(set.get()), "H5Dget_space", path), close_space);
  const auto n = H5Sget_simple_extent_npoints(space.get());
  std::vector<double> data(n > 0 ? n : 0);
  if (n > 0)
    check(H5Dread(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), "H5Dread", path);
  return data;
}

}  // namespace shockgas::app
