// Blob writer and reader: explicit little-endian encoding (independent of the host's byte order), sizes checked
// against the header before anything is allocated, FNV-1a 64 of the payload.
#include <cstring>
#include <limits>
#include <string>

#include "ctab/lookup/blob.hpp"
#include "ctab/tables/limits.hpp"
#include "load_guard.hpp"

namespace ctab::lookup {

namespace {

constexpr std::size_t kCountsBytes = 32;  // eight u32 at the start of the payload
constexpr std::size_t kJumpBytes = 12;
constexpr std::size_t kReservedHeaderOffset = 40;  // header bytes 40..63: zero

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

class Reader {
 public:
  explicit Reader(const unsigned char* p) : p_(p) {}  // bounds: the caller checked the size first
  std::uint64_t u(int bytes) noexcept {
    std::uint64_t v = 0;
    for (int i = 0; i < bytes; ++i) v |= static_cast<std::uint64_t>(p_[at_ + static_cast<std::size_t>(i)]) << (8 * i);
    at_ += static_cast<std::size_t>(bytes);
    return v;
  }
  double f64() noexcept {
    const std::uint64_t bits = u(8);
    double v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  }
  double f32() noexcept {
    const auto bits = static_cast<std::uint32_t>(u(4));
    float v;
    std::memcpy(&v, &bits, sizeof v);
    return static_cast<double>(v);
  }
  void values(std::vector<double>& v, bool single) noexcept {
    for (double& x : v) x = single ? f32() : f64();
  }

