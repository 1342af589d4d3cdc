// SPDX-License-Identifier: Apache-2.0
#pragma once
//! The bem2d matrix-vector product u = A p on an nx x ny element grid by FFT: the coefficients for every offset
//! (-(n-1) .. n-1 in each direction) are laid out circulantly on a zero-padded grid of at least (2nx-1) x (2ny-1)
//! (sizes with factors 2, 3, 5 only), transformed once; each product is a real 2-D FFT of p (its nonzero rows only),
//! a pointwise product and an inverse transform, of which the first nx x ny values are the linear convolution
//! (DC-FFT, Liu, Wang & Liu 2000, Wear 243:101-111). Eigen's FFT module (kissfft) does the 1-D transforms.
//! Storage is allocated at construction; apply() does not allocate. One object per thread.
#include <cstddef>
#include <memory>
#include <vector>

namespace ctab::gen {

class InfluenceConvolution {
 public:
  //! Throws InputError for zero sizes, sizes over kBem2dMaxElementsPerSide, or a bad element size or E*.
  InfluenceConvolution(std::size_t nx, std::size_t ny, double dx_m, double dy_m, double E_star_Pa);
  ~InfluenceConvolution();
  InfluenceConvolution(InfluenceConvolution&&) noexcept;
  InfluenceConvolution& operator=(InfluenceConvolution&&) noexcept;

  //! u = A p: p [Pa] and u [m] are ny x nx, row-major (index j nx + i); u is resized to nx ny.
  void apply(const std::vector<double>& pressure_Pa, std::vector<double>& displacement_m);
  //! A_II, the displacement of an element under its own unit pressure [m/Pa].
  [[nodiscard]] double self_coefficient() const noexcept;
  [[nodiscard]] std::size_t nx() const noexcept;
  [[nodiscard]] std::size_t ny() const noexcept;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ctab::gen
