#pragma once
// A file given to shockgas that is not what it should be (a scene that is a
// directory or not TOML, a result file that is damaged): an InputError (exit 2)
// whose message is the place, the problem and the detail, e.g.
//   "out/a/result.h5: truncated: 81920 of the 1146880 bytes ... recorded".
#include <string>

#include "shockgas/core/error.hpp"

namespace shockgas::app {

class FileProblem : public InputError {
 public:
  // where: the path, or "path:line:column"; key: what the file was given as
  // ("RESULT", "SCENE"); problem: a few words ("no such file", "damaged").
  FileProblem(const std::string& key, const std::string& where, const std::string& problem,
              const std::string& detail)
      : InputError(key, to_text(where), problem, where,
                   Message{where + ": " + problem + (detail.empty() ? "" : ": " + detail)}),
        detail_(detail) {}
  const std::string& problem() const { return allowed(); }
  const std::string& detail() const { return detail_; }

 private:
  std::string detail_;
};

}  // namespace shockgas::app
