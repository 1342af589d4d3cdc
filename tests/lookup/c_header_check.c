// SPDX-License-Identifier: Apache-2.0
/* A C99 program with the table compiled in (a header written by the blob exporter): loads it with
 * ctab_table_open_memory (no file system) and checks its answers against the C library's recorded results.
 *   lookup_c_header_check RESULTS */
#include <stdio.h>
#include <string.h>

#include "ctab/lookup/ctab_lookup.h"
#include "synthetic_blob.h"

int main(int argc, char** argv) {
  ctab_table* table = NULL;
  ctab_result expected, got;
  FILE* results;
  long count = 0;
  int i, k, wheel;
  if (argc != 2) return 2;
  if (ctab_table_open_memory(ctab_synthetic_blob, ctab_synthetic_blob_size, NULL, &table) != CTAB_OK) return 1;
  results = fopen(argv[1], "rb");
  if (results == NULL) return 1;
  for (i = 0; i <= 260; ++i)
    for (k = 0; k < 3; ++k)
      for (wheel = 0; wheel < 2; ++wheel) {
        memset(&got, 0, sizeof got);
        ctab_query(table, -13e-3 + 0.1e-3 * i, 50e3 + 27e3 * k, wheel, &got);
        if (fread(&expected, sizeof expected, 1, results) != 1 || memcmp(&expected, &got, sizeof got) != 0) {
          fprintf(stderr, "query %ld differs from the recorded result\n", count);
          return 1;
        }
        ++count;
      }
  fclose(results);
  ctab_table_close(table);
  printf("compiled-in table: %ld queries identical to the library's results\n", count);
  return 0;
}
