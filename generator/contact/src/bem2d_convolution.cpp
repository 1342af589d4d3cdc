// SPDX-License-Identifier: Apache-2.0
#include "ctab/contact/bem2d_convolution.hpp"

#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <string>

#include "ctab/contact/bem2d_influence.hpp"
#include "ctab/contact/bem2d_options.hpp"
#include "ctab/core/error.hpp"

namespace ctab::gen {

namespace {

using Complex = std::complex<double>;

bool is_5_smooth(std::size_t n) {
  for (const std::size_t f : {2u, 3u, 5u})
    while (n % f == 0) n /= f;
  return n == 1;
}

// Smallest multiple of 4 (kissfft's fast real transform) with factors 2, 3, 5 only, at least `minimum`.
std::size_t padded_size(std::size_t minimum) {
  std::size_t quarter = (minimum + 3) / 4;
  while (!is_5_smooth(quarter)) ++quarter;
  return 4 * quarter;
}

}  // namespace

struct InfluenceConvolution::Impl {
  std::size_t nx = 0, ny = 0;  // element grid
  std::size_t px = 0, py = 0;  // padded grid
  std::size_t hx = 0;          // half spectrum along x: px/2 + 1
  double self = 0.0;
  std::vector<Complex> kernel_spectrum;  // hx columns of py values (column k contiguous)
  std::vector<Complex> spectrum;         // ny rows of hx values (rows j >= ny are zero and not stored)
  std::vector<Complex> column;           // py values
  std::vector<Complex> transformed;      // py values
  std::vector<double> row;               // px values
  std::vector<Complex> row_spectrum;     // hx values
  Eigen::FFT<double> fft;

