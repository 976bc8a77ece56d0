#include "shockgas/continuum/fftw_real_transform.hpp"

#include <fftw3.h>

#include <mutex>
#include <string>

#include "shockgas/core/error.hpp"

namespace shockgas::continuum {

namespace {

std::mutex& planner_mutex() {
  static std::mutex m;
  return m;
}

template <class T>
T* checked(T* p, const char* call, std::size_t n) {
  if (p == nullptr) throw RunError(std::string("FFTW: ") + call + " failed for n = " + std::to_string(n));
  return p;
}

}  // namespace

RealFft::RealFft(std::size_t n) : n_(n) {
  if (n == 0) throw RunError("FFTW: transform size must be >= 1");
  try {
    real_ = checked(fftw_alloc_real(n), "fftw_alloc_real", n);
    spectrum_ = reinterpret_cast<std::complex<double>*>(
        checked(fftw_alloc_complex(n / 2 + 1), "fftw_alloc_complex", n));
    auto* c = reinterpret_cast<fftw_complex*>(spectrum_);
    const int size = static_cast<int>(n);
    std::lock_guard<std::mutex> lock(planner_mutex());
    forward_plan_ = checked(fftw_plan_dft_r2c_1d(size, real_, c, FFTW_ESTIMATE), "fftw_plan_dft_r2c_1d", n);
    backward_plan_ = checked(fftw_plan_dft_c2r_1d(size, c, real_, FFTW_ESTIMATE), "fftw_plan_dft_c2r_1d", n);
  } catch (...) {
    release();
    throw;
  }
}

RealFft::~RealFft() { release(); }

void RealFft::release() {
  {
    std::lock_guard<std::mutex> lock(planner_mutex());  // fftw_destroy_plan touches planner state
    if (forward_plan_) fftw_destroy_plan(forward_plan_);
    if (backward_plan_) fftw_destroy_plan(backward_plan_);
  }
  forward_plan_ = backward_plan_ = nullptr;
  if (real_) fftw_free(real_);
  if (spectrum_) fftw_free(spectrum_);
  real_ = nullptr;
  spectrum_ = nullptr;
}

void RealFft::forward() { fftw_execute(forward_plan_); }
void RealFft::backward() { fftw_execute(backward_plan_); }

}  // namespace shockgas::continuum
