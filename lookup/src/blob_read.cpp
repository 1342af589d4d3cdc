// SPDX-License-Identifier: Apache-2.0
// Blob reader: header (magic, versions, reserved bytes, size), counts checked against the size limit and the exact
// payload size before anything is allocated, the FNV-1a 64 checksum before the payload is parsed, then the arrays
// read straight into a TableData. A file is read in chunks: its bytes are never held whole.
#include <array>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <string>

#include "ctab/lookup/blob.hpp"
#include "ctab/tables/limits.hpp"
#include "load_guard.hpp"

namespace ctab::lookup {

namespace {

constexpr std::size_t kCountsBytes = 32;  // eight u32 at the start of the payload
constexpr std::size_t kJumpBytes = 12;
constexpr std::size_t kReservedHeaderOffset = 40;  // header bytes 40..63: zero

// The payload's bytes in order, from memory or from a file in chunks, hashed (FNV-1a 64) as they are taken.
class Source {
 public:
  Source(const unsigned char* bytes, std::size_t size) noexcept : at_(bytes), left_(size) {}
  explicit Source(std::FILE* file) noexcept : file_(file) {}
  Source(const Source&) = delete;
  Source& operator=(const Source&) = delete;
  //! The next byte; 0 past the end (complete() false from then on).
  unsigned char next() noexcept {
    if (left_ == 0 && !refill()) {
      short_ = true;
      return 0;
    }
    --left_;
    const unsigned char byte = *at_++;
    hash_ = fnv1a64_step(hash_, byte);
    return byte;
  }
  //! Hashes `count` bytes without keeping them.
  void skip(std::uint64_t count) noexcept {
    for (std::uint64_t i = 0; i < count && !short_; ++i) (void)next();
  }
  [[nodiscard]] bool complete() const noexcept { return !short_; }
  [[nodiscard]] std::uint64_t hash() const noexcept { return hash_; }

