// SPDX-License-Identifier: Apache-2.0
// HDF5 types and attribute helpers of the table format.
#include "hdf5_types.hpp"

#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <utility>

namespace ctab::tables::detail {

void silence_hdf5_errors() noexcept {
  static const bool done = [] {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    return true;
  }();
  (void)done;
}

hid_t make_case_status_type() noexcept {
  const hid_t type = H5Tenum_create(H5T_STD_I8LE);
  for (int value = kCaseStatusMin; value <= kCaseStatusMax; ++value) {
    const auto v = static_cast<std::int8_t>(value);
    H5Tenum_insert(type, case_status_name(static_cast<CaseStatus>(v)), &v);
  }
  return type;
}

hid_t make_method_type() noexcept {
  const hid_t type = H5Tenum_create(H5T_STD_I8LE);
  const std::pair<const char*, std::int8_t> methods[] = {{"not_recorded", kMethodNotRecorded}, {"mim1d", 0},
                                                         {"hertz", 1}, {"kp", 2}, {"analyn", 3}, {"bem2d", 4}};
  static_assert(kMaxMethodValue == 4, "a ContactMethod value without its name in the method enum");
  for (const auto& [name, value] : methods) H5Tenum_insert(type, name, &value);
  return type;
}

hid_t make_bool_type() noexcept {
  const hid_t type = H5Tenum_create(H5T_STD_I8LE);
  const std::int8_t no = 0, yes = 1;
  H5Tenum_insert(type, "FALSE", &no);
  H5Tenum_insert(type, "TRUE", &yes);
  return type;
}

hid_t make_jump_kind_type() noexcept {
  const hid_t type = H5Tenum_create(H5T_STD_U8LE);
  const std::pair<const char*, JumpKind> kinds[] = {{"appears", JumpKind::Appears},
                                                    {"disappears", JumpKind::Disappears},
                                                    {"moves", JumpKind::Moves}};
  for (const auto& [name, kind] : kinds) {
    const auto v = static_cast<std::uint8_t>(kind);
    H5Tenum_insert(type, name, &v);
  }
  return type;
}

hid_t make_jump_type(hid_t kind_type) noexcept {
  const hid_t type = H5Tcreate(H5T_COMPOUND, sizeof(JumpRecord));
  H5Tinsert(type, "i_second", HOFFSET(JumpRecord, i_second), H5T_STD_U32LE);
  H5Tinsert(type, "wheel", HOFFSET(JumpRecord, wheel), H5T_STD_U8LE);
  H5Tinsert(type, "slot", HOFFSET(JumpRecord, slot), H5T_STD_U8LE);
  H5Tinsert(type, "i_dy", HOFFSET(JumpRecord, i_dy), H5T_STD_U32LE);
  H5Tinsert(type, "dy_low_m", HOFFSET(JumpRecord, dy_low_m), H5T_IEEE_F64LE);
  H5Tinsert(type, "dy_high_m", HOFFSET(JumpRecord, dy_high_m), H5T_IEEE_F64LE);
  H5Tinsert(type, "kind", HOFFSET(JumpRecord, kind), kind_type);
  return type;
}

hid_t make_jump_file_type() noexcept {
  const Handle kind(make_jump_kind_type(), H5Tclose);
  const Handle memory(make_jump_type(kind.get()), H5Tclose);
  const hid_t type = H5Tcopy(memory.get());
  H5Tpack(type);
  return type;
}

bool same_enum(hid_t type, hid_t expected) noexcept {
  if (H5Tget_class(type) != H5T_ENUM || H5Tget_size(type) != 1) return false;
  // Every member of the file's type is one of ours with the same value: tables written before a status was
  // appended (e.g. under-resolved, 2) have fewer members and stay readable.
  const int members = H5Tget_nmembers(type);
  if (members <= 0 || members > H5Tget_nmembers(expected)) return false;
  for (int i = 0; i < members; ++i) {
    char* name = H5Tget_member_name(type, static_cast<unsigned>(i));
    std::int8_t want = 0, got = 0;
    const bool ok = name != nullptr && H5Tget_member_value(type, static_cast<unsigned>(i), &got) >= 0 &&
                    H5Tenum_valueof(expected, name, &want) >= 0 && want == got;
    H5free_memory(name);
    if (!ok) return false;
  }
  return true;
}

hid_t make_utf8_type() noexcept {
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, H5T_VARIABLE);
  H5Tset_cset(type, H5T_CSET_UTF8);
  return type;
}

namespace {

bool write_scalar_attribute(hid_t object, const char* name, hid_t file_type, hid_t memory_type,
                            const void* value) noexcept {
  const Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  const Handle attribute(H5Acreate2(object, name, file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  return attribute.valid() && H5Awrite(attribute.get(), memory_type, value) >= 0;
}

}  // namespace

bool write_text_attribute(hid_t object, const char* name, const std::string& value) noexcept {
  const Handle type(make_utf8_type(), H5Tclose);
  const char* text = value.c_str();
  return write_scalar_attribute(object, name, type.get(), type.get(), &text);
}

bool write_integer_attribute(hid_t object, const char* name, std::int64_t value) noexcept {
  return write_scalar_attribute(object, name, H5T_STD_I64LE, H5T_NATIVE_INT64, &value);
}

bool write_number_attribute(hid_t object, const char* name, double value) noexcept {
  return write_scalar_attribute(object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value);
}

bool write_bool_attribute(hid_t object, const char* name, bool value) noexcept {
  const Handle type(make_bool_type(), H5Tclose);
  const std::int8_t v = value ? 1 : 0;
  return write_scalar_attribute(object, name, type.get(), type.get(), &v);
}

bool read_text_attribute(hid_t attribute, std::string& value) {
  const Handle type(H5Aget_type(attribute), H5Tclose);
  if (H5Tget_class(type.get()) != H5T_STRING) return false;
  const Handle space(H5Aget_space(attribute), H5Sclose);
  if (H5Sget_simple_extent_npoints(space.get()) != 1) return false;
  if (H5Tis_variable_str(type.get()) > 0) {
    const Handle memory(make_utf8_type(), H5Tclose);
    char* text = nullptr;
    if (H5Aread(attribute, memory.get(), &text) < 0) return false;
    value = text != nullptr ? text : "";
    H5free_memory(text);
    return true;
  }
  const std::size_t size = H5Tget_size(type.get());
  if (size == 0 || size > (std::size_t{1} << 26)) return false;
  value.assign(size, '\0');
  const Handle memory(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(memory.get(), size);
  H5Tset_cset(memory.get(), H5Tget_cset(type.get()));
  if (H5Aread(attribute, memory.get(), value.data()) < 0) return false;
  value.resize(std::strlen(value.c_str()));
  return true;
}

}  // namespace ctab::tables::detail
