#pragma once
// The one wrapper of FFTW3 in shockgas: a real-to-complex / complex-to-real
// transform pair of size n with its own aligned buffers and plans (RAII).
//
// Contract (FFTW3 manual, "One-Dimensional DFTs of Real Data"):
//   forward():  spectrum[k] = sum_j real[j] exp(-2 pi i j k / n),  k = 0..n/2
//   backward(): real[j]     = sum_k spectrum[k] exp(+2 pi i j k / n) over the full
//               Hermitian spectrum, unnormalised (forward then backward multiplies by n).
// backward() destroys the spectrum (FFTW's c2r overwrites its input).
// Plans are made with FFTW_ESTIMATE, so the buffers are not touched while
// planning and results do not depend on timing; the planner is serialised by a
// mutex (FFTW's planner is not thread-safe; executing plans is).
#include <complex>
#include <cstddef>
#include <span>

struct fftw_plan_s;  // FFTW's opaque plan type (fftw3.h: typedef struct fftw_plan_s* fftw_plan)

namespace shockgas::continuum {

class RealFft {
 public:
  // n >= 1 real samples. Throws RunError naming the FFTW call if allocation or planning fails.
  explicit RealFft(std::size_t n);
  ~RealFft();
  RealFft(const RealFft&) = delete;
  RealFft& operator=(const RealFft&) = delete;

  std::size_t size() const { return n_; }
  std::span<double> real() { return {real_, n_}; }
  std::span<std::complex<double>> spectrum() { return {spectrum_, n_ / 2 + 1}; }

  void forward();   // real() -> spectrum()
  void backward();  // spectrum() -> real(), unnormalised; destroys spectrum()

 private:
  void release();  // frees plans and buffers; safe on a partly built object

  std::size_t n_;
  double* real_ = nullptr;
  std::complex<double>* spectrum_ = nullptr;
  fftw_plan_s* forward_plan_ = nullptr;
  fftw_plan_s* backward_plan_ = nullptr;
};

}  // namespace shockgas::continuum