 private:
  const unsigned char* p_;
  std::size_t at_ = 0;
};

std::size_t payload_bytes(std::size_t n_dy, std::size_t n_2, std::size_t n_slots, std::size_t samples,
                          std::size_t n_jumps, std::size_t value_bytes) noexcept {
  const std::size_t cases = n_dy * n_2, patches = cases * kWheels * n_slots;
  const std::size_t bytes = kCountsBytes + 8 * (n_dy + n_2 + 2 * cases) +
                            value_bytes * (patches * kQuantities + 2 * patches * samples) + cases * kWheels + patches +
                            kJumpBytes * n_jumps;
  return (bytes + 7) / 8 * 8;
}

LoadResult fail(ctab_status status, const std::string& what) { return {status, "blob: " + what}; }

}  // namespace

std::uint64_t fnv1a64(const void* data, std::size_t size) noexcept {
  std::uint64_t hash = 14695981039346656037ull;  // FNV offset basis
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) hash = (hash ^ p[i]) * 1099511628211ull;  // FNV prime
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

namespace {

LoadResult parse_blob(const void* bytes, std::size_t size, TableData& data, bool& single) {
  if (bytes == nullptr || size < kBlobHeaderBytes || std::memcmp(bytes, kBlobMagic, 8) != 0)
    return fail(CTAB_ERR_NOT_A_TABLE, "not a ctab blob (no CTABBLOB magic) or shorter than its header");
  const auto* p = static_cast<const unsigned char*>(bytes);
  Reader header(p + 8);
  const auto version = header.u(4), schema = header.u(4), value_bytes = header.u(4), header_bytes = header.u(4);
  const std::uint64_t payload_size = header.u(8), checksum = header.u(8);
  if (version != kBlobVersion)
    return fail(CTAB_ERR_VERSION, "format version " + std::to_string(version) + ", expected 1");
  if (schema != static_cast<std::uint64_t>(kSchemaVersion))
    return fail(CTAB_ERR_VERSION, "table schema " + std::to_string(schema) + ", expected 2");
  if ((value_bytes != 4 && value_bytes != 8) || header_bytes != kBlobHeaderBytes)
    return fail(CTAB_ERR_NOT_A_TABLE, "bad value size or header size");
  for (std::size_t i = kReservedHeaderOffset; i < kBlobHeaderBytes; ++i)
    if (p[i] != 0) return fail(CTAB_ERR_NOT_A_TABLE, "header byte " + std::to_string(i) + " is reserved and not zero");
  if (payload_size != size - kBlobHeaderBytes) return fail(CTAB_ERR_NOT_A_TABLE, "truncated or padded: size mismatch");
  const unsigned char* payload = p + kBlobHeaderBytes;
  if (fnv1a64(payload, payload_size) != checksum) return fail(CTAB_ERR_CHECKSUM, "payload checksum mismatch");
  if (payload_size < kCountsBytes) return fail(CTAB_ERR_SHAPE, "payload shorter than its counts");

  Reader r(payload);
  std::uint64_t counts[8];
  for (std::uint64_t& c : counts) c = r.u(4);
  const auto [n_dy, n_2, n_slots, samples, n_jumps, axis, quantities, reserved] = counts;
  if (n_dy < 2 || n_dy > tables::kMaxAxisLength || n_2 < 1 || n_2 > tables::kMaxAxisLength)
    return fail(CTAB_ERR_AXES, "axis lengths out of range (dy 2 to 2^20 values, second axis 1 to 2^20)");
  if (n_slots < 1 || n_slots > kMaxSlots || samples > kMaxStripSamples || quantities != kQuantities || reserved != 0 ||
      n_jumps > n_dy * n_2 * kWheels * n_slots)
    return fail(CTAB_ERR_SHAPE, "slots, strip samples, quantities or jumps out of range");
  if (axis > 2) return fail(CTAB_ERR_AXES, "unknown second-axis quantity");
  const double bytes_in_memory = tables::table_bytes(static_cast<double>(n_dy), static_cast<double>(n_2),
                                                     static_cast<double>(n_slots), static_cast<double>(samples));
  if (bytes_in_memory > tables::kMaxTableBytes)
    return fail(CTAB_ERR_SHAPE, "the table would take " + std::to_string(bytes_in_memory / (1u << 30)) +
                                    " GiB in memory (limit " + std::to_string(tables::kMaxTableBytes / (1u << 30)) +
                                    " GiB)");
  if (payload_bytes(n_dy, n_2, n_slots, samples, n_jumps, value_bytes) != payload_size)
    return fail(CTAB_ERR_SHAPE, "payload size does not match the counts");

  single = value_bytes == 4;
  data = TableData{};
  data.dy_m.resize(n_dy);
  data.second.resize(n_2);
  data.second_axis = static_cast<SecondAxis>(axis);
  data.n_slots = n_slots;
  data.strip_samples = samples;
  data.allocate();
  for (double& v : data.dy_m) v = r.f64();
  for (double& v : data.second) v = r.f64();
  for (double& v : data.roll_rad) v = r.f64();
  for (double& v : data.rolling_radius_difference_m) v = r.f64();
  r.values(data.quantities, single);
  r.values(data.strip_half_length_m, single);
  r.values(data.strip_peak_pressure_Pa, single);
  for (std::int8_t& s : data.case_status) s = static_cast<std::int8_t>(static_cast<std::uint8_t>(r.u(1)));
  for (std::uint8_t& v : data.present) v = static_cast<std::uint8_t>(r.u(1));
  data.jumps.resize(n_jumps);
  for (Jump& j : data.jumps) {
    j.i_second = static_cast<std::uint32_t>(r.u(4));
    j.i_dy = static_cast<std::uint32_t>(r.u(4));
    j.wheel = static_cast<std::uint8_t>(r.u(1));
    j.slot = static_cast<std::uint8_t>(r.u(1));
    j.kind = static_cast<JumpKind>(r.u(1));
    (void)r.u(1);
  }
  static_assert(std::numeric_limits<double>::is_iec559, "blobs store IEEE 754 values");
  return {};
}

}  // namespace

LoadResult read_blob(const void* bytes, std::size_t size, TableData& data, bool& single) {
  return detail::guard_allocation([&] { return parse_blob(bytes, size, data, single); });
}

}  // namespace ctab::lookup
