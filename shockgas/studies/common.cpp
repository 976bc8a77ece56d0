// Shared machinery of `shockgas bench`: see common.hpp.
#include "shockgas/studies/common.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <iostream>

#include "shockgas/continuum/godunov.hpp"
#include "shockgas/continuum/hopf_cole.hpp"
#include "shockgas/continuum/hopf_lax.hpp"
#include "shockgas/continuum/pressureless.hpp"
#include "shockgas/continuum/viscous_mol.hpp"
#include "shockgas/core/error.hpp"
#include "shockgas/core/interrupt.hpp"
#include "shockgas/particles/params.hpp"

namespace shockgas::studies {

void Context::log(const std::string& section, const std::string& text) const {
  if (progress) std::cerr << "bench: " << section << ": " << text << std::endl;
}

namespace {

// The failure to write a table at path, with the system's reason (errno,
// cleared before the write).
[[noreturn]] void cannot_write(const std::string& path) {
  throw TableWriteFailed("cannot write " + path + ": " + (errno ? std::strerror(errno) : "write failed"));
}

}  // namespace

std::string Context::path(const std::string& file) const { return out_dir + "/" + file; }

CsvWriter::CsvWriter(const std::string& path, const std::vector<std::string>& columns)
    : out_(path), path_(path), columns_(columns.size()) {
  if (!out_) cannot_write(path);
  for (const auto& c : columns) *this << c;
  end_row();
}

void CsvWriter::separator() {
  if (cells_++ > 0) out_ << ',';
}

CsvWriter& CsvWriter::operator<<(double value) {
  separator();
  if (std::isfinite(value)) out_ << to_text(value);
  return *this;
}

CsvWriter& CsvWriter::operator<<(const std::string& text) {
  separator();
  if (text.find_first_of(",\"\n") == std::string::npos) {
    out_ << text;
    return *this;
  }
  out_ << '"';
  for (char c : text) out_ << (c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c));
  out_ << '"';
  return *this;
}

void CsvWriter::end_row() {
  if (cells_ != columns_)
    throw RunError("bench: " + path_ + ": row of " + std::to_string(cells_) + " cells, header has " +
                   std::to_string(columns_));
  // Each row reaches the file before the next is made (a table is small): a
  // full disk is then met here, in this table's row, with the system's reason.
  errno = 0;
  out_ << '\n' << std::flush;
  cells_ = 0;
  if (!out_) cannot_write(path_);
}

void rethrow_if_bench_failure(const std::exception& e) {
  if (dynamic_cast<const Interrupted*>(&e) || dynamic_cast<const TableWriteFailed*>(&e)) throw;
}

void FailureLog::write(const Context& ctx) const {
  CsvWriter csv(ctx.path("failures.csv"), {"bench_section", "section", "method", "parameter", "what"});
  std::ofstream md(ctx.path("failures.md"));
  md << "# Failures detected by shockgas bench\n\n| section | method | parameter | what happened "
        "|\n|---|---|---|---|\n";
  for (const auto& [bench_section, f] : failures_) {
    csv << bench_section << f.section << f.method << f.parameter << f.what;
    csv.end_row();
    md << "| " << f.section << " | " << f.method << " | " << f.parameter << " | " << f.what << " |\n";
  }
  errno = 0;
  md.flush();
  if (!md) cannot_write(ctx.path("failures.md"));
}

namespace {

// The cells of one line as CsvWriter writes them: quoted where they hold a
// comma or a quote, a quote doubled inside.
std::vector<std::string> csv_cells(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"')
      cells.back() += '"', ++i;
    else if (c == '"')
      quoted = !quoted;
    else if (c == ',' && !quoted)
      cells.emplace_back();
    else
      cells.back() += c;
  }
  return cells;
}

}  // namespace

void FailureLog::keep_earlier(const std::string& path, const std::vector<std::string>& measured) {
  std::ifstream in(path);
  std::string line;
  if (!std::getline(in, line) || csv_cells(line).front() != "bench_section") return;
  while (std::getline(in, line)) {
    const std::vector<std::string> c = csv_cells(line);
    if (c.size() != 5 || std::find(measured.begin(), measured.end(), c[0]) != measured.end()) continue;
    failures_.push_back({c[0], {c[1], c[2], c[3], c[4]}});
  }
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double median_seconds(std::size_t runs, const std::function<void()>& fn) {
  std::vector<double> t;
  for (std::size_t k = 0; k < std::max<std::size_t>(runs, 1); ++k) {
    const auto start = std::chrono::steady_clock::now();
    fn();
    t.push_back(seconds_since(start));
  }
  std::sort(t.begin(), t.end());
  const std::size_t n = t.size();
  return n % 2 ? t[n / 2] : 0.5 * (t[n / 2 - 1] + t[n / 2]);
}

Norms error_norms(const std::vector<double>& a, const std::vector<double>& b, double h) {
  if (a.size() != b.size()) throw RunError("bench: error norms of fields of different sizes");
  Norms n;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double d = std::abs(a[i] - b[i]);
    n.l1 += d * h;
    n.linf = std::max(n.linf, d);
  }
  return n;
}

namespace {

// Signed periodic offset of x from x_s, in (-length/2, length/2].
double offset(double x, double x_s, double length) {
  double d = std::fmod(x - x_s, length);
  if (d > length / 2) d -= length;
  if (d <= -length / 2) d += length;
  return d;
}

// Offset from x_s of the downward crossing of v_mid nearest to x_s; NaN if none.
double crossing(const std::vector<double>& v, double length, double x_s, double v_mid, double half_width) {
  const std::size_t n = v.size();
  const double h = length / static_cast<double>(n);
  double best = NAN;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = v[i], b = v[(i + 1) % n];
    if (!(a >= v_mid && b < v_mid)) continue;
    const double x = (static_cast<double>(i) + 0.5 + (a - v_mid) / (a - b)) * h;
    const double d = offset(x, x_s, length);
    if (std::abs(d) <= half_width && !(std::abs(d) >= std::abs(best))) best = d;
  }
  return best;
}

}  // namespace

double shock_position_error(const std::vector<double>& v, const std::vector<double>& exact, double length,
                            double x_s, double v_mid, double half_width) {
  return std::abs(crossing(v, length, x_s, v_mid, half_width) -
                  crossing(exact, length, x_s, v_mid, half_width));
}

std::string fmt(double value, int digits) { return to_text(value, digits); }

const SolverNames& solver_names() {
  static const SolverNames names{
      continuum::godunov_solver().name,      continuum::godunov2_solver().name,
      continuum::pressureless_solver().name, continuum::hopf_lax_solver().name,
      continuum::hopf_cole_solver().name,    continuum::cvode_solver().name,
      continuum::arkode_solver().name,       name_of(particles::ParticleSolver::events)};
  return names;
}

}  // namespace shockgas::studies
