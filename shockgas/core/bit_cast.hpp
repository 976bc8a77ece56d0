#pragma once
// std::bit_cast where the standard library has it, else the same bits through
// std::memcpy: libc++ 14 (Emscripten's, for the lab's WebAssembly build) lacks
// it. Every build of the command has std::bit_cast itself.
#include <bit>
#include <cstring>
#include <type_traits>

namespace shockgas {

#if defined(__cpp_lib_bit_cast)
using std::bit_cast;
#else
template <class To, class From>
To bit_cast(const From& from) noexcept {
  static_assert(sizeof(To) == sizeof(From) && std::is_trivially_copyable_v<To> &&
                std::is_trivially_copyable_v<From>);
  To to;
  std::memcpy(&to, &from, sizeof to);
  return to;
}
#endif

}  // namespace shockgas
