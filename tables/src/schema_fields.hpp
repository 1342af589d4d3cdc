// SPDX-License-Identifier: Apache-2.0
#pragma once
// The array datasets of schema 2 (private header): path, element type, unit, description, shape and the Table
// member that holds the data. The one list the writer, the reader and the validation walk.
#include <hdf5.h>

#include <string>
#include <vector>

#include "ctab/tables/table.hpp"

namespace ctab::tables::detail {

enum class Element { Float64, Presence, Status, Int8 };

//! Which axes a dataset spans.
//! PerCell: (n_dy - 1, n_second, kCellErrorQuantities), the cells of the dy axis.
enum class Extent { DyAxis, SecondAxis, PerCase, PerWheel, PerSlot, PerSample, PerCell };

struct Field {
  const char* path;
  const char* units;
  const char* description;
  Extent extent;
  Element element;
  std::vector<double>* doubles = nullptr;       //!< Float64
  std::vector<std::uint8_t>* bytes = nullptr;   //!< Presence
  std::vector<CaseStatus>* statuses = nullptr;  //!< Status
  std::vector<std::int8_t>* int8s = nullptr;    //!< Int8
  //! Optional on read: a table without the dataset gets `missing_value` everywhere (datasets added to schema 2
  //! later; readers of older tables keep working).
  bool optional = false;
  double missing_value = 0.0;
  //! Optional and kept empty where absent (not filled): neither allocated nor written while empty.
  bool empty_when_missing = false;
  //! Constraint on present patches (PerSlot and PerSample patch quantities): 0 none, 1 >= 0, 2 > 0.
  int sign = 0;
  //! True for patch quantities (must be 0 where the slot is empty).
  bool patch = false;

  [[nodiscard]] void* data() const noexcept;
  [[nodiscard]] std::size_t size() const noexcept;
  void resize(std::size_t n) const;
  void fill_missing() const;  //!< every element missing_value
};

//! Every array dataset of the schema, bound to the members of `table`.
[[nodiscard]] std::vector<Field> schema_fields(Table& table);

//! The shape of a dataset for the given axis lengths, slots and samples.
[[nodiscard]] std::vector<hsize_t> shape_of(Extent extent, hsize_t n_dy, hsize_t n_second, hsize_t n_slots,
                                            hsize_t strip_samples);

//! "i_dy=3, i_2=0, wheel=1, slot=2" for a flat index of a dataset of this extent.
[[nodiscard]] std::string index_text(Extent extent, const std::vector<hsize_t>& shape, std::size_t flat);

inline constexpr const char* kJumpsPath = "/jumps";
inline constexpr const char* kGroups[] = {"/axes", "/cases", "/wheels", "/patches"};

}  // namespace ctab::tables::detail
