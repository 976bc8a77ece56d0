#pragma once
// Private to hdf5_file*.cpp: the checked call (hdf5_file_calls.cpp), the
// closers of each kind of identifier, and the library's reason for a failure.
#include <hdf5.h>

#include <cstdint>
#include <string>

#include "shockgas/app/output/hdf5_file.hpp"

namespace shockgas::app::hdf5 {

// Once per process, before any other HDF5 call (hdf5_file.cpp says why).
void init();

// Why the last HDF5 call failed, from its error stack.
std::string reason();

// id, or RunError "HDF5: <call> failed on <object> (<reason>)" when it is
// negative; on a full disk also " (the file system holding it has N free)".
std::int64_t check(std::int64_t id, const char* call, const std::string& object);

inline int close_file(std::int64_t id) { return H5Fclose(id); }
inline int close_group(std::int64_t id) { return H5Gclose(id); }
inline int close_dataset(std::int64_t id) { return H5Dclose(id); }
inline int close_space(std::int64_t id) { return H5Sclose(id); }
inline int close_type(std::int64_t id) { return H5Tclose(id); }
inline int close_attr(std::int64_t id) { return H5Aclose(id); }
inline int close_plist(std::int64_t id) { return H5Pclose(id); }
inline int close_object(std::int64_t id) { return H5Oclose(id); }

// A property list of `kind` (H5P_LINK_CREATE, ...), owned.
inline H5Handle plist(hid_t kind, const std::string& object) {
  return H5Handle(check(H5Pcreate(kind), "H5Pcreate", object), close_plist);
}

// The file's dataspace of a dataset, owned.
inline H5Handle space_of(hid_t set, const std::string& path) {
  return H5Handle(check(H5Dget_space(set), "H5Dget_space", path), close_space);
}

}  // namespace shockgas::app::hdf5
