// SPDX-License-Identifier: Apache-2.0
#pragma once
// HDF5's shuffle + deflate filter pipeline applied to one chunk of a dataset outside the library, so that a table's
// chunks can be compressed in parallel and stored with H5Dwrite_chunk. The bytes are those the library's own filters
// give (H5Zshuffle.c: byte k of element i moves to k * elements + i; H5Zdeflate.c: zlib's compress2 at the level), for
// a full-size chunk whose part beyond the dataset's extent holds the default fill value (zero bytes), as the
// library stores edge chunks.
#include <hdf5.h>

#include <cstddef>
#include <vector>

namespace ctab::tables::detail {

//! The chunk grid of a dataset: its shape and chunk shape (same rank), and the chunks in row-major order.
class ChunkGrid {
 public:
  ChunkGrid(std::vector<hsize_t> shape, std::vector<hsize_t> chunk);
  [[nodiscard]] std::size_t count() const noexcept { return count_; }
  //! Element offsets of chunk `index` in the dataset (H5Dwrite_chunk's offset).
  [[nodiscard]] std::vector<hsize_t> offset(std::size_t index) const;
  //! Elements of a full chunk.
  [[nodiscard]] std::size_t chunk_elements() const noexcept { return chunk_elements_; }
  //! Copies chunk `index` of row-major `data` (elements of `element_size` bytes) into `out` (chunk_elements()
  //! elements, zero beyond the dataset's extent).
  void gather(const unsigned char* data, std::size_t element_size, std::size_t index,
              std::vector<unsigned char>& out) const;

 private:
  std::vector<hsize_t> shape_, chunk_, chunks_per_dim_;
  std::size_t count_ = 1, chunk_elements_ = 1;
};

//! Shuffles `chunk` (elements of `element_size` bytes) and deflates it at `level` (1..9) into `out`; false when zlib
//! fails.
[[nodiscard]] bool shuffle_and_deflate(const std::vector<unsigned char>& chunk, std::size_t element_size, int level,
                                       std::vector<unsigned char>& scratch, std::vector<unsigned char>& out);

}  // namespace ctab::tables::detail
