#pragma once
// The bytes of a saved run (private to particles/; run_state.hpp says what is
// saved and why): the engine, the window scheduler and the recorder each write
// their state in a fixed order and read it back in the same order. Nothing is
// recomputed on restore that could differ from the saved run: the pair times
// and every tree's nodes are saved as they are (a tree rebuilt from the times
// may order equal times differently from the refreshes that built it).
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "shockgas/core/error.hpp"
#include "shockgas/particles/run_state.hpp"

namespace shockgas::particles {
class EventTree;
}

namespace shockgas::particles::detail {

template <bool Linked>
class EventEngine;
template <bool Linked>
class WindowScheduler;

template <class T>
void put(RunStateWriter& out, const T& value) {
  static_assert(std::is_trivially_copyable_v<T>);
  out.write(&value, sizeof value);
}
template <class T>
T get(RunStateReader& in) {
  static_assert(std::is_trivially_copyable_v<T>);
  T value;
  in.read(&value, sizeof value);
  return value;
}

// A count of items of `size` bytes each, checked against what is left of the state.
inline std::size_t get_count(RunStateReader& in, std::size_t size, const char* what) {
  const auto n = get<std::uint64_t>(in);
  if (size > 0 && n > in.remaining() / size)
    throw RunError(std::string("a saved run state: ") + what + " of " + std::to_string(n) +
                   " items runs past the end of the state");
  return static_cast<std::size_t>(n);
}

template <class T, class A>
void put_vector(RunStateWriter& out, const std::vector<T, A>& v) {
  static_assert(std::is_trivially_copyable_v<T>);
  put<std::uint64_t>(out, v.size());
  if (!v.empty()) out.write(v.data(), v.size() * sizeof(T));
}
template <class T, class A>
void get_vector(RunStateReader& in, std::vector<T, A>& v, const char* what) {
  v.resize(get_count(in, sizeof(T), what));
  if (!v.empty()) in.read(v.data(), v.size() * sizeof(T));
}
// The same into a vector that already has the size the state must give.
template <class T, class A>
void get_into(RunStateReader& in, std::vector<T, A>& v, const char* what) {
  if (get_count(in, sizeof(T), what) != v.size())
    throw RunError(std::string("a saved run state: ") + what + " does not fit the run it is resumed in");
  if (!v.empty()) in.read(v.data(), v.size() * sizeof(T));
}

inline void put_text(RunStateWriter& out, const std::string& s) {
  put<std::uint64_t>(out, s.size());
  out.write(s.data(), s.size());
}
inline std::string get_text(RunStateReader& in, const char* what) {
  std::string s(get_count(in, 1, what), '\0');
  if (!s.empty()) in.read(s.data(), s.size());
  return s;
}

// A value the state must have (a tag, a size): RunError naming it if not.
template <class T>
void expect(RunStateReader& in, const T& value, const char* what) {
  if (get<T>(in) != value)
    throw RunError(std::string("a saved run state: its ") + what + " differs from the run it is resumed in");
}

// The friend of the engine, the scheduler and the event tree that reads and
// writes their members (state_io.hpp's functions are in run_state_io.hpp).
struct StateIo {
  template <bool Linked>
  static void save(const EventEngine<Linked>& e, RunStateWriter& out);
  template <bool Linked>
  static void restore(EventEngine<Linked>& e, RunStateReader& in);
  template <bool Linked>
  static void save(const WindowScheduler<Linked>& s, RunStateWriter& out);
  template <bool Linked>
  static void restore(WindowScheduler<Linked>& s, RunStateReader& in);
  // A tree's nodes as they are, and its hint.
  static void put_nodes(RunStateWriter& out, const EventTree& t);
  static void get_nodes(RunStateReader& in, EventTree& t);
};

}  // namespace shockgas::particles::detail
