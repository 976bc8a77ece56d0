// The version of the shared library a program runs with, to compare with the
// one its headers declare (shockgas/version.hpp): shockgas::kVersion. Declared
// in the facade (shockgas/shockgas.hpp), which no part of shockgas includes.
#include "shockgas/version.hpp"

namespace shockgas {

const char* library_version() { return kVersion; }

}  // namespace shockgas
