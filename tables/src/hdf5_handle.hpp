// SPDX-License-Identifier: Apache-2.0
#pragma once
// RAII for HDF5 identifiers and the module's one place that silences HDF5's own error printing (private header).
#include <hdf5.h>

namespace ctab::tables::detail {

//! Owns an hid_t and closes it with the matching H5*close function.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) noexcept : id_(id), close_(close) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle(Handle&& other) noexcept : id_(other.id_), close_(other.close_) { other.id_ = -1; }
  Handle& operator=(Handle&&) = delete;
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  [[nodiscard]] hid_t get() const noexcept { return id_; }
  [[nodiscard]] bool valid() const noexcept { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

//! Turns off HDF5's automatic error stack printing (errors become status codes and messages).
void silence_hdf5_errors() noexcept;

}  // namespace ctab::tables::detail
