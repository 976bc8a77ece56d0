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

// What a file carries besides its datasets, as its reader found it.
struct LayoutMarks {
  bool own_checksum = false;       // its SHA-256 in its first 512 bytes, verified (own_checksum.hpp)
  bool attributes_digest = false;  // /@attributes_sha256
  bool shockgas_version = false;   // /@shockgas_version, which every layout's writer stores
};

// The layouts since which a file carries its own checksum (2.0) and the digest
// of its attributes (3.1); docs/output.md, "Layout version".
inline constexpr LayoutVersion kOwnChecksumSince{2, 0}, kAttributesDigestSince{3, 1};

// FileProblem (exit 2) for a file that lacks what every file of its layout
// carries: "not a result file" without /@shockgas_version (no writer of any
// layout leaves it out), "damaged" without the own checksum or the attributes'
// digest its layout has (rewritten by another program, or its checksum block
// lost to damage: a file that only says an older layout is read as one).
void check_layout_marks(const std::string& file, LayoutVersion v, const LayoutMarks& marks);

}  // namespace shockgas::app
