// SPDX-License-Identifier: Apache-2.0
/* ctab lookup: the plain C API of the real-time contact-table interpolation (C99, also valid C++).
 *
 * Load once (ctab_table_open*, the only calls that allocate), then query any number of times from any number of
 * threads: ctab_query / ctab_prelookup / ctab_query_prelooked / ctab_strip_profile never allocate, lock, throw
 * or make a system call, and their time does not depend on the query or the table's values. SI units
 * throughout (m, N, Pa, rad). Behaviour, statuses and the blob format: lookup/README.md. */
#ifndef CTAB_LOOKUP_H
#define CTAB_LOOKUP_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(__GNUC__)
#define CTAB_API __attribute__((visibility("default")))
#else
#define CTAB_API
#endif

/* Version of this header; ctab_version() and ctab_version_numbers() give the loaded library's (they differ only
 * where a program runs against another library than the one it was compiled with). */
#define CTAB_VERSION_MAJOR 0
#define CTAB_VERSION_MINOR 2
#define CTAB_VERSION_PATCH 0
#define CTAB_VERSION_STRING "0.2.0"
#define CTAB_BLOB_FORMAT_VERSION 1 /* the blob layout this library reads (lookup/README.md "Blob format") */
#define CTAB_TABLE_SCHEMA_VERSION 2 /* the table schema it reads (tables/README.md) */
CTAB_API const char* ctab_version(void); /* "MAJOR.MINOR.PATCH" */
CTAB_API void ctab_version_numbers(int32_t* major, int32_t* minor, int32_t* patch); /* any may be NULL */

#define CTAB_MAX_SLOTS 16 /* most patch slots per wheel (= ctab::tables::kMaxSlots) */
#define CTAB_WHEEL_RIGHT 0
#define CTAB_WHEEL_LEFT 1

/* Status of a load or a query. 0 ok, 1 usable with a caveat, < 0 failure. */
typedef enum ctab_status {
  CTAB_OK = 0,
  CTAB_CLAMPED = 1,           /* query outside the table range: answered at the nearest edge */
  CTAB_INVALID_INPUT = -1,    /* NaN/infinite input, wheel/slot out of range, null pointer: outputs zeroed */
  CTAB_NOT_LOADED = -2,       /* null table handle: outputs zeroed */
  CTAB_ERR_CANNOT_OPEN = -10, /* file missing or unreadable */
  CTAB_ERR_NOT_A_TABLE = -11, /* neither a ctab blob nor (with ctab_lookup_hdf5) an HDF5 table; truncated */
  CTAB_ERR_VERSION = -12,     /* blob format or table schema version not supported */
  CTAB_ERR_CHECKSUM = -13,    /* blob payload does not match its checksum */
  CTAB_ERR_AXES = -14,  /* fewer than 2 dy values, not finite, not increasing, a step without a finite inverse, or
                           dy refined below 1/64 of its mean step */
  CTAB_ERR_SHAPE = -15, /* array sizes do not match the axes, slots or strip samples; above the size limit */
  CTAB_ERR_CONTENT = -16, /* non-finite value or beyond 1e300, beyond the float range in single precision, PCHIP
                             slopes that overflow, unknown case status, presence not 0/1, bad jump */
  CTAB_ERR_OUT_OF_MEMORY = -17, /* an allocation failed while loading */
  CTAB_ERR_HDF5_UNAVAILABLE = -18 /* an HDF5 file given to a build without ctab_lookup_hdf5: export a blob */
} ctab_status;

/* Interpolation along the lateral displacement dy (the second axis is always linear). */
typedef enum ctab_interpolation {
  CTAB_LINEAR = 0,
  CTAB_PCHIP = 1 /* monotone cubic, Fritsch-Carlson slopes, never across a jump */
} ctab_interpolation;

typedef struct ctab_open_options {
  int32_t interpolation;    /* ctab_interpolation; default CTAB_LINEAR */
  int32_t single_precision; /* nonzero: store values as float (half the memory); a float blob always is */
} ctab_open_options;

/* Indices of the tabulated quantities in ctab_patch.q. Frames as in tables/README.md (each wheel in its own side
 * frame: y lateral + to the field side, z vertical + down); forces are those of the wheel on the rail. */
