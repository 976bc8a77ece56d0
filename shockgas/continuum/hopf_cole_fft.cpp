// Hopf-Cole: the moving-frame potential, the spectral (FFT) heat solve and the
// velocity from ln theta. See hopf_cole.hpp for the equations and error bound.
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>

#include "shockgas/continuum/fftw_real_transform.hpp"
#include "shockgas/continuum/hopf_cole.hpp"

namespace shockgas::continuum {

double MovingFramePotential::spread() const {
  const auto [lo, hi] = std::minmax_element(psi.begin(), psi.end());
  return *hi - *lo;
}

MovingFramePotential moving_frame_potential(const std::vector<double>& cell_average_v, double length) {
  MovingFramePotential p;
  p.length = length;
  const std::size_t n = cell_average_v.size();
  double sum = 0;
  for (double v : cell_average_v) sum += v;
  p.mean_velocity = sum / static_cast<double>(n);
  const double h = length / static_cast<double>(n);
  p.psi.resize(n);
  double psi = 0;
  for (std::size_t j = 0; j < n; ++j) {
    p.psi[j] = psi;
    psi += h * (cell_average_v[j] - p.mean_velocity);
  }
  return p;
}

namespace {

// Multiplies the half spectrum of theta0 by the heat propagator exp(-nu kappa^2 t),
// the shift phase exp(-i kappa shift) and the 1/n of FFTW's unnormalised pair.
void propagate(std::span<std::complex<double>> c, std::size_t n, double length, double nu, double t,
               double shift) {
  const double base = 2.0 * std::numbers::pi / length;
  for (std::size_t k = 0; k < c.size(); ++k) {
    const double kappa = base * static_cast<double>(k);
    const double damp = std::exp(-nu * kappa * kappa * t) / static_cast<double>(n);
    if (2 * k == n)  // Nyquist mode: real cosine, its shifted form is c cos(kappa shift)
      c[k] = c[k].real() * damp * std::cos(kappa * shift);
    else
      c[k] *= damp * std::polar(1.0, -kappa * shift);
  }
}

}  // namespace

LogTheta log_theta_fft(const MovingFramePotential& psi0, double nu, double t, double shift) {
  const std::size_t n = psi0.psi.size();
  RealFft fft(n);
  auto theta = fft.real();
  const double psi_min = *std::min_element(psi0.psi.begin(), psi0.psi.end());
  for (std::size_t j = 0; j < n; ++j) theta[j] = std::exp(-(psi0.psi[j] - psi_min) / (2 * nu));  // max 1
  fft.forward();
  propagate(fft.spectrum(), n, psi0.length, nu, t, shift);
  fft.backward();

  // Absolute error of theta ~ eps log2(n) max theta0 (max theta0 = 1): relative error
  // e_j = floor / theta_j, so the cell-average v error is <= 2 nu (e_j + e_{j+1}) / h.
  const double floor = std::numeric_limits<double>::epsilon() * (1.0 + std::log2(static_cast<double>(n)));
  LogTheta out;
  out.values.resize(n);
  std::vector<double> rel(n);
  for (std::size_t j = 0; j < n; ++j) {
    const bool ok = std::isfinite(theta[j]) && theta[j] > 0;
    out.values[j] = ok ? std::log(theta[j]) : std::numeric_limits<double>::quiet_NaN();
    rel[j] = ok ? floor / theta[j] : std::numeric_limits<double>::infinity();
  }
  double worst = 0;
  for (std::size_t j = 0; j < n; ++j) worst = std::max(worst, rel[j] + rel[(j + 1) % n]);
  out.velocity_error_bound = 2 * nu * worst / psi0.spacing();
  return out;
}

std::vector<double> velocity_from_log_theta(const MovingFramePotential& psi0,
                                            const std::vector<double>& log_theta, double nu) {
  const std::size_t n = log_theta.size();
  const double h = psi0.spacing();
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i)
    v[i] = psi0.mean_velocity - 2 * nu * (log_theta[(i + 1) % n] - log_theta[i]) / h;
  return v;
}

}  // namespace shockgas::continuum
