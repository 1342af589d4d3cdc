// SPDX-License-Identifier: Apache-2.0
#pragma once
// HDF5 types and attribute helpers of the table format (private header): the CaseStatus and JumpKind enum types,
// the /jumps compound record, UTF-8 strings, and typed scalar attributes.
#include <hdf5.h>

#include <cstdint>
#include <string>

#include "ctab/tables/table.hpp"
#include "hdf5_handle.hpp"

namespace ctab::tables::detail {

//! The root attribute written as a boolean (make_bool_type); Table::text_attributes holds it as text, true when it
//! starts with "true". Tables that wrote it as a sentence ("true: left wheel at dy = ...") read the same.
inline constexpr const char* kMirroredAttribute = "mirrored";

//! One row of /jumps in memory (the file type is the packed little-endian form: no padding bytes on disk).
struct JumpRecord {
  std::uint32_t i_second;
  std::uint8_t wheel;
  std::uint8_t slot;
  std::uint32_t i_dy;
  double dy_low_m;
  double dy_high_m;
  std::uint8_t kind;
};

//! Enum type (int8 base) with the names of CaseStatus (case_status_name) and their values.
[[nodiscard]] hid_t make_case_status_type() noexcept;
//! Enum type (int8 base) of /wheels/method: the ContactMethod names and values (mim1d 0, hertz 1, kp 2, analyn 3,
//! bem2d 4) and not_recorded (kMethodNotRecorded).
[[nodiscard]] hid_t make_method_type() noexcept;
//! h5py's boolean: an enum (int8 base) FALSE = 0, TRUE = 1.
[[nodiscard]] hid_t make_bool_type() noexcept;
//! Enum type (uint8 base) with the JumpKind names "appears", "disappears", "moves".
[[nodiscard]] hid_t make_jump_kind_type() noexcept;
//! Memory compound type of JumpRecord; its kind member has type `kind_type` (a JumpKind enum type).
[[nodiscard]] hid_t make_jump_type(hid_t kind_type) noexcept;
//! The file type: the packed copy of make_jump_type(make_jump_kind_type()).
[[nodiscard]] hid_t make_jump_file_type() noexcept;
//! True if `type` is a 1-byte enum whose members are all members of `expected` with the same values (a table written
//! before a status was appended has fewer).
[[nodiscard]] bool same_enum(hid_t type, hid_t expected) noexcept;
//! Variable-length UTF-8 string type (h5py reads it as str).
[[nodiscard]] hid_t make_utf8_type() noexcept;

[[nodiscard]] bool write_text_attribute(hid_t object, const char* name, const std::string& value) noexcept;
[[nodiscard]] bool write_integer_attribute(hid_t object, const char* name, std::int64_t value) noexcept;
[[nodiscard]] bool write_number_attribute(hid_t object, const char* name, double value) noexcept;
[[nodiscard]] bool write_bool_attribute(hid_t object, const char* name, bool value) noexcept;

//! Reads a string attribute (variable or fixed length); false if it is not a string or cannot be read.
[[nodiscard]] bool read_text_attribute(hid_t attribute, std::string& value);

}  // namespace ctab::tables::detail
