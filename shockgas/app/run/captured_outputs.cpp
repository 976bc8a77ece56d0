// The outputs of a run in memory: captured from the declarations as the
// writers emit them, or read back from the files of a finished run.
#include "shockgas/app/run/captured_outputs.hpp"

#include <charconv>
#include <filesystem>
#include <fstream>

#include "shockgas/app/output/hdf5_file.hpp"
#include "shockgas/app/output/result_reader.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::app {

namespace fs = std::filesystem;

namespace {

class CaptureEmitter : public Emitter {
 public:
  CaptureEmitter(CapturedOutputs& out, const LayoutEntry& e) : out_(out), e_(e) {}
  void values(const std::vector<double>& data, const std::vector<std::string>& at) override {
    out_.datasets[fill_path(e_.path, at)] = {data, {data.size()}, e_.unit, e_.description, e_.storage};
  }
  void matrix(const std::vector<double>& data, std::size_t rows, std::size_t cols,
              const std::vector<std::string>& at) override {
    if (data.size() != rows * cols)
      throw RunError("output layout: matrix " + e_.path + " has the wrong size");
    out_.datasets[fill_path(e_.path, at)] = {data, {rows, cols}, e_.unit, e_.description, e_.storage};
  }
  void text(const std::string& value, const std::vector<std::string>& at) override {
    out_.attributes[fill_path(e_.path, at)] = value;
  }
  void number(double value, const std::vector<std::string>& at) override {
    out_.attributes[fill_path(e_.path, at)] = value;
  }
  void json(const nlohmann::ordered_json&, const std::vector<std::string>&) override {
    throw RunError("output layout: " + e_.path + " is a dataset or attribute, not a summary key");
  }

 private:
  CapturedOutputs& out_;
  const LayoutEntry& e_;
};

// An attribute as written: a number if its declaration has a unit (text has
// none), parsed from its shortest round-trip text; else the text.
std::variant<std::string, double> attribute_value(const std::string& concrete, const std::string& text) {
  const LayoutEntry* e = find_in_layout(LayoutEntry::Kind::attribute, concrete);
  if (!e || e->unit.empty()) return text;
  double value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size()) return text;
  return value;
}

fs::path result_file(const std::string& path) {
  const fs::path p(path);
  return fs::is_directory(p) ? p / "result.h5" : p;
}

nlohmann::ordered_json read_summary(const fs::path& h5) {
  std::ifstream in(h5.parent_path() / "summary.json");
  if (!in) return nlohmann::ordered_json::object();
  try {
    return nlohmann::ordered_json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(
        "summary.json", to_text((h5.parent_path() / "summary.json").string()),
        "valid JSON, as a run writes it (a syntax error at byte " + std::to_string(e.byte) + ")");
  } catch (const nlohmann::json::exception&) {
    throw InputError("summary.json", to_text((h5.parent_path() / "summary.json").string()),
                     "valid JSON, as a run writes it");
  }
}

}  // namespace

PartSink capture_into(CapturedOutputs& out) {
  return [&out](const RunResults& r, Part part) {
    for (const auto& d : dataset_declarations())
      if (d.entry.part == part) {
        CaptureEmitter emitter(out, d.entry);
        d.emit(r, emitter);
      }
    summarize_part(out.summary, r, part);
  };
}

CapturedOutputs read_outputs(const std::string& path) {
  const fs::path h5_path = result_file(path);
  if (!fs::is_regular_file(h5_path))
    throw InputError("RESULT.h5", to_text(h5_path.string()), "an existing shockgas result file (HDF5)");
  ResultContents file = read_result(h5_path, [](const std::string&) { return true; });
  CapturedOutputs out;
  for (const DatasetInfo& d : file.datasets)
    out.datasets[d.path] = {std::move(file.values[d.path]),
                            {d.shape.begin(), d.shape.end()},
                            d.unit,
                            d.description,
                            d.type == "float32" ? Storage::float32
                            : d.type == "int64" ? Storage::integer
                                                : Storage::float64};
  for (const std::string& group : file.groups)
    for (const auto& [name, text] : file.attributes_of(group)) {
      if (group == "/" && name == Hdf5File::kAttributesDigest)
        continue;  // the file's check, checked on reading
      const std::string concrete = group + "@" + name;
      out.attributes[concrete] = attribute_value(concrete, text);
    }
  out.summary = read_summary(h5_path);
  return out;
}

}  // namespace shockgas::app
