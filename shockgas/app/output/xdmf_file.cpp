#include "shockgas/app/output/xdmf_file.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <sstream>
#include <vector>

#include "shockgas/app/files/durable_file.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace {

namespace fs = std::filesystem;

struct Shape {
  std::vector<std::uint64_t> dims;
  std::string type;  // "float64", "float32", "int64"
};

// XDMF's NumberType and Precision of a dataset's type.
std::string number_type(const std::string& type) {
  if (type == "float32") return "NumberType=\"Float\" Precision=\"4\"";
  if (type == "int64") return "NumberType=\"Int\" Precision=\"8\"";
  return "NumberType=\"Float\" Precision=\"8\"";
}

std::string dims_text(const std::vector<std::uint64_t>& dims) {
  std::string s;
  for (auto d : dims) s += (s.empty() ? "" : " ") + std::to_string(d);
  return s;
}

class Writer {
 public:
  Writer(const ResultContents& h5, std::string h5_name) : h5_(h5), name_(std::move(h5_name)) {
    for (const DatasetInfo& d : h5.datasets) sets_[d.path] = {d.shape, d.type};
  }

  std::string text() {
    out_ << "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n<Xdmf "
            "Version=\"3.0\">\n<Domain>\n";
    for (const std::string& solver : solvers()) continuum(solver);
    particles();
    out_ << "</Domain>\n</Xdmf>\n";
    return out_.str();
  }

 private:
  bool has(const std::string& path) const { return sets_.count(path) > 0; }

  std::string attribute(const std::string& object, const std::string& name) const {
    return h5_.attribute(object, name);
  }

  // The solvers with fields at t_end, or frames of the animation.
  std::vector<std::string> solvers() const {
    std::vector<std::string> names;
    for (const auto& [path, shape] : sets_)
      for (const std::string prefix : {"/continuum/", "/animation/fields/"})
        if (path.rfind(prefix, 0) == 0 && path.size() > prefix.size() + 2 &&
            path.substr(path.size() - 2) == "/v") {
          const std::string name = path.substr(prefix.size(), path.size() - prefix.size() - 2);
          if (name.find('/') == std::string::npos &&
              std::find(names.begin(), names.end(), name) == names.end())
            names.push_back(name);
        }
    return names;
  }

  // A DataItem reading the whole dataset.
  void item(const std::string& path, const std::string& indent) {
    const Shape& s = sets_.at(path);
    out_ << indent << "<DataItem Dimensions=\"" << dims_text(s.dims) << "\" " << number_type(s.type)
         << " Format=\"HDF\">" << name_ << ":" << path << "</DataItem>\n";
  }

  // A DataItem reading row `row` of a rows x cols dataset (a HyperSlab: start, stride, count).
  void row_item(const std::string& path, std::uint64_t row, const std::string& indent) {
    const Shape& s = sets_.at(path);
    const std::uint64_t cols = s.dims.at(1);
    out_ << indent << "<DataItem ItemType=\"HyperSlab\" Dimensions=\"" << cols << "\" Type=\"HyperSlab\">\n"
         << indent << "  <DataItem Dimensions=\"3 2\" Format=\"XML\">" << row << " 0 1 1 1 " << cols
         << "</DataItem>\n";
    item(path, indent + "  ");
    out_ << indent << "</DataItem>\n";
  }

  // One grid of a solver's fields at time t: x from x_path, each field a whole
  // dataset or (row >= 0) one row of a matrix.
  void field_grid(const std::string& solver, const std::string& t, const std::string& x_path,
                  const std::map<std::string, std::string>& fields, long row) {
    const std::uint64_t n = sets_.at(x_path).dims.at(0);
    out_ << "    <Grid Name=\"" << solver << "\" GridType=\"Uniform\">\n      <Time Value=\"" << t << "\"/>\n"
         << "      <Topology TopologyType=\"2DRectMesh\" Dimensions=\"1 " << n << "\"/>\n"
         << "      <Geometry GeometryType=\"VXVY\">\n";
    item(x_path, "        ");
    out_ << "        <DataItem Dimensions=\"1\" NumberType=\"Float\" Precision=\"8\" "
            "Format=\"XML\">0</DataItem>\n"
         << "      </Geometry>\n";
    for (const auto& [field, path] : fields) {
      out_ << "      <Attribute Name=\"" << field << "\" AttributeType=\"Scalar\" Center=\"Node\">\n";
      if (row >= 0)
        row_item(path, static_cast<std::uint64_t>(row), "        ");
      else
        item(path, "        ");
      out_ << "      </Attribute>\n";
    }
    out_ << "    </Grid>\n";
  }

