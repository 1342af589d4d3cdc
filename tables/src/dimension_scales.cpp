// SPDX-License-Identifier: Apache-2.0
// HDF5 dimension scales of a table: the layout of the HDF5 Dimension Scale Specification 1.0 written with the core
// API. A scale dataset carries CLASS = "DIMENSION_SCALE", NAME = its dimension's name and REFERENCE_LIST (the
// datasets and dimensions it is attached to); a dataset carries DIMENSION_LIST (per dimension, its scales) and
// DIMENSION_LABELS (per dimension, a name). Every attribute is written once, after all datasets exist.
#include "dimension_scales.hpp"

#include <array>
#include <cstdint>
#include <cstring>
#include <string>

#include "hdf5_handle.hpp"
#include "hdf5_types.hpp"

namespace ctab::tables::detail {

namespace {

// The table's dimensions in dataset order: dy, second, wheel, slot, sample.
constexpr std::size_t kDimensions = 5;
constexpr std::array<const char*, kDimensions> kNames = {"dy", "second", "wheel", "slot", "sample"};
constexpr std::array<const char*, kDimensions> kScalePaths = {"/axes/lateral_displacement_m", "/axes/second",
                                                              "/axes/wheel", "/axes/slot", "/axes/sample"};

std::size_t rank_of(Extent extent) noexcept {
  switch (extent) {
    case Extent::DyAxis:
    case Extent::SecondAxis: return 1;
    case Extent::PerCase: return 2;
    case Extent::PerWheel: return 3;
    case Extent::PerSlot: return 4;
    case Extent::PerSample: return 5;
    case Extent::PerCell: return 3;
  }
  return 0;
}

// The dimension (index into kNames) of a dataset's dimension d.
std::size_t dimension_of(Extent extent, std::size_t d) noexcept { return extent == Extent::SecondAxis ? 1 : d; }

// One entry of a scale's REFERENCE_LIST (the specification's compound: "dataset", "dimension").
struct Reference {
  hobj_ref_t dataset;
  int dimension;
};

bool write_attribute(hid_t object, const char* name, hid_t type, hsize_t count, const void* data) {
  const Handle space(count == 0 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &count, nullptr), H5Sclose);
  const Handle attribute(H5Acreate2(object, name, type, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  return attribute.valid() && H5Awrite(attribute.get(), type, data) >= 0;
}

// A scalar null-terminated ASCII string of fixed length, as the specification writes CLASS and NAME.
bool write_fixed_text(hid_t object, const char* name, const char* value) {
  const Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), std::strlen(value) + 1);
  H5Tset_strpad(type.get(), H5T_STR_NULLTERM);
  return write_attribute(object, name, type.get(), 0, value);
}

template <typename T>
bool write_index_dataset(hid_t file, const char* path, hid_t file_type, hid_t memory_type, const std::vector<T>& values,
                         const char* description) {
  const hsize_t count = values.size();
  const Handle space(H5Screate_simple(1, &count, nullptr), H5Sclose);
  const Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  H5Pset_obj_track_times(dcpl.get(), false);  // no timestamps: the same table gives the same bytes
  const Handle dataset(H5Dcreate2(file, path, file_type, space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT),
                       H5Dclose);
  return dataset.valid() && H5Dwrite(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0 &&
         write_text_attribute(dataset.get(), "units", "1") &&
         write_text_attribute(dataset.get(), "description", description);
}

bool create_index_scales(hid_t file, hsize_t n_slots, hsize_t strip_samples) {
  std::vector<std::uint8_t> slots(n_slots);
  for (hsize_t i = 0; i < n_slots; ++i) slots[i] = static_cast<std::uint8_t>(i);
  std::vector<double> samples(strip_samples);
  for (hsize_t k = 0; k < strip_samples; ++k)
    samples[k] = static_cast<double>(k) / static_cast<double>(strip_samples - 1);
  return write_index_dataset(file, kScalePaths[2], H5T_STD_U8LE, H5T_NATIVE_UINT8, std::vector<std::uint8_t>{0, 1},
                             "wheel index: 0 right wheel, 1 left wheel (its quantities in the left side's mirrored "
                             "frame)") &&
         write_index_dataset(file, kScalePaths[3], H5T_STD_U8LE, H5T_NATIVE_UINT8, slots,
                             "patch slot index (slots hold patches in ascending y_rail_m; empty slots last)") &&
         write_index_dataset(file, kScalePaths[4], H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, samples,
                             "strip sample position as a fraction of the patch: s = s_min_m + sample (s_max_m - "
                             "s_min_m)");
}

bool write_labels(hid_t dataset, const std::vector<const char*>& labels) {
  const Handle string_type(make_utf8_type(), H5Tclose);
  return write_attribute(dataset, "DIMENSION_LABELS", string_type.get(), labels.size(), labels.data());
}

// A per-cell dataset (n_dy - 1, n_second, quantity): its cells lie between the dy nodes, so only its second
// dimension has a scale; the others are labelled (dy_cell, quantity) and left without one (an empty list).
bool attach_per_cell(hid_t dataset, hobj_ref_t self, const std::array<hobj_ref_t, kDimensions>& scales,
                     std::array<std::vector<Reference>, kDimensions>& references) {
  if (!write_labels(dataset, {"dy_cell", kNames[1], "quantity"})) return false;
  hobj_ref_t second = scales[1];
  const std::array<hvl_t, 3> lists = {hvl_t{0, nullptr}, hvl_t{1, &second}, hvl_t{0, nullptr}};
  references[1].push_back({self, 1});
  const Handle list_type(H5Tvlen_create(H5T_STD_REF_OBJ), H5Tclose);
  return write_attribute(dataset, "DIMENSION_LIST", list_type.get(), lists.size(), lists.data());
}

// DIMENSION_LABELS and (unless the dataset is a scale itself) DIMENSION_LIST of one dataset; its dimensions appended
// to the scales' reference lists.
bool attach(hid_t file, const DimensionedDataset& d, const std::array<hobj_ref_t, kDimensions>& scales,
            std::array<std::vector<Reference>, kDimensions>& references) {
  const Handle dataset(H5Dopen2(file, d.path, H5P_DEFAULT), H5Dclose);
  hobj_ref_t self{};
  if (!dataset.valid() || H5Rcreate(&self, file, d.path, H5R_OBJECT, -1) < 0) return false;
  const std::size_t rank = rank_of(d.extent);
  if (d.extent == Extent::PerCell) return attach_per_cell(dataset.get(), self, scales, references);
  std::vector<const char*> labels(rank);
  for (std::size_t i = 0; i < rank; ++i) labels[i] = kNames[dimension_of(d.extent, i)];
  if (!write_labels(dataset.get(), labels)) return false;
  if (d.extent == Extent::DyAxis || d.extent == Extent::SecondAxis) return true;  // a scale is not its own scale
  std::vector<hobj_ref_t> refs(rank);
  std::vector<hvl_t> lists(rank);
  for (std::size_t i = 0; i < rank; ++i) {
    const std::size_t dim = dimension_of(d.extent, i);
    refs[i] = scales[dim];
    lists[i] = {1, &refs[i]};
    references[dim].push_back({self, static_cast<int>(i)});
  }
  const Handle list_type(H5Tvlen_create(H5T_STD_REF_OBJ), H5Tclose);
  return write_attribute(dataset.get(), "DIMENSION_LIST", list_type.get(), rank, lists.data());
}

bool write_scale(hid_t file, std::size_t dim, const std::vector<Reference>& references) {
  const Handle scale(H5Dopen2(file, kScalePaths[dim], H5P_DEFAULT), H5Dclose);
  const Handle type(H5Tcreate(H5T_COMPOUND, sizeof(Reference)), H5Tclose);
  H5Tinsert(type.get(), "dataset", HOFFSET(Reference, dataset), H5T_STD_REF_OBJ);
  H5Tinsert(type.get(), "dimension", HOFFSET(Reference, dimension), H5T_NATIVE_INT);
  const bool index_scale = dim >= 2;  // the axis datasets got their labels with the other datasets
  return scale.valid() && (!index_scale || write_labels(scale.get(), {kNames[dim]})) &&
         write_fixed_text(scale.get(), "CLASS", "DIMENSION_SCALE") &&
         write_fixed_text(scale.get(), "NAME", kNames[dim]) &&
         (references.empty() ||
          write_attribute(scale.get(), "REFERENCE_LIST", type.get(), references.size(), references.data()));
}

}  // namespace

bool write_dimension_scales(hid_t file, const std::vector<DimensionedDataset>& datasets, hsize_t n_slots,
                            hsize_t strip_samples) {
  if (!create_index_scales(file, n_slots, strip_samples)) return false;
  std::array<hobj_ref_t, kDimensions> scales{};
  for (std::size_t dim = 0; dim < kDimensions; ++dim)
    if (H5Rcreate(&scales[dim], file, kScalePaths[dim], H5R_OBJECT, -1) < 0) return false;
  std::array<std::vector<Reference>, kDimensions> references;
  for (const DimensionedDataset& d : datasets)
    if (!attach(file, d, scales, references)) return false;
  for (std::size_t dim = 0; dim < kDimensions; ++dim)
    if (!write_scale(file, dim, references[dim])) return false;
  const Handle jumps(H5Dopen2(file, kJumpsPath, H5P_DEFAULT), H5Dclose);
  return jumps.valid() && write_labels(jumps.get(), {"jump"});
}

}  // namespace ctab::tables::detail
