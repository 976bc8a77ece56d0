#pragma once
// The version of the layout of result.h5 (docs/output.md, "Layout version"):
// major.minor, written as the file's attribute /@layout_version. A minor
// version adds datasets or attributes a reader of the same major may ignore;
// a major version changes what a path holds, its type or its place (3.0:
// /particles/n_clusters counts the clusters of two or more particles; 4.0: of
// at least particles.min_cluster_particles). A file
// without the attribute is of layout 1.0 (written before it was versioned).
// Every reader (Hdf5File::open: info, merge, animate, the report, the Python
// load) reads every layout of its major and below, and refuses a newer major.
#include <optional>
#include <string>

namespace shockgas::app {

struct LayoutVersion {
  int major = 1, minor = 0;
};

// The layout this build writes.
inline constexpr LayoutVersion kLayoutVersion{4, 0};

// "3.0".
std::string layout_version_text(LayoutVersion v = kLayoutVersion);

// The version an attribute's text names (no attribute = 1.0, before
// versioning); FileProblem for a text that is not major.minor ("" included).
LayoutVersion parse_layout_version(const std::string& file, const std::optional<std::string>& text);

// FileProblem (exit 2) "written in layout 5.0; this shockgas reads layouts
// 1.0 to 4.x" when the file's major is newer than kLayoutVersion's.
void check_layout_version(const std::string& file, const std::optional<std::string>& text);

}  // namespace shockgas::app