typedef enum ctab_quantity {
  CTAB_NORMAL_FORCE_N = 0,    /* resultant normal force [N] */
  CTAB_FORCE_LATERAL_N = 1,   /* lateral component on the rail, + to the field side [N] */
  CTAB_FORCE_VERTICAL_N = 2,  /* vertical component on the rail, + downwards [N] */
  CTAB_AREA_M2 = 3,           /* contact area [m^2] */
  CTAB_MAX_PRESSURE_PA = 4,   /* [Pa] */
  CTAB_APPROACH_M = 5,        /* normal approach of the patch [m] */
  CTAB_CONTACT_ANGLE_RAD = 6, /* direction of the resultant force [rad] */
  CTAB_PLANE_ANGLE_RAD = 7,   /* inclination of the contact plane in which s is measured [rad] */
  CTAB_S_ORIGIN_Y_RAIL_M = 8, /* rail point where s = 0, lateral [m] */
  CTAB_S_ORIGIN_Z_RAIL_M = 9, /* rail point where s = 0, vertical + down [m] */
  CTAB_Y_WHEEL_M = 10,        /* contact point on the wheel profile [m] */
  CTAB_Y_RAIL_M = 11,         /* contact point on the rail profile [m] */
  CTAB_Y_COP_RAIL_M = 12,     /* centre of pressure on the rail profile [m] */
  CTAB_ROLLING_RADIUS_M = 13, /* [m] */
  CTAB_SEMI_AXIS_A_M = 14,    /* equivalent ellipse, rolling direction [m] */
  CTAB_SEMI_AXIS_B_M = 15,    /* equivalent ellipse, lateral [m] */
  CTAB_S_MIN_M = 16,          /* lateral extent of the patch in its contact plane [m] */
  CTAB_S_MAX_M = 17,
  CTAB_QUANTITIES = 18
} ctab_quantity;

/* One patch slot: every quantity (indexed by ctab_quantity), all zero where present == 0. */
typedef struct ctab_patch {
  double q[CTAB_QUANTITIES];
  int32_t present; /* 1: the slot holds a patch at the query point, 0: not */
  int32_t reserved;
} ctab_patch;

/* Where a query point lies in the table: computed once, reusable for both wheels and every quantity. */
typedef struct ctab_location {
  uint32_t i_dy;     /* cell (i_dy, i_dy + 1) of the dy axis */
  uint32_t i_second; /* cell (i_second, i_second + 1) of the second axis (0 when it has one value) */
  double f_dy;       /* fraction in [0, 1] inside the dy cell */
  double f_second;   /* fraction in [0, 1] inside the second-axis cell (0 when it has one value) */
  double dy_m;       /* the query point actually used (clamped) [m] */
  double second;     /* second-axis value actually used (clamped), in its units */
  int32_t status;    /* CTAB_OK, CTAB_CLAMPED, CTAB_INVALID_INPUT or CTAB_NOT_LOADED */
  int32_t reserved;
} ctab_location;

typedef struct ctab_result {
  int32_t status;             /* ctab_status of this query */
  int32_t n_slots;            /* slots of the table; patch[n_slots..] have present = 0, other members unwritten */
  int32_t worst_case_status;  /* smallest (most severe) of neighbour_status: < 0 means a failed case is adjacent */
  int8_t neighbour_status[4]; /* table case status (tables/README.md) at (dy lo, 2nd lo), (dy hi, 2nd lo),
                                 (dy lo, 2nd hi), (dy hi, 2nd hi) for this wheel */
  double dy_m;                /* query point used (clamped) [m] */
  double second;              /* second-axis value used (clamped) */
  double roll_rad;            /* wheelset roll [rad] */
  double rolling_radius_difference_m; /* r_right - r_left [m] */
  ctab_patch patch[CTAB_MAX_SLOTS];
} ctab_result;

typedef struct ctab_table ctab_table; /* opaque, immutable after load */

/* Loading (allocates). `options` may be NULL (defaults). On failure *table is NULL. */
CTAB_API ctab_status ctab_table_open(const char* path, const ctab_open_options* options, ctab_table** table);
CTAB_API ctab_status ctab_table_open_memory(const void* data, size_t size, const ctab_open_options* options,
                                            ctab_table** table);
CTAB_API void ctab_table_close(ctab_table* table); /* NULL is fine */

/* A blob's header (its first 64 bytes), read without loading or checksumming it. */
typedef struct ctab_blob_info {
  uint32_t format_version; /* blob layout version (this library reads CTAB_BLOB_FORMAT_VERSION) */
  uint32_t schema_version; /* table schema version of the content (this library reads CTAB_TABLE_SCHEMA_VERSION) */
  uint32_t value_bytes;    /* 8: double, 4: float (exported with --single-precision) */
  uint32_t reserved;
  uint64_t payload_bytes; /* the blob is 64 + payload_bytes long */
} ctab_blob_info;
/* CTAB_OK: this library reads that format and schema; CTAB_ERR_VERSION: it does not (*info filled in all the
 * same); CTAB_ERR_NOT_A_TABLE (no blob magic, shorter than 64 bytes), CTAB_ERR_HDF5_UNAVAILABLE (an HDF5 file),
 * CTAB_ERR_CANNOT_OPEN or CTAB_INVALID_INPUT: *info zeroed. */
