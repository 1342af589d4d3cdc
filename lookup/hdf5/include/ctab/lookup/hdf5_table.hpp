// SPDX-License-Identifier: Apache-2.0
#pragma once
//! ctab_lookup_hdf5: HDF5 tables (schema 2, through ctab::tables) into the lookup core's representation.
#include <string>

#include "ctab/lookup/table.hpp"
#include "ctab/lookup/table_data.hpp"
#include "ctab/tables/table.hpp"

namespace ctab::lookup {

//! Converts an in-memory schema-2 table (as read or generated) into a TableData. A second-axis name other than
//! the three known ones gives CTAB_ERR_AXES; everything else is checked by validate()/Table::load.
[[nodiscard]] LoadResult from_tables(const tables::Table& table, TableData& data);
//! The same, taking `table`'s arrays (moved, or released once converted): `table` is left unspecified.
[[nodiscard]] LoadResult from_tables(tables::Table&& table, TableData& data);
//! Reads an HDF5 table (tables::read_table) and converts it.
[[nodiscard]] LoadResult read_hdf5(const std::string& path, TableData& data);
//! Loads an HDF5 table or a blob file, chosen by the file's first bytes.
[[nodiscard]] LoadResult open_file(const std::string& path, const LoadOptions& options, Table& table);
//! Reads an HDF5 table or a blob file into a TableData (`single_precision` true for a float blob).
[[nodiscard]] LoadResult read_any(const std::string& path, TableData& data, bool& single_precision);

}  // namespace ctab::lookup
