// The writers, the lookup and the documentation of the declared output layout.
#include "shockgas/app/output/output_layout.hpp"

#include <sstream>
#include <string_view>

#include "shockgas/app/files/durable_file.hpp"
#include "shockgas/app/files/fault.hpp"
#include "shockgas/app/output/layout_declarations.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/core/interrupt.hpp"

namespace shockgas::app {

namespace {

class FileEmitter : public Emitter {
 public:
  FileEmitter(Hdf5File& h5, const LayoutEntry& e) : h5_(h5), e_(e) {}
  void values(const std::vector<double>& data, const std::vector<std::string>& at) override {
    h5_.write(fill_path(e_.path, at), data.data(), {data.size()}, e_.storage, e_.unit, e_.description);
  }
  void pieces(std::size_t size, const std::function<void(const PutPiece&)>& put,
              const std::vector<std::string>& at) override {
    Hdf5File::Writer w = h5_.start(fill_path(e_.path, at), size, e_.storage, e_.unit, e_.description);
    put([&](const double* p, std::size_t count) { w.append(p, count); });
    w.finish();
  }
  void matrix(const std::vector<double>& data, std::size_t rows, std::size_t cols,
              const std::vector<std::string>& at) override {
    const std::string path = fill_path(e_.path, at);
    if (data.size() != rows * cols) throw RunError("HDF5: matrix " + path + " has the wrong size");
    h5_.write(path, data.data(), {rows, cols}, e_.storage, e_.unit, e_.description);
  }
  void text(const std::string& value, const std::vector<std::string>& at) override {
    const auto [object, name] = split(fill_path(e_.path, at));
    h5_.set_attribute(object, name, value);
  }
  void number(double value, const std::vector<std::string>& at) override {
    const auto [object, name] = split(fill_path(e_.path, at));
    h5_.set_attribute(object, name, value);
  }
  void json(const nlohmann::ordered_json&, const std::vector<std::string>&) override {
    throw RunError("output layout: " + e_.path + " is a dataset or attribute, not a summary key");
  }

 private:
  static std::pair<std::string, std::string> split(const std::string& path) {
    const auto at = path.find('@');
    return {path.substr(0, at), path.substr(at + 1)};
  }
  Hdf5File& h5_;
  const LayoutEntry& e_;
};

class SummaryEmitter : public Emitter {
 public:
  SummaryEmitter(nlohmann::ordered_json& summary, const LayoutEntry& e) : summary_(summary), e_(e) {}
  void json(const nlohmann::ordered_json& value, const std::vector<std::string>& at) override {
    nlohmann::ordered_json* node = &summary_;
    std::stringstream key(fill_path(e_.path, at));
    for (std::string part; std::getline(key, part, '.');) node = &(*node)[part];
    *node = value;
  }
  void values(const std::vector<double>& d, const std::vector<std::string>& at) override { json(d, at); }
  void matrix(const std::vector<double>& d, std::size_t, std::size_t,
              const std::vector<std::string>& at) override {
    json(d, at);
  }
  void text(const std::string& v, const std::vector<std::string>& at) override { json(v, at); }
  void number(double v, const std::vector<std::string>& at) override { json(v, at); }

 private:
  nlohmann::ordered_json& summary_;
  const LayoutEntry& e_;
};

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, sep);) parts.push_back(part);
  return parts;
}

// Whether `concrete` is `pattern` with each {placeholder} standing for one segment.
bool matches(const std::string& pattern, const std::string& concrete, char sep) {
  const auto p = split(pattern, sep), c = split(concrete, sep);
  if (p.size() != c.size()) return false;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p[i] != c[i] && !(p[i].size() > 2 && p[i].front() == '{' && p[i].back() == '}' && !c[i].empty()))
      return false;
  return true;
}

// "object@name": the objects match as paths, the names exactly.
bool matches_attribute(const std::string& pattern, const std::string& concrete) {
  const auto p = pattern.find('@'), c = concrete.find('@');
  if (p == std::string::npos || c == std::string::npos || pattern.substr(p) != concrete.substr(c))
    return false;
  return matches(pattern.substr(0, p), concrete.substr(0, c), '/');
}

// "~ {analysis.t_stick_theory}" -> "~ `analysis.t_stick_theory`".
std::string theory_markdown(std::string text) {
  for (char& c : text)
    if (c == '{' || c == '}') c = '`';
  return text;
}

// "; theory: -2/3 (sticky gas) where theory.sticky_cooling holds; ..."
std::string theories_markdown(const std::vector<Theory>& theories) {
  std::string out;
  for (const Theory& t : theories)
    out += "; " + (t.law.empty()
                       ? "exact: " + theory_markdown(t.value)
                       : "theory: " + theory_markdown(t.value) + " where `theory." + t.law + "` holds");
  return out;
}

std::string cell(const std::string& text) {
  std::string out;
  for (char c : text)
    out += c == '|' ? std::string("\\|") : c == '<' ? std::string("&lt;") : std::string(1, c);
  return out;
}

// The type column: a dataset's storage, an attribute's kind (text or float64).
std::string type_cell(const LayoutEntry& e) {
  if (e.kind == LayoutEntry::Kind::dataset) return storage_name(e.storage);
  return e.unit.empty() ? "text" : "float64";
}

