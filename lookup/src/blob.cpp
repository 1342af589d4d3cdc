// SPDX-License-Identifier: Apache-2.0
// Blob writer: explicit little-endian encoding (independent of the host's byte order), FNV-1a 64 of the payload
// (the reader: blob_read.cpp).
#include <cstring>
#include <limits>
#include <string>

#include "ctab/lookup/blob.hpp"
#include "load_guard.hpp"

namespace ctab::lookup {

namespace {


void store_le(unsigned char* at, std::uint64_t v, int bytes) noexcept {
  for (int i = 0; i < bytes; ++i) at[i] = static_cast<unsigned char>(v >> (8 * i));
}

class Writer {
 public:
  explicit Writer(std::vector<unsigned char>& out) : out_(out) {}
  void u(std::uint64_t v, int bytes) {
    for (int i = 0; i < bytes; ++i) out_.push_back(static_cast<unsigned char>(v >> (8 * i)));
  }
  void f64(double v) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    u(bits, 8);
  }
  void f32(float v) {
    std::uint32_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    u(bits, 4);
  }
  void values(const std::vector<double>& v, bool single) {
    for (const double x : v) single ? f32(static_cast<float>(x)) : f64(x);
  }

 private:
  std::vector<unsigned char>& out_;
};

LoadResult fail(ctab_status status, const std::string& what) { return {status, "blob: " + what}; }

}  // namespace

std::uint64_t fnv1a64(const void* data, std::size_t size) noexcept {
  std::uint64_t hash = kFnvOffsetBasis;
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) hash = fnv1a64_step(hash, p[i]);
  return hash;
}

bool looks_like_hdf5(const void* bytes, std::size_t size) noexcept {
  static constexpr unsigned char kSignature[8] = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};
  return size >= 8 && std::memcmp(bytes, kSignature, 8) == 0;
}

LoadResult write_blob(const TableData& data, bool single, std::vector<unsigned char>& blob) {
  blob.clear();
  return detail::guard_allocation([&] {
    LoadResult checked = validate(data);
    if (checked.ok() && single) checked = check_float_range(data);
    if (!checked.ok()) return fail(checked.status, "cannot write: " + checked.message);
    blob = write_blob(data, single);
    return LoadResult{};
  });
}

std::vector<unsigned char> write_blob(const TableData& data, bool single) {
  const std::size_t value_bytes = single ? 4 : 8;
  std::vector<unsigned char> blob(kBlobHeaderBytes, 0);  // header filled in at the end
  Writer w(blob);
  for (const std::size_t count : {data.n_dy(), data.n_second(), data.n_slots, data.strip_samples, data.jumps.size(),
                                  static_cast<std::size_t>(data.second_axis), kQuantities, std::size_t{0}})
    w.u(count, 4);
  for (const double v : data.dy_m) w.f64(v);
  for (const double v : data.second) w.f64(v);
  for (const double v : data.roll_rad) w.f64(v);
  for (const double v : data.rolling_radius_difference_m) w.f64(v);
  w.values(data.quantities, single);
  w.values(data.strip_half_length_m, single);
  w.values(data.strip_peak_pressure_Pa, single);
  for (const std::int8_t s : data.case_status) w.u(static_cast<std::uint8_t>(s), 1);
  for (const std::uint8_t p : data.present) w.u(p, 1);
  for (const Jump& j : data.jumps) {
    w.u(j.i_second, 4);
    w.u(j.i_dy, 4);
    w.u(j.wheel, 1);
    w.u(j.slot, 1);
    w.u(static_cast<std::uint8_t>(j.kind), 1);
    w.u(0, 1);
  }
  while (blob.size() % 8 != 0) blob.push_back(0);
  const std::size_t payload_size = blob.size() - kBlobHeaderBytes;

  unsigned char* header = blob.data();
  std::memcpy(header, kBlobMagic, sizeof kBlobMagic);
  store_le(header + 8, kBlobVersion, 4);
  store_le(header + 12, static_cast<std::uint64_t>(kSchemaVersion), 4);
  store_le(header + 16, value_bytes, 4);
  store_le(header + 20, kBlobHeaderBytes, 4);
  store_le(header + 24, payload_size, 8);
  store_le(header + 32, fnv1a64(header + kBlobHeaderBytes, payload_size), 8);
  return blob;
}

}  // namespace ctab::lookup