CTAB_API ctab_status ctab_blob_info_memory(const void* data, size_t size, ctab_blob_info* info);
CTAB_API ctab_status ctab_blob_info_file(const char* path, ctab_blob_info* info);

/* Table description. */
CTAB_API uint32_t ctab_table_dy_count(const ctab_table* table);
CTAB_API uint32_t ctab_table_second_count(const ctab_table* table);
CTAB_API uint32_t ctab_table_slot_count(const ctab_table* table);
CTAB_API uint32_t ctab_table_strip_samples(const ctab_table* table);
CTAB_API double ctab_table_dy_min(const ctab_table* table); /* [m] */
CTAB_API double ctab_table_dy_max(const ctab_table* table); /* [m] */
CTAB_API double ctab_table_second_value(const ctab_table* table,
                                        uint32_t i); /* second axis value i; NaN if out of range */
CTAB_API const char* ctab_table_second_axis_name(
    const ctab_table* table); /* "vertical_load_N", "normal_load_N", "approach_m" */
CTAB_API size_t ctab_table_memory_bytes(const ctab_table* table);

/* Queries (no allocation, lock, system call or data-dependent time). `second` is ignored when the table has
 * one second-axis value. `wheel` is CTAB_WHEEL_RIGHT or CTAB_WHEEL_LEFT. */
CTAB_API ctab_status ctab_prelookup(const ctab_table* table, double dy_m, double second, ctab_location* out);
CTAB_API ctab_status ctab_query_prelooked(const ctab_table* table, const ctab_location* where, int32_t wheel,
                                          ctab_result* out);
CTAB_API ctab_status ctab_query(const ctab_table* table, double dy_m, double second, int32_t wheel, ctab_result* out);

/* n queries of one wheel in one call: point i is (dy_m[i], second[i]); `second` may be NULL when the table has one
 * second-axis value (otherwise every point is CTAB_INVALID_INPUT). With S = ctab_table_slot_count(table), writes
 * for each point status[i] (ctab_query's status), quantities[(i * S + s) * CTAB_QUANTITIES + q] and
 * present[i * S + s]; any output may be NULL. Returns the most severe point status (a failure before CTAB_CLAMPED
 * before CTAB_OK). */
CTAB_API ctab_status ctab_query_batch(const ctab_table* table, const double* dy_m, const double* second, size_t n,
                                      int32_t wheel, int32_t* status, double* quantities, int8_t* present);

/* Strip profile of one slot at a prelooked point: `capacity` >= ctab_table_strip_samples(); writes s [m]
 * (evenly spread over the interpolated [s_min, s_max]), half-length a(s) [m] and peak pressure p0(s) [Pa]
 * (any of the three may be NULL), and *count (the samples written; 0 where the patch is absent). Same rule as
 * the patch quantities at jumps. */
CTAB_API ctab_status ctab_strip_profile(const ctab_table* table, const ctab_location* where, int32_t wheel,
                                        int32_t slot, double* s_m, double* half_length_m, double* peak_pressure_Pa,
                                        uint32_t capacity, uint32_t* count);

/* A static English sentence for any status value (never NULL). */
CTAB_API const char* ctab_status_message(int32_t status);

/* ---- Creep forces (tangential contact) on the tabulated strips: docs/creep.md ----
 * Steady rolling, Coulomb friction, quasi-identical materials (the normal solution does not depend on the
 * tangential one). Same rules as the queries: no allocation, lock, system call or exception; time bounded by the
 * table's strip samples and the cells per strip. Frames: per patch the contact plane (x rolling direction, s as
 * the table's s, in the plane inclined by CTAB_PLANE_ANGLE_RAD, + towards the field side) and the wheel's side
 * frame (y lateral + to the field side, z vertical + down). Forces are those of the wheel on the rail. Creepages
 * are CONTACT's: (rail velocity - wheel velocity) / V at the patch's s origin; positive xi (a driving wheel) gives
 * a force on the rail < 0; spin phi [1/m] about the contact normal. */
typedef enum ctab_creep_method {
  CTAB_CREEP_STRIPS_CARTER = 0,   /* FASTSIM on the patch's own strips, each strip's force on Carter's 2-D curve
                                      (partial slip; the default: best against CONTACT, docs/creep.md) */
  CTAB_CREEP_FASTSIM_ELLIPSE = 1,  /* FASTSIM on the equivalent ellipse (Kalker 1982) */
  CTAB_CREEP_LINEAR = 2,           /* Kalker's linear theory on the equivalent ellipse (no saturation) */
  CTAB_CREEP_STRIPS = 3            /* FASTSIM on the patch's own strips, parabolic bound per strip */
} ctab_creep_method;