  Impl(std::size_t nx_, std::size_t ny_, double dx, double dy, double E_star);
  void build_kernel(double dx, double dy, double E_star);
  void forward_rows(const std::vector<double>& p);
  void convolve_columns();
  void inverse_rows(std::vector<double>& u);
};

InfluenceConvolution::Impl::Impl(std::size_t nx_, std::size_t ny_, double dx, double dy, double E_star)
    : nx(nx_), ny(ny_), px(padded_size(2 * nx_ - 1)), py(padded_size(2 * ny_ - 1)), hx(px / 2 + 1) {
  fft.SetFlag(Eigen::FFT<double>::HalfSpectrum);
  kernel_spectrum.assign(hx * py, Complex{});
  spectrum.assign(ny * hx, Complex{});
  column.assign(py, Complex{});
  transformed.assign(py, Complex{});
  row.assign(px, 0.0);
  row_spectrum.assign(hx, Complex{});
  build_kernel(dx, dy, E_star);
}

// Coefficients for offsets |di| < nx, |dj| < ny from Love's primitive on the corner lattice X_k = (k - 1/2) dx,
// k = 0..nx (F is odd in X and in Y, so the coefficient is even in both offsets); laid out circulantly.
void InfluenceConvolution::Impl::build_kernel(double dx, double dy, double E_star) {
  std::vector<double> corner((nx + 1) * (ny + 1));
  for (std::size_t l = 0; l <= ny; ++l)
    for (std::size_t k = 0; k <= nx; ++k)
      corner[l * (nx + 1) + k] =
          love_primitive((static_cast<double>(k) - 0.5) * dx, (static_cast<double>(l) - 0.5) * dy);
  const double scale = 1.0 / (std::numbers::pi * E_star);
  const auto F = [&](std::size_t k, std::size_t l) { return corner[l * (nx + 1) + k]; };
  std::vector<double> padded(px * py, 0.0);
  for (std::size_t dj = 0; dj < ny; ++dj)
    for (std::size_t di = 0; di < nx; ++di) {
      const double a = scale * (F(di + 1, dj + 1) - F(di, dj + 1) - F(di + 1, dj) + F(di, dj));
      const std::size_t ii[2] = {di, (px - di) % px}, jj[2] = {dj, (py - dj) % py};
      for (const std::size_t j : jj)
        for (const std::size_t i : ii) padded[j * px + i] = a;
    }
  self = padded[0];
  // 2-D transform: rows (real to half spectrum), then each half-spectrum column.
  std::vector<Complex> rows(py * hx);
  for (std::size_t j = 0; j < py; ++j) fft.fwd(&rows[j * hx], &padded[j * px], static_cast<Eigen::Index>(px));
  for (std::size_t k = 0; k < hx; ++k) {
    for (std::size_t j = 0; j < py; ++j) column[j] = rows[j * hx + k];
    fft.fwd(&kernel_spectrum[k * py], column.data(), static_cast<Eigen::Index>(py));
  }
}

void InfluenceConvolution::Impl::forward_rows(const std::vector<double>& p) {
  for (std::size_t j = 0; j < ny; ++j) {
    std::copy(p.begin() + static_cast<std::ptrdiff_t>(j * nx), p.begin() + static_cast<std::ptrdiff_t>((j + 1) * nx),
              row.begin());
    std::fill(row.begin() + static_cast<std::ptrdiff_t>(nx), row.end(), 0.0);
    fft.fwd(&spectrum[j * hx], row.data(), static_cast<Eigen::Index>(px));
  }
}

void InfluenceConvolution::Impl::convolve_columns() {
  for (std::size_t k = 0; k < hx; ++k) {
    for (std::size_t j = 0; j < ny; ++j) column[j] = spectrum[j * hx + k];
    std::fill(column.begin() + static_cast<std::ptrdiff_t>(ny), column.end(), Complex{});
    fft.fwd(transformed.data(), column.data(), static_cast<Eigen::Index>(py));
    const Complex* kernel = &kernel_spectrum[k * py];
    for (std::size_t m = 0; m < py; ++m) transformed[m] *= kernel[m];
    fft.inv(column.data(), transformed.data(), static_cast<Eigen::Index>(py));
    for (std::size_t j = 0; j < ny; ++j) spectrum[j * hx + k] = column[j];
  }
}

void InfluenceConvolution::Impl::inverse_rows(std::vector<double>& u) {
  u.resize(nx * ny);
  for (std::size_t j = 0; j < ny; ++j) {
    fft.inv(row.data(), &spectrum[j * hx], static_cast<Eigen::Index>(px));
    std::copy(row.begin(), row.begin() + static_cast<std::ptrdiff_t>(nx),
              u.begin() + static_cast<std::ptrdiff_t>(j * nx));
  }
}

InfluenceConvolution::InfluenceConvolution(std::size_t nx, std::size_t ny, double dx_m, double dy_m, double E_star_Pa) {
  const std::string source = "bem2d grid";
  if (nx == 0 || ny == 0 || nx > kBem2dMaxElementsPerSide || ny > kBem2dMaxElementsPerSide)
    throw InputError(source, 0,
                     "element counts " + std::to_string(nx) + " x " + std::to_string(ny) + " (expected 1.." +
                         std::to_string(kBem2dMaxElementsPerSide) + " per side)");
  if (!(dx_m > 0.0 && std::isfinite(dx_m) && dy_m > 0.0 && std::isfinite(dy_m)))
    throw InputError(source, 0, "element size must be positive and finite [m]");
  if (!(E_star_Pa > 0.0 && std::isfinite(E_star_Pa)))
    throw InputError(source, 0, "combined modulus E* must be positive and finite [Pa]");
  impl_ = std::make_unique<Impl>(nx, ny, dx_m, dy_m, E_star_Pa);
}

InfluenceConvolution::~InfluenceConvolution() = default;
InfluenceConvolution::InfluenceConvolution(InfluenceConvolution&&) noexcept = default;
InfluenceConvolution& InfluenceConvolution::operator=(InfluenceConvolution&&) noexcept = default;

void InfluenceConvolution::apply(const std::vector<double>& pressure_Pa, std::vector<double>& displacement_m) {
  impl_->forward_rows(pressure_Pa);
  impl_->convolve_columns();
  impl_->inverse_rows(displacement_m);
}

double InfluenceConvolution::self_coefficient() const noexcept { return impl_->self; }
std::size_t InfluenceConvolution::nx() const noexcept { return impl_->nx; }
std::size_t InfluenceConvolution::ny() const noexcept { return impl_->ny; }

}  // namespace ctab::gen
