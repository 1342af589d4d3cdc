// SPDX-License-Identifier: Apache-2.0
/* A C program of someone else's over the installed lookup (CTest install.*): built by a LANGUAGES C CMake project
 * (consumer/CMakeLists.txt) and by plain `cc` with pkg-config (pkg_config_consumer.sh).
 *   query_blob TABLE.blob RESULTS
 * Checks the library's version against the header's, reads the blob's header (format, schema), loads the blob and
 * compares ctab_query_batch for the right wheel with the recorded ctab_result records of RESULTS (the synthetic
 * table's query list: 261 dy x 3 loads x 2 wheels, tests/lookup/write_synthetic_blob.cpp). */
#include <stdio.h>
#include <string.h>

#include "ctab/lookup/ctab_lookup.h"

#define N_DY 261
#define N_LOAD 3
#define N_POINTS (N_DY * N_LOAD)

static int check_versions(const char* blob) {
  int32_t major = -1, minor = -1, patch = -1;
  ctab_blob_info info;
  ctab_version_numbers(&major, &minor, &patch);
  if (strcmp(ctab_version(), CTAB_VERSION_STRING) != 0 || major != CTAB_VERSION_MAJOR || minor != CTAB_VERSION_MINOR ||
      patch != CTAB_VERSION_PATCH) {
    fprintf(stderr, "library version %s, header %s\n", ctab_version(), CTAB_VERSION_STRING);
    return 0;
  }
  if (ctab_blob_info_file(blob, &info) != CTAB_OK || info.format_version != CTAB_BLOB_FORMAT_VERSION ||
      info.schema_version != CTAB_TABLE_SCHEMA_VERSION || info.value_bytes != 8) {
    fprintf(stderr, "%s: blob header not readable (format %u, schema %u)\n", blob, (unsigned)info.format_version,
            (unsigned)info.schema_version);
    return 0;
  }
  return 1;
}

/* The recorded right-wheel answers against the batch's, slot by slot. */
static int compare(FILE* results, const int32_t* status, const double* q, const int8_t* present, uint32_t n_slots) {
  ctab_result expected;
  long point, slot, wheel;
  for (point = 0; point < N_POINTS; ++point)
    for (wheel = 0; wheel < 2; ++wheel) {
      if (fread(&expected, sizeof expected, 1, results) != 1) return 0;
      if (wheel == 1) continue;
      if (expected.status != status[point]) return 0;
      for (slot = 0; slot < (long)n_slots; ++slot) {
        const double* got = q + (point * n_slots + slot) * CTAB_QUANTITIES;
        if (expected.patch[slot].present != present[point * n_slots + slot] ||
            memcmp(expected.patch[slot].q, got, sizeof expected.patch[slot].q) != 0) {
          fprintf(stderr, "point %ld slot %ld differs from the recorded result\n", point, slot);
          return 0;
        }
      }
    }
  return 1;
}

int main(int argc, char** argv) {
  static double dy[N_POINTS], load[N_POINTS], q[N_POINTS * CTAB_MAX_SLOTS * CTAB_QUANTITIES];
  static int32_t status[N_POINTS];
  static int8_t present[N_POINTS * CTAB_MAX_SLOTS];
  ctab_table* table = NULL;
  FILE* results;
  int i, k, ok;
  if (argc != 3 || !check_versions(argv[1])) return 1;
  if (ctab_table_open(argv[1], NULL, &table) != CTAB_OK) return 1;
  for (i = 0; i < N_DY; ++i)
    for (k = 0; k < N_LOAD; ++k) {
      dy[i * N_LOAD + k] = -13e-3 + 0.1e-3 * i;
      load[i * N_LOAD + k] = 50e3 + 27e3 * k;
    }
  ctab_query_batch(table, dy, load, N_POINTS, CTAB_WHEEL_RIGHT, status, q, present);
  results = fopen(argv[2], "rb");
  if (results == NULL) return 1;
  ok = compare(results, status, q, present, ctab_table_slot_count(table));
  fclose(results);
  ctab_table_close(table);
  if (!ok) return 1;
  printf("ctab %s: %d batch queries identical to the recorded results\n", ctab_version(), N_POINTS);
  return 0;
}
