// SPDX-License-Identifier: Apache-2.0
#include "chunk_deflate.hpp"

#include <zlib.h>

#include <algorithm>
#include <cstring>

namespace ctab::tables::detail {

ChunkGrid::ChunkGrid(std::vector<hsize_t> shape, std::vector<hsize_t> chunk)
    : shape_(std::move(shape)), chunk_(std::move(chunk)), chunks_per_dim_(shape_.size()) {
  for (std::size_t d = 0; d < shape_.size(); ++d) {
    chunks_per_dim_[d] = (shape_[d] + chunk_[d] - 1) / chunk_[d];
    count_ *= static_cast<std::size_t>(chunks_per_dim_[d]);
    chunk_elements_ *= static_cast<std::size_t>(chunk_[d]);
  }
}

std::vector<hsize_t> ChunkGrid::offset(std::size_t index) const {
  std::vector<hsize_t> at(shape_.size());
  for (std::size_t d = shape_.size(); d-- > 0;) {
    at[d] = (index % chunks_per_dim_[d]) * chunk_[d];
    index /= chunks_per_dim_[d];
  }
  return at;
}

void ChunkGrid::gather(const unsigned char* data, std::size_t element_size, std::size_t index,
                       std::vector<unsigned char>& out) const {
  out.assign(chunk_elements_ * element_size, 0);
  const std::vector<hsize_t> origin = offset(index);
  const std::size_t rank = shape_.size();
  // Rows along the last dimension: a contiguous run of the dataset per row of the chunk (clipped at the extent).
  const std::size_t last = rank - 1;
  const auto run = static_cast<std::size_t>(std::min(chunk_[last], shape_[last] - origin[last]));
  std::vector<hsize_t> row(rank, 0);  // chunk-relative coordinates of the row's first element (row[last] = 0)
  for (;;) {
    bool inside = true;
    std::size_t source = 0, target = 0;
    for (std::size_t d = 0; d < rank; ++d) {
      const hsize_t at = origin[d] + row[d];
      inside = inside && at < shape_[d];
      source = source * static_cast<std::size_t>(shape_[d]) + static_cast<std::size_t>(at);
      target = target * static_cast<std::size_t>(chunk_[d]) + static_cast<std::size_t>(row[d]);
    }
    if (inside) std::memcpy(out.data() + target * element_size, data + source * element_size, run * element_size);
    std::size_t d = last;  // next row: odometer over the leading dimensions
    while (d-- > 0) {
      if (++row[d] < chunk_[d]) break;
      row[d] = 0;
    }
    if (d == static_cast<std::size_t>(-1)) return;
  }
}

bool shuffle_and_deflate(const std::vector<unsigned char>& chunk, std::size_t element_size, int level,
                         std::vector<unsigned char>& scratch, std::vector<unsigned char>& out) {
  const std::size_t bytes = chunk.size();
  const unsigned char* source = chunk.data();
  const std::size_t elements = bytes / element_size;
  if (element_size > 1 && elements > 1) {  // H5Zshuffle.c (bytes % element_size is 0 for whole chunks)
    scratch.resize(bytes);
    for (std::size_t k = 0; k < element_size; ++k)
      for (std::size_t i = 0; i < elements; ++i) scratch[k * elements + i] = chunk[i * element_size + k];
    source = scratch.data();
  }
  uLongf compressed = compressBound(static_cast<uLong>(bytes));
  out.resize(compressed);
  if (compress2(out.data(), &compressed, source, static_cast<uLong>(bytes), level) != Z_OK) return false;
  out.resize(compressed);
  return true;
}

}  // namespace ctab::tables::detail