void table(std::ostringstream& out, const std::vector<Declaration>& decls, Part part, const char* head) {
  bool any = false;
  const bool typed = decls.empty() || decls.front().entry.kind != LayoutEntry::Kind::summary;
  for (const auto& d : decls) {
    const LayoutEntry& e = d.entry;
    if (e.part != part) continue;
    if (!any)
      out << "\n### " << part_title(part) << "\n\n| " << head << " | unit" << (typed ? " | type" : "")
          << " | meaning |\n|---|---|" << (typed ? "---|" : "") << "---|\n";
    any = true;
    std::string meaning = e.description;
    if (!e.when.empty()) meaning += " (" + e.when + ")";
    meaning += theories_markdown(e.theory);
    out << "| `" << e.path << "` | " << (e.unit.empty() ? "" : cell(e.unit)) << " | "
        << (typed ? type_cell(e) + " | " : "") << cell(meaning) << " |\n";
  }
}

const std::vector<Part> kParts = {Part::provenance, Part::initial, Part::particles, Part::analysis,
                                  Part::continuum,  Part::compare, Part::animation, Part::theory,
                                  Part::sweep,      Part::shard};

}  // namespace

const std::vector<Declaration>& dataset_declarations() {
  static const std::vector<Declaration> all = [] {
    std::vector<Declaration> d = layout::provenance_datasets();
    layout::append(d, layout::particle_datasets());
    layout::append(d, layout::realization_datasets());
    layout::append(d, layout::field_datasets());
    layout::append(d, layout::frame_datasets());
    layout::append(d, layout::shard_datasets());
    return d;
  }();
  return all;
}

const std::vector<Declaration>& summary_declarations() {
  static const std::vector<Declaration> all = [] {
    std::vector<Declaration> d = layout::run_keys();
    layout::append(d, layout::theory_keys());
    layout::append(d, layout::realization_error_keys());
    layout::append(d, layout::comparison_keys());
    layout::append(d, layout::extreme_keys());
    layout::append(d, layout::frame_keys());
    layout::append(d, layout::shard_keys());
    return d;
  }();
  return all;
}

std::vector<LayoutEntry> output_layout() {
  std::vector<LayoutEntry> all;
  for (const auto& d : dataset_declarations()) all.push_back(d.entry);
  for (const auto& d : summary_declarations()) all.push_back(d.entry);
  return all;
}

void write_part(Hdf5File& h5, const RunResults& r, Part part) {
  for (const auto& d : dataset_declarations())
    if (d.entry.part == part) {
      fault_point("write:result.h5");
      throw_if_aborted();
      FileEmitter out(h5, d.entry);
      try {
        d.emit(r, out);
      } catch (const RunError& e) {  // the library names the dataset; the message names the file too
        if (std::string_view(e.what()).starts_with("HDF5: "))
          throw RunError(write_failure(h5.path(), e.what()));
        throw;
      }
    }
}

void summarize_part(nlohmann::ordered_json& summary, const RunResults& r, Part part) {
  for (const auto& d : summary_declarations())
    if (d.entry.part == part) {
      SummaryEmitter out(summary, d.entry);
      d.emit(r, out);
    }
}

const LayoutEntry* find_in_layout(LayoutEntry::Kind kind, const std::string& concrete) {
  const auto& decls = kind == LayoutEntry::Kind::summary ? summary_declarations() : dataset_declarations();
  for (const auto& d : decls) {
    if (d.entry.kind != kind) continue;
    if (kind == LayoutEntry::Kind::summary   ? matches(d.entry.path, concrete, '.')
        : kind == LayoutEntry::Kind::dataset ? matches(d.entry.path, concrete, '/')
                                             : matches_attribute(d.entry.path, concrete))
      return &d.entry;
  }
  return nullptr;
}

std::string part_title(Part part) {
  switch (part) {
    case Part::provenance:
      return "Provenance";
    case Part::initial:
      return "The initial condition";
    case Part::particles:
      return "Particles (when [particles] is present)";
    case Part::analysis:
      return "The particles' cooling law and velocity distribution";
    case Part::continuum:
      return "Continuum (one group per solver of continuum.solvers)";
    case Part::compare:
      return "Particles against continuum (when [compare] and [continuum] are present)";
    case Part::animation:
      return "Frames and the wave's evolution (when output.animation = true)";
    case Part::theory:
      return "Where each law holds for the run (written last: to the time its data end)";
    case Part::sweep:
      return "Sweep (a [sweep] scene's own result)";
    case Part::shard:
      return "Shard (a slice of a run for `shockgas merge`: docs/cluster.md)";
  }
  return "";
}

std::string output_layout_markdown() {
  std::ostringstream out;
  out << "\n## result.h5: datasets and attributes\n\nAttributes are written `object@name`. "
         "`{solver}` stands for a solver's name, `{k}` for an index.\n";
  for (Part part : kParts) table(out, dataset_declarations(), part, "dataset or attribute");
  out << "\n## summary.json\n\nKeys are dotted paths into the JSON object.\n";
  for (Part part : kParts) table(out, summary_declarations(), part, "key");
  return out.str();
}

}  // namespace shockgas::app
