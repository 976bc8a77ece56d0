#include "shockgas/app/output/declaration.hpp"

#include "shockgas/core/error.hpp"

namespace shockgas::app {

// path with each {placeholder} replaced by the next of `at`.
std::string fill_path(const std::string& path, const std::vector<std::string>& at) {
  std::string out;
  std::size_t next = 0;
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (path[i] != '{') {
      out += path[i];
      continue;
    }
    const std::size_t close = path.find('}', i);
    if (next >= at.size()) throw RunError("output layout: no value for a placeholder of " + path);
    out += at[next++];
    i = close;
  }
  return out;
}

void Emitter::pieces(std::size_t size, const std::function<void(const PutPiece&)>& put,
                     const std::vector<std::string>& at) {
  std::vector<double> data;
  data.reserve(size);
  put([&](const double* p, std::size_t count) { data.insert(data.end(), p, p + count); });
  values(data, at);
}

}  // namespace shockgas::app
