// The checked HDF5 call and the library's state shared by every file
// (hdf5_file_calls.hpp): its mutex, its setup, its reason for a failure.
#include "shockgas/app/output/hdf5_file_calls.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <string_view>
#include <vector>

#include "shockgas/app/files/durable_file.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

std::recursive_mutex& hdf5_calls() {
  static std::recursive_mutex calls;
  return calls;
}

namespace hdf5 {

// HDF5's own error printing silenced (failures are reported by check()), and no
// clean-up at exit: the identifier of a file whose closing flush failed (a full
// disk) stays registered, and HDF5's exit handler crashes closing it again
// (HDF5 1.10.8: SIGSEGV in H5F__close_cb). shockgas closes every file itself (a
// failed close is a RunError), so an exit handler has nothing to do.
void init() {
  static const bool done = [] {
    H5dont_atexit();
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    return true;
  }();
  (void)done;
}

namespace {

// Walks HDF5's error stack, innermost entry first.
template <class F>
void walk_errors(F&& visit) {
  auto cb = [](unsigned, const H5E_error2_t* e, void* data) -> herr_t {
    (*static_cast<F*>(data))(*e);
    return 0;
  };
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, cb, &visit);
}

}  // namespace

// The system's reason where HDF5 gives one ("No space left on device"), else
// the innermost description.
std::string reason() {
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

namespace {

// Where the file a call failed on lies: the object itself for a call on a
// file (H5Fcreate, H5Fclose: its path), else the file the library has open
// for writing (one at a time here); empty if none.
std::filesystem::path written_file(const char* call, const std::string& object) {
  if (std::string_view(call).rfind("H5F", 0) == 0) return object;
  const ssize_t count = H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_FILE);
  std::vector<hid_t> ids(count > 0 ? static_cast<std::size_t>(count) : 0);
  if (ids.empty() || H5Fget_obj_ids(H5F_OBJ_ALL, H5F_OBJ_FILE, ids.size(), ids.data()) < 0) return {};
  for (const hid_t id : ids) {  // the library's own identifiers: not to be closed here
    unsigned intent = 0;
    if (H5Fget_intent(id, &intent) < 0 || (intent & H5F_ACC_RDWR) == 0) continue;
    std::string name(static_cast<std::size_t>(std::max<ssize_t>(H5Fget_name(id, nullptr, 0), 0)), '\0');
    if (!name.empty() && H5Fget_name(id, name.data(), name.size() + 1) > 0) return name;
  }
  return {};
}

}  // namespace

std::int64_t check(std::int64_t id, const char* call, const std::string& object) {
  if (id < 0) {
    const std::string why = reason();
    // A full disk: how much room is left where the file lies (as every write names it).
    const std::filesystem::path file = why == std::strerror(ENOSPC) ? written_file(call, object) : "";
    throw RunError(std::string("HDF5: ") + call + " failed on " + object +
                   (why.empty() ? "" : " (" + why + ")") +
                   (file.empty() ? "" : room_note(file.parent_path())));
  }
  return id;
}

}  // namespace hdf5

}  // namespace shockgas::app
