// SPDX-License-Identifier: Apache-2.0
/* ctab_lookup_hdf5: the C loader for HDF5 tables (link ctab::lookup_hdf5). */
#ifndef CTAB_LOOKUP_HDF5_H
#define CTAB_LOOKUP_HDF5_H

#include "ctab/lookup/ctab_lookup.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Opens an HDF5 table (schema 2) or a blob file, chosen by the file's first bytes. */
CTAB_API ctab_status ctab_table_open_hdf5(const char* path, const ctab_open_options* options, ctab_table** table);

#ifdef __cplusplus
}
#endif

#endif /* CTAB_LOOKUP_HDF5_H */
