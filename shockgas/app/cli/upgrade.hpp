#pragma once
// `shockgas upgrade RESULT`: there is nothing to rewrite (docs/output.md,
// "Layout version"). Every layout of this build's major and below is read as
// it is; a file rewritten in the current layout would carry checksums taken
// now, vouching for bytes nobody can check any more. The command checks the
// result as `info` does and says so: the layout it holds, that this build reads
// it, and how to have the current layout (run its scene again).
#include <string>

namespace shockgas::app {

// The answer for a result file or run directory; FileProblem (exit 2) for one
// that is damaged, of a newer major layout, or not a result.
std::string upgrade_answer(const std::string& path);

}  // namespace shockgas::app
