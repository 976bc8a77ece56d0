// The SHA-256 of a file's attributes (Hdf5File::attributes_digest): the
// library keeps a string attribute's value in its global heap, which carries
// no checksum, so the file's writer stores their digest and every reader
// compares it (hdf5_file.cpp: close() and open()).
#include <string>
#include <vector>

#include "shockgas/app/files/sha256.hpp"
#include "shockgas/app/output/hdf5_file.hpp"
#include "shockgas/app/output/hdf5_file_calls.hpp"

namespace shockgas::app {

using namespace hdf5;

std::string Hdf5File::attributes_digest() const {
  const std::lock_guard<std::recursive_mutex> calls(hdf5_calls());
  std::vector<std::string> objects;
  auto collect = [](hid_t, const char* name, const H5O_info_t* info, void* out) -> herr_t {
    if (info->type != H5O_TYPE_GROUP && info->type != H5O_TYPE_DATASET) return 0;
    const std::string path(name);
    static_cast<std::vector<std::string>*>(out)->push_back(path == "." ? "/" : "/" + path);
    return 0;
  };
  // H5O_INFO_ALL: every object header read whole, each of its chunks' checksums checked.
  check(H5Ovisit2(file_.get(), H5_INDEX_NAME, H5_ITER_INC, collect, &objects, H5O_INFO_ALL), "H5Ovisit",
        "every object header");
  std::string text;
  for (const std::string& object : objects)
    for (const auto& [name, value] : attributes(object)) {
      if (object == "/" && name == kAttributesDigest) continue;
      for (const std::string* part : {&object, &name, &value}) text.append(*part).push_back('\0');
    }
  return sha256_of_text(text);
}

}  // namespace shockgas::app
