#include "shockgas/core/instruction_sets.hpp"

#include <unistd.h>

#include <cstddef>
#include <cstring>

#include "shockgas/version.hpp"

namespace shockgas {

namespace {

struct Probe {
  const char* name;
  bool (*has)();
};

#if defined(__x86_64__) || defined(__i386__)
// One entry per instruction set, by its name for __builtin_cpu_supports (which
// wants a literal): those GCC and Clang both know. LZCNT and MOVBE come with
// every AVX2 processor; F16C, AVX-VNNI and AVX512-FP16 carry no double arithmetic.
// cmake/Native.cmake reads the names of the SHOCKGAS_INSTRUCTION_SET(" entries.
#define SHOCKGAS_INSTRUCTION_SET(name)                     \
  Probe {                                                  \
    name, [] { return __builtin_cpu_supports(name) != 0; } \
  }
const Probe kProbes[] = {
    SHOCKGAS_INSTRUCTION_SET("sse3"),         SHOCKGAS_INSTRUCTION_SET("ssse3"),
    SHOCKGAS_INSTRUCTION_SET("sse4.1"),       SHOCKGAS_INSTRUCTION_SET("sse4.2"),
    SHOCKGAS_INSTRUCTION_SET("sse4a"),        SHOCKGAS_INSTRUCTION_SET("popcnt"),
    SHOCKGAS_INSTRUCTION_SET("bmi"),          SHOCKGAS_INSTRUCTION_SET("bmi2"),
    SHOCKGAS_INSTRUCTION_SET("fma"),          SHOCKGAS_INSTRUCTION_SET("avx"),
    SHOCKGAS_INSTRUCTION_SET("avx2"),         SHOCKGAS_INSTRUCTION_SET("avx512f"),
    SHOCKGAS_INSTRUCTION_SET("avx512cd"),     SHOCKGAS_INSTRUCTION_SET("avx512bw"),
    SHOCKGAS_INSTRUCTION_SET("avx512dq"),     SHOCKGAS_INSTRUCTION_SET("avx512vl"),
    SHOCKGAS_INSTRUCTION_SET("avx512ifma"),   SHOCKGAS_INSTRUCTION_SET("avx512vbmi"),
    SHOCKGAS_INSTRUCTION_SET("avx512vbmi2"),  SHOCKGAS_INSTRUCTION_SET("avx512vnni"),
    SHOCKGAS_INSTRUCTION_SET("avx512bitalg"), SHOCKGAS_INSTRUCTION_SET("avx512vpopcntdq"),
    SHOCKGAS_INSTRUCTION_SET("avx512bf16"),   SHOCKGAS_INSTRUCTION_SET("avx512vp2intersect"),
};
#undef SHOCKGAS_INSTRUCTION_SET
#else
// Elsewhere a build targets the compiler's default: nothing to ask.
const Probe kProbes[] = {{"", [] { return true; }}};
#endif

// Whether this processor has the instruction set named by [name, name + length).
bool has_named(const void*, const char* name, std::size_t length) {
  for (const Probe& p : kProbes)
    if (std::strlen(p.name) == length && std::strncmp(p.name, name, length) == 0) return p.has();
  return false;
}

using Has = bool (*)(const void* context, const char* name, std::size_t length);

// Writes the message for a processor judged by has(context, ...) into out (at
// most size bytes, 0-terminated, cut if need be); returns whether one lacks any.
bool write_message(const char* needed, const char* build_target, Has has, const void* context, char* out,
                   std::size_t size) {
  std::size_t used = 0;
  auto append = [&](const char* text, std::size_t length) {
    const std::size_t n = length < size - 1 - used ? length : size - 1 - used;
    std::memcpy(out + used, text, n);
    used += n;
    out[used] = '\0';
  };
  auto append_text = [&](const char* text) { append(text, std::strlen(text)); };
  out[0] = '\0';
  bool any = false;
  for (const char* word = needed; *word != '\0';) {
    const std::size_t skip = std::strspn(word, " ");
    const std::size_t length = std::strcspn(word + skip, " ");
    if (length > 0 && !has(context, word + skip, length)) {
      if (!any) {
        append_text("shockgas: this build was compiled for ");
        append_text(build_target);
        append_text(" and uses instructions this processor lacks: ");
      } else {
        append_text(", ");
      }
      append(word + skip, length);
      any = true;
    }
    word += skip + length;
  }
  if (any)
    append_text(
        ". Build it on this machine, or build a portable binary or package with cmake "
        "-DSHOCKGAS_NATIVE=OFF (docs/install.md).\n");
  return any;
}

}  // namespace

std::vector<std::string> checkable_instruction_sets() {
  std::vector<std::string> names;
  for (const Probe& p : kProbes)
    if (*p.name != '\0') names.emplace_back(p.name);
  return names;
}

bool processor_has(std::string_view name) { return has_named(nullptr, name.data(), name.size()); }

std::string instruction_set_message(std::string_view needed, std::string_view build_target,
                                    const std::function<bool(std::string_view)>& has) {
  const Has call = [](const void* context, const char* name, std::size_t length) {
    return (*static_cast<const std::function<bool(std::string_view)>*>(context))({name, length});
  };
  std::string out(4096, '\0');
  write_message(std::string(needed).c_str(), std::string(build_target).c_str(), call, &has, out.data(),
                out.size());
  out.resize(std::strlen(out.c_str()));
  return out;
}

}  // namespace shockgas

// Runs before the other initialisers of the program or the Python module
// (priority 101, the first one not reserved), in code compiled for the portable
// target. The link of shockgas_core names it (core/CMakeLists.txt), so that a
// static link keeps it.
extern "C" __attribute__((constructor(101))) void shockgas_check_instruction_sets() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_cpu_init();  // CPUID, before any constructor that would ask has run
#endif
  char message[1024];
  if (!shockgas::write_message(shockgas::kBuildInstructionSets, shockgas::kBuildTarget, shockgas::has_named,
                               nullptr, message, sizeof message))
    return;
  [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, message, std::strlen(message));
  ::_exit(1);
}