typedef struct ctab_creep_input {
  double xi;                /* longitudinal creepage [-] */
  double eta;               /* lateral creepage, along s [-] */
  double phi_per_m;         /* spin creepage [1/m] */
  double friction;          /* Coulomb friction coefficient mu > 0 */
  double youngs_modulus_Pa; /* both bodies; 0: 208e9 (the generator's default; use the table's attribute) */
  double poisson_ratio;     /* both bodies, in [0, 0.5); used only when youngs_modulus_Pa > 0, else 0.3 */
  int32_t method;           /* ctab_creep_method */
  int32_t cells;            /* cells per strip along x; 0: 16 (range 4..64) */
} ctab_creep_input;

typedef struct ctab_creep_patch {
  double fx_N;                /* longitudinal force on the rail [N] */
  double fs_N;                /* lateral force on the rail in the contact plane (along s) [N] */
  double mz_Nm;               /* spin moment about the s origin, sum of (x py - s px) dA [N m] */
  double force_lateral_N;     /* tangential force's lateral part in the side frame: fs cos(plane angle) [N] */
  double force_vertical_N;    /* its vertical part (+ down): fs sin(plane angle) [N] */
  double normal_force_N;      /* the normal force the solution used [N] */
  double slip_fraction;       /* share of the contact area in slip [0, 1] */
  int32_t present;            /* 1: a patch at this slot */
  int32_t status;             /* CTAB_OK, CTAB_CLAMPED, or < 0 */
} ctab_creep_patch;

typedef struct ctab_creep_result {
  int32_t status;       /* ctab_status of the call */
  int32_t n_slots;      /* slots of the table; patch[n_slots..] zero */
  double fx_N;          /* wheel totals over the present patches, side frame [N] */
  double force_lateral_N;
  double force_vertical_N;
  double mz_Nm;         /* sum of the patches' moments (each about its own s origin) [N m] */
  ctab_creep_patch patch[CTAB_MAX_SLOTS];
} ctab_creep_result;

/* Creep forces of every slot of one wheel at a prelooked point. NaN/infinite creepages, friction <= 0 or not
 * finite, a bad material, method or cell count, or a table without strip profiles or with more than 256 strip
 * samples: CTAB_INVALID_INPUT with every output zeroed. */
CTAB_API ctab_status ctab_creep_prelooked(const ctab_table* table, const ctab_location* where, int32_t wheel,
                                          const ctab_creep_input* input, ctab_creep_result* out);

/* A batch for scripting (the Python wrapper): for i < n, prelookup (dy_m[i], second[i]) and the creep forces of
 * wheel[i] with inputs[i] into out[i]. Returns the most severe status (a failure, else CTAB_CLAMPED, else
 * CTAB_OK); each out[i] has its own. */
CTAB_API ctab_status ctab_creep_batch(const ctab_table* table, size_t n, const double* dy_m, const double* second,
                                      const int32_t* wheel, const ctab_creep_input* inputs, ctab_creep_result* out);

/* One slot's creep forces with that patch's own creepages (a wheel's tread and flange patches roll at different
 * radii and contact angles). An absent slot: present 0, zeros, the query's status. */
CTAB_API ctab_status ctab_creep_slot_prelooked(const ctab_table* table, const ctab_location* where, int32_t wheel,
                                               int32_t slot, const ctab_creep_input* input, ctab_creep_patch* out);

/* The same solver on one patch given by its strips (s evenly spaced, n in 2..256): s [m], half-length a(s) [m],
 * peak pressure p0(s) [Pa] of the semi-elliptic pressure along x; normal_force_N > 0 rescales the pressure to
 * that force, 0 keeps it; plane_angle_rad for the side-frame parts. */
CTAB_API ctab_status ctab_creep_strips(const double* s_m, const double* half_length_m, const double* peak_pressure_Pa,
                                       uint32_t n, double normal_force_N, double plane_angle_rad,
                                       const ctab_creep_input* input, ctab_creep_patch* out);

/* sizeof the public struct of that name ("ctab_result", "ctab_creep_input", ...); 0 for an unknown name. For
 * bindings that mirror the structs: the Python wrapper checks its own against these when it loads the library. */
CTAB_API size_t ctab_struct_size(const char* name);

/* Kalker's linear-theory creepage coefficients C11, C22, C23, C33 (out[0..3]) for semi-axes a (rolling) and b
 * and Poisson's ratio nu (Kalker 1990, Table E.3; linear in a/b or b/a, quadratic in nu on the reciprocals;
 * ratios beyond 10 are clamped). CTAB_INVALID_INPUT on a bad argument. */
CTAB_API ctab_status ctab_kalker_coefficients(double a_m, double b_m, double poisson_ratio, double* out);

#ifdef __cplusplus
}
#endif

#endif /* CTAB_LOOKUP_H */
