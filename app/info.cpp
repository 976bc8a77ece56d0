#include "shockgas/app/info.hpp"

#include <sstream>

#include "hdf5_file.hpp"
#include "output_layout.hpp"

namespace shockgas::app {

namespace {

std::string shape_text(const std::vector<std::uint64_t>& shape) {
  std::string s = "(";
  for (std::size_t i = 0; i < shape.size(); ++i) s += (i ? ", " : "") + std::to_string(shape[i]);
  return s + (shape.size() == 1 ? ",)" : ")");
}

}  // namespace

std::string describe_result(const std::string& path) {
  const Hdf5File file = Hdf5File::open(path);
  std::ostringstream out;
  out << path << "\n\nprovenance:\n";
  std::string scene_text, resolved;
  for (const auto& [name, value] : file.attributes("/")) {
    if (name == "scene_text")
      scene_text = value;
    else if (name == "resolved_parameters")
      resolved = value;
    else
      out << "  " << name << ": " << value << "\n";
  }
  out << "\ndatasets (docs/output.md explains each):\n";
  for (const auto& d : file.datasets()) {
    out << "  " << d.path << "  " << d.type << " " << shape_text(d.shape);
    if (!d.unit.empty()) out << "  [" << d.unit << "]";
    if (!d.description.empty()) out << "  " << d.description;
    if (!find_in_layout(LayoutEntry::Kind::dataset, d.path)) out << "  (not in this version's layout)";
    out << "\n";
  }
  out << "\nscene (as given):\n" << scene_text << "\n";
  if (!resolved.empty()) out << "resolved parameters:\n" << resolved;
  return out.str();
}

std::string describe_layout() { return output_layout_markdown(); }

}  // namespace shockgas::app
