// SPDX-License-Identifier: Apache-2.0
#pragma once
// HDF5 dimension scales of a table's datasets (private header), written with the core HDF5 API in the layout of the
// HDF5 Dimension Scale Specification 1.0 (what libhdf5_hl's H5DS functions write and h5py's `dims` read), so the
// tables library and its consumers link no further library.
#include <hdf5.h>

#include <vector>

#include "schema_fields.hpp"

namespace ctab::tables::detail {

//! A dataset of the file and the axes it spans.
struct DimensionedDataset {
  const char* path;
  Extent extent;
};

//! Creates the index scales /axes/wheel, /axes/slot and /axes/sample, makes them and the two axis datasets dimension
//! scales named dy, second, wheel, slot, sample, and attaches them to every dimension of `datasets` (labels too);
//! /jumps gets the label "jump". False on any HDF5 failure.
[[nodiscard]] bool write_dimension_scales(hid_t file, const std::vector<DimensionedDataset>& datasets,
                                          hsize_t n_slots, hsize_t strip_samples);

}  // namespace ctab::tables::detail
