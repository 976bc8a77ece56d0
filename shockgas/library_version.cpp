// The version of the shared library a program runs with, to compare with the
// one its headers declare (shockgas/version.hpp): shockgas::kVersion.
#include "shockgas/shockgas.hpp"

namespace shockgas {

const char* library_version() { return kVersion; }

}  // namespace shockgas