 private:
  bool refill() noexcept {
    if (file_ == nullptr) return false;
    left_ = std::fread(buffer_.data(), 1, buffer_.size(), file_);
    at_ = buffer_.data();
    return left_ > 0;
  }
  std::FILE* file_ = nullptr;
  const unsigned char* at_ = nullptr;
  std::size_t left_ = 0;
  bool short_ = false;
  std::uint64_t hash_ = kFnvOffsetBasis;
  std::array<unsigned char, 65536> buffer_{};
};

class Reader {
 public:
  explicit Reader(Source& source) : source_(source) {}
  std::uint64_t u(int bytes) noexcept {
    std::uint64_t v = 0;
    for (int i = 0; i < bytes; ++i) v |= static_cast<std::uint64_t>(source_.next()) << (8 * i);
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
  Source& source_;
};

struct Header {
  std::uint64_t value_bytes = 0, payload_size = 0, checksum = 0;
};

// The payload's bytes before its zero padding to a multiple of 8.
std::size_t unpadded_payload_bytes(std::size_t n_dy, std::size_t n_2, std::size_t n_slots, std::size_t samples,
                                   std::size_t n_jumps, std::size_t value_bytes) noexcept {
  const std::size_t cases = n_dy * n_2, patches = cases * kWheels * n_slots;
  return kCountsBytes + 8 * (n_dy + n_2 + 2 * cases) + value_bytes * (patches * kQuantities + 2 * patches * samples) +
         cases * kWheels + patches + kJumpBytes * n_jumps;
}

LoadResult fail(ctab_status status, const std::string& what) { return {status, "blob: " + what}; }

// The 64 header bytes of a blob of `size` bytes in all.
LoadResult check_header(const unsigned char* p, std::uint64_t size, Header& out) {
  if (size < kBlobHeaderBytes || std::memcmp(p, kBlobMagic, 8) != 0)
    return fail(CTAB_ERR_NOT_A_TABLE, "not a ctab blob (no CTABBLOB magic) or shorter than its header");
  const std::uint64_t version = load_le(p + 8, 4), schema = load_le(p + 12, 4), header_bytes = load_le(p + 20, 4);
  out = {load_le(p + 16, 4), load_le(p + 24, 8), load_le(p + 32, 8)};
  if (version != kBlobVersion)
    return fail(CTAB_ERR_VERSION, "format version " + std::to_string(version) + ", expected 1");
  if (schema != static_cast<std::uint64_t>(kSchemaVersion))
    return fail(CTAB_ERR_VERSION, "table schema " + std::to_string(schema) + ", expected 2");
  if ((out.value_bytes != 4 && out.value_bytes != 8) || header_bytes != kBlobHeaderBytes)
    return fail(CTAB_ERR_NOT_A_TABLE, "bad value size or header size");
  for (std::size_t i = kReservedHeaderOffset; i < kBlobHeaderBytes; ++i)
    if (p[i] != 0) return fail(CTAB_ERR_NOT_A_TABLE, "header byte " + std::to_string(i) + " is reserved and not zero");
  if (out.payload_size != size - kBlobHeaderBytes)
    return fail(CTAB_ERR_NOT_A_TABLE, "truncated or padded: size mismatch");
  return {};
}

// Counts and their limits, then the arrays; the source's bytes must end exactly there and hash to the checksum.
LoadResult parse_payload(const Header& header, Source& source, TableData& data, bool& single) {
  if (header.payload_size < kCountsBytes) return fail(CTAB_ERR_SHAPE, "payload shorter than its counts");
  Reader r(source);
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
  const std::size_t unpadded = unpadded_payload_bytes(n_dy, n_2, n_slots, samples, n_jumps, header.value_bytes);
  if ((unpadded + 7) / 8 * 8 != header.payload_size)
    return fail(CTAB_ERR_SHAPE, "payload size does not match the counts");

  single = header.value_bytes == 4;
  data = TableData{};
  data.dy_m.resize(n_dy);
  data.second.resize(n_2);
  data.second_axis = static_cast<SecondAxis>(axis);
  data.n_slots = n_slots;
  data.strip_samples = samples;
  data.allocate();
  for (auto* axis_values : {&data.dy_m, &data.second, &data.roll_rad, &data.rolling_radius_difference_m})
    r.values(*axis_values, false);
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
  source.skip(header.payload_size - unpadded);  // the padding: hashed, not stored
  if (!source.complete()) return fail(CTAB_ERR_NOT_A_TABLE, "truncated while reading");
  if (source.hash() != header.checksum) return fail(CTAB_ERR_CHECKSUM, "payload checksum mismatch");
  static_assert(std::numeric_limits<double>::is_iec559, "blobs store IEEE 754 values");
  return {};
}

// A blob file: header, the checksum over a first pass in chunks, then the parse in a second pass (whose hash must
// agree too: a file changed in between is refused).
LoadResult parse_file(std::FILE* file, TableData& data, bool& single) {
  unsigned char header_bytes[kBlobHeaderBytes] = {};
  const std::size_t got = std::fread(header_bytes, 1, sizeof header_bytes, file);
  if (looks_like_hdf5(header_bytes, got))
    return {CTAB_ERR_HDF5_UNAVAILABLE, "an HDF5 table; this build loads blobs only (ctab export)"};
  if (std::fseek(file, 0, SEEK_END) != 0) return {CTAB_ERR_CANNOT_OPEN, "cannot read (not a seekable file)"};
  const long size = std::ftell(file);
  if (size < 0) return {CTAB_ERR_CANNOT_OPEN, "cannot read (not a seekable file)"};
  Header header;
  if (LoadResult r = check_header(header_bytes, static_cast<std::uint64_t>(size), header); !r.ok()) return r;
  if (std::fseek(file, static_cast<long>(kBlobHeaderBytes), SEEK_SET) != 0)
    return {CTAB_ERR_CANNOT_OPEN, "cannot read"};
  Source first(file);
  first.skip(header.payload_size);
  if (!first.complete()) return fail(CTAB_ERR_NOT_A_TABLE, "truncated while reading");
  if (first.hash() != header.checksum) return fail(CTAB_ERR_CHECKSUM, "payload checksum mismatch");
  if (std::fseek(file, static_cast<long>(kBlobHeaderBytes), SEEK_SET) != 0)
    return {CTAB_ERR_CANNOT_OPEN, "cannot read"};
  Source second(file);
  return parse_payload(header, second, data, single);
}

}  // namespace

LoadResult read_blob(const void* bytes, std::size_t size, TableData& data, bool& single) {
  return detail::guard_allocation([&] {
    if (bytes == nullptr) return fail(CTAB_ERR_NOT_A_TABLE, "no bytes");
    const auto* p = static_cast<const unsigned char*>(bytes);
    Header header;
    if (LoadResult r = check_header(p, size, header); !r.ok()) return r;
    if (fnv1a64(p + kBlobHeaderBytes, header.payload_size) != header.checksum)
      return fail(CTAB_ERR_CHECKSUM, "payload checksum mismatch");
    Source source(p + kBlobHeaderBytes, header.payload_size);
    return parse_payload(header, source, data, single);
  });
}

LoadResult read_blob_file(const std::string& path, TableData& data, bool& single) {
  LoadResult result = detail::guard_allocation([&] {
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), std::fclose);
    if (file == nullptr) return LoadResult{CTAB_ERR_CANNOT_OPEN, "cannot open"};
    LoadResult parsed = parse_file(file.get(), data, single);
    if (parsed.ok() && std::ferror(file.get()) != 0) parsed = {CTAB_ERR_CANNOT_OPEN, "read error"};
    return parsed;
  });
  if (!result.ok()) result.message = path + ": " + result.message;
  return result;
}

}  // namespace ctab::lookup