  // The animation's frames, then the fields at t_end: a frame at t_end itself
  // is left out (one grid per time; the fields at t_end are on the solver's
  // own cells, a frame may be coarser).
  void continuum(const std::string& solver) {
    out_ << "  <Grid Name=\"continuum " << solver
         << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    const std::string at_end = "/continuum/" + solver;
    const bool fields_at_end = has(at_end + "/x") && has(at_end + "/v");
    const std::string frames = "/animation/fields/" + solver;
    if (has(frames + "/x") && has("/animation/t")) {
      const std::vector<double>& t = h5_.values.at("/animation/t");
      std::map<std::string, std::string> fields;
      for (const char* f : {"v", "rho"})
        if (has(frames + "/" + f) && sets_.at(frames + "/" + f).dims.size() == 2)
          fields[f] = frames + "/" + f;
      const std::string t_end = fields_at_end ? attribute(at_end, "t") : "";
      for (std::size_t k = 0; k < t.size(); ++k)
        if (to_text(t[k]) != t_end)
          field_grid(solver, to_text(t[k]), frames + "/x", fields, static_cast<long>(k));
    }
    if (fields_at_end) {
      std::map<std::string, std::string> fields;
      for (const char* f : {"v", "rho"})
        if (has(at_end + "/" + f)) fields[f] = at_end + "/" + f;
      field_grid(solver, attribute(at_end, "t"), at_end + "/x", fields, -1);
    }
    out_ << "  </Grid>\n";
  }

  // A state's bodies as points (x, v, m) with the attributes v and m.
  void state_grid(const std::string& group, const std::string& t) {
    const std::uint64_t n = sets_.at(group + "/x").dims.at(0);
    out_ << "    <Grid Name=\"particles\" GridType=\"Uniform\">\n      <Time Value=\"" << t << "\"/>\n"
         << "      <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n
         << "\" NodesPerElement=\"1\"/>\n"
         << "      <Geometry GeometryType=\"X_Y_Z\">\n";
    for (const char* column : {"x", "v", "m"}) item(group + "/" + column, "        ");
    out_ << "      </Geometry>\n";
    for (const char* column : {"v", "m"}) {
      out_ << "      <Attribute Name=\"" << column << "\" AttributeType=\"Scalar\" Center=\"Node\">\n";
      item(group + "/" + column, "        ");
      out_ << "      </Attribute>\n";
    }
    out_ << "    </Grid>\n";
  }

  void particles() {
    std::vector<std::pair<std::string, std::string>> states;  // group, time
    if (has("/initial/x")) states.push_back({"/initial", "0"});
    for (int k = 0; has("/particles/snapshots/" + std::to_string(k) + "/x"); ++k)
      states.push_back({"/particles/snapshots/" + std::to_string(k),
                        attribute("/particles/snapshots/" + std::to_string(k), "t")});
    if (has("/particles/final/x"))
      states.push_back({"/particles/final", attribute("/particles", "stop_time")});
    if (states.empty()) return;
    out_ << "  <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (const auto& [group, t] : states) state_grid(group, t);
    out_ << "  </Grid>\n";
  }

  const ResultContents& h5_;
  std::string name_;
  std::map<std::string, Shape> sets_;
  std::ostringstream out_;
};

}  // namespace

std::string xdmf_text(const ResultContents& h5, const std::string& h5_name) {
  return Writer(h5, h5_name).text();
}

void write_xdmf(const std::string& dir, const ResultContents& h5) {
  write_file(fs::path(dir) / "result.xdmf", xdmf_text(h5, "result.h5"));
}

}  // namespace shockgas::app
