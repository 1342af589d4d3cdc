# SPDX-License-Identifier: Apache-2.0
"""Thin ctypes wrapper over the ctab lookup C API (ctab/lookup/ctab_lookup.h).

The same compiled code as a HIL target: results are those of the C library, bit for bit. Blobs load through
libctab_lookup (`ctab export FILE.h5 -o FILE.blob`), HDF5 tables through libctab_lookup_hdf5 where it is installed.
Where the libraries are looked for, and the CTAB_LOOKUP_LIBRARY override: _library.py. Installed
(`cmake --install`) into <prefix>/lib/python3/dist-packages; in a checkout, put lookup/python on sys.path:

    import ctab_lookup
    with ctab_lookup.Table("build/default_table.blob") as table:
        r = table.query(dy_m=2e-3, wheel="right")
        print(r.status, r.patches[0]["normal_force_N"])
        batch = table.query_batch(numpy.linspace(-5e-3, 5e-3, 100000))  # numpy arrays, one C call
        print(batch["normal_force_N"][:, 0])
        c = table.creep(2e-3, math.nan, "right", 1e-3, 0.0, 0.0, 0.3)  # creep forces, method="carter"
        print(c.status, c.fx_N, c.patches[0]["slip_fraction"])
"""
import ctypes
import math
import os

from . import _creep
from . import _library

MAX_SLOTS = 16
QUANTITIES = ("normal_force_N", "force_lateral_N", "force_vertical_N", "area_m2", "max_pressure_Pa", "approach_m",
              "contact_angle_rad", "plane_angle_rad", "s_origin_y_rail_m", "s_origin_z_rail_m", "y_wheel_m",
              "y_rail_m", "y_cop_rail_m", "rolling_radius_m", "semi_axis_a_m", "semi_axis_b_m", "s_min_m", "s_max_m")
STATUS = {0: "ok", 1: "clamped", -1: "invalid-input", -2: "not-loaded"}
ERR_VERSION, ERR_OUT_OF_MEMORY = -12, -17  # CTAB_ERR_VERSION, CTAB_ERR_OUT_OF_MEMORY
_HDF5_SIGNATURE = b"\x89HDF\r\n\x1a\n"
LINEAR, PCHIP = 0, 1


class _Patch(ctypes.Structure):
    _fields_ = [("q", ctypes.c_double * len(QUANTITIES)), ("present", ctypes.c_int32), ("reserved", ctypes.c_int32)]


class _Location(ctypes.Structure):
    _fields_ = [("i_dy", ctypes.c_uint32), ("i_second", ctypes.c_uint32), ("f_dy", ctypes.c_double),
                ("f_second", ctypes.c_double), ("dy_m", ctypes.c_double), ("second", ctypes.c_double),
                ("status", ctypes.c_int32), ("reserved", ctypes.c_int32)]


class _Result(ctypes.Structure):
    _fields_ = [("status", ctypes.c_int32), ("n_slots", ctypes.c_int32), ("worst_case_status", ctypes.c_int32),
                ("neighbour_status", ctypes.c_int8 * 4), ("dy_m", ctypes.c_double), ("second", ctypes.c_double),
                ("roll_rad", ctypes.c_double), ("rolling_radius_difference_m", ctypes.c_double),
                ("patch", _Patch * MAX_SLOTS)]


class _BlobInfo(ctypes.Structure):
    _fields_ = [("format_version", ctypes.c_uint32), ("schema_version", ctypes.c_uint32),
                ("value_bytes", ctypes.c_uint32), ("reserved", ctypes.c_uint32), ("payload_bytes", ctypes.c_uint64)]


class _Options(ctypes.Structure):
    _fields_ = [("interpolation", ctypes.c_int32), ("single_precision", ctypes.c_int32)]


_CreepResult = _creep.result_type(MAX_SLOTS)
CREEP_METHODS = _creep.METHODS
# The structs mirrored here and their C names: load_library checks each size against ctab_struct_size.
_MIRRORED = {"ctab_open_options": _Options, "ctab_patch": _Patch, "ctab_location": _Location, "ctab_result": _Result,
             "ctab_blob_info": _BlobInfo, "ctab_creep_input": _creep.CreepInput,
             "ctab_creep_patch": _creep.CreepPatch, "ctab_creep_result": _CreepResult}


def _check_struct_sizes(lib, path):
    if not hasattr(lib, "ctab_struct_size"):
        raise OSError("%s: no ctab_struct_size: a library older than this module" % path)
    lib.ctab_struct_size.argtypes = [ctypes.c_char_p]
    lib.ctab_struct_size.restype = ctypes.c_size_t
    for name, mirror in _MIRRORED.items():
        size = lib.ctab_struct_size(name.encode())
        if size != ctypes.sizeof(mirror):
            raise OSError("%s: %s is %d bytes in the library, %d in ctab_lookup (module and library of different "
                          "versions?)" % (path, name, size, ctypes.sizeof(mirror)))


def load_library(path=None, hdf5=False):
    """The C library with its prototypes declared: `path`, else the one _library.find(hdf5) finds."""
    path = path or _library.find(hdf5)
    lib = _library.load(path)
    _check_struct_sizes(lib, path)
    P, c = ctypes.POINTER, ctypes
    lib.ctab_table_open.argtypes = [c.c_char_p, P(_Options), P(c.c_void_p)]
    lib.ctab_table_open.restype = c.c_int
    lib.ctab_table_open_memory.argtypes = [c.c_void_p, c.c_size_t, P(_Options), P(c.c_void_p)]
    lib.ctab_table_open_memory.restype = c.c_int
    lib.ctab_table_close.argtypes = [c.c_void_p]
    lib.ctab_table_close.restype = None
    for name in ("dy_count", "second_count", "slot_count", "strip_samples"):
        getattr(lib, "ctab_table_" + name).argtypes = [c.c_void_p]
        getattr(lib, "ctab_table_" + name).restype = c.c_uint32
    for name in ("dy_min", "dy_max"):
        getattr(lib, "ctab_table_" + name).argtypes = [c.c_void_p]
        getattr(lib, "ctab_table_" + name).restype = c.c_double
    lib.ctab_table_second_value.argtypes = [c.c_void_p, c.c_uint32]
    lib.ctab_table_second_value.restype = c.c_double
    lib.ctab_table_second_axis_name.argtypes = [c.c_void_p]
    lib.ctab_table_second_axis_name.restype = c.c_char_p
    lib.ctab_table_memory_bytes.argtypes = [c.c_void_p]
    lib.ctab_table_memory_bytes.restype = c.c_size_t
    lib.ctab_prelookup.argtypes = [c.c_void_p, c.c_double, c.c_double, P(_Location)]
    lib.ctab_prelookup.restype = c.c_int
    lib.ctab_query_prelooked.argtypes = [c.c_void_p, P(_Location), c.c_int32, P(_Result)]
    lib.ctab_query_prelooked.restype = c.c_int
    lib.ctab_query.argtypes = [c.c_void_p, c.c_double, c.c_double, c.c_int32, P(_Result)]
    lib.ctab_query.restype = c.c_int
    lib.ctab_strip_profile.argtypes = [c.c_void_p, P(_Location), c.c_int32, c.c_int32, P(c.c_double), P(c.c_double),
                                       P(c.c_double), c.c_uint32, P(c.c_uint32)]
    lib.ctab_strip_profile.restype = c.c_int
    lib.ctab_status_message.argtypes = [c.c_int32]
    lib.ctab_status_message.restype = c.c_char_p
    lib.ctab_query_batch.argtypes = [c.c_void_p, c.c_void_p, c.c_void_p, c.c_size_t, c.c_int32, c.c_void_p,
                                     c.c_void_p, c.c_void_p]
    lib.ctab_query_batch.restype = c.c_int
    lib.ctab_version.argtypes = []
    lib.ctab_version.restype = c.c_char_p
    lib.ctab_blob_info_file.argtypes = [c.c_char_p, P(_BlobInfo)]
    lib.ctab_blob_info_file.restype = c.c_int
    if hasattr(lib, "ctab_table_open_hdf5"):
        lib.ctab_table_open_hdf5.argtypes = lib.ctab_table_open.argtypes
        lib.ctab_table_open_hdf5.restype = c.c_int
    _creep.declare(lib, _Location, _CreepResult)
    return lib


def version(library=None):
    """The C library's version, "MAJOR.MINOR.PATCH"."""
    return load_library(library).ctab_version().decode()


def blob_info(path, library=None):
    """A blob's header as a dict (format_version, schema_version, value_bytes, payload_bytes) and whether this
    library reads it ("readable"); ValueError for a file that is no blob."""
    lib, info = load_library(library), _BlobInfo()
    status = lib.ctab_blob_info_file(os.fsencode(path), ctypes.byref(info))
    if status not in (0, ERR_VERSION):
        raise ValueError("%s: %s" % (path, lib.ctab_status_message(status).decode()))
    return {"format_version": info.format_version, "schema_version": info.schema_version,
            "value_bytes": info.value_bytes, "payload_bytes": info.payload_bytes, "readable": status == 0}


def _is_hdf5(source):
    if isinstance(source, (bytes, bytearray)):
        return bytes(source[:8]) == _HDF5_SIGNATURE
    try:
        with open(source, "rb") as f:
            return f.read(8) == _HDF5_SIGNATURE
    except OSError:
        return False  # the C library reports it


class Result:
    """One query: status, wheelset quantities, and the present patches as dicts (slot -> quantities)."""

    def __init__(self, raw):
        self.raw = raw  # the C struct itself
        self.status = STATUS.get(raw.status, str(raw.status))
        self.dy_m, self.second = raw.dy_m, raw.second
        self.roll_rad, self.rolling_radius_difference_m = raw.roll_rad, raw.rolling_radius_difference_m
        self.neighbour_status = list(raw.neighbour_status)
        self.patches = {s: dict(zip(QUANTITIES, raw.patch[s].q))
                        for s in range(raw.n_slots) if raw.patch[s].present}


class BatchResult:
    """query_batch's answer: status (N, int32: 0 ok, 1 clamped, < 0 failed), quantities (N, slots, 18) in
    QUANTITIES order, zero where absent, present (N, slots, bool); result["normal_force_N"] is (N, slots)."""

    def __init__(self, status, quantities, present):
        self.status, self.quantities, self.present = status, quantities, present

    def __getitem__(self, name):
        return self.quantities[:, :, QUANTITIES.index(name)]


class Table:
    """A loaded table (blob file or bytes, HDF5 table file where libctab_lookup_hdf5 is installed). Use as a
    context manager or call close()."""

    def __init__(self, source, interpolation=LINEAR, single_precision=False, library=None):
        hdf5 = _is_hdf5(source)
        self._lib = load_library(library, hdf5)
        self._handle = ctypes.c_void_p()
        options = _Options(interpolation, 1 if single_precision else 0)
        if isinstance(source, (bytes, bytearray)):
            self._buffer = ctypes.create_string_buffer(bytes(source), len(source))
            status = self._lib.ctab_table_open_memory(self._buffer, len(source), options, ctypes.byref(self._handle))
        else:
            opener = getattr(self._lib, "ctab_table_open_hdf5", self._lib.ctab_table_open) if hdf5 else self._lib.ctab_table_open
            status = opener(os.fsencode(source), options, ctypes.byref(self._handle))
        if status != 0:  # out of memory (CTAB_ERR_OUT_OF_MEMORY) as Python's own MemoryError, the rest ValueError
            error = MemoryError if status == ERR_OUT_OF_MEMORY else ValueError
            raise error("%s: %s" % (source if not isinstance(source, (bytes, bytearray)) else "<bytes>",
                                    self._lib.ctab_status_message(status).decode()))
        lib, h = self._lib, self._handle
        self.n_dy, self.n_second = lib.ctab_table_dy_count(h), lib.ctab_table_second_count(h)
        self.n_slots, self.strip_samples = lib.ctab_table_slot_count(h), lib.ctab_table_strip_samples(h)
        self.dy_min_m, self.dy_max_m = lib.ctab_table_dy_min(h), lib.ctab_table_dy_max(h)
        self.second_axis = [lib.ctab_table_second_value(h, i) for i in range(self.n_second)]
        self.second_axis_name = lib.ctab_table_second_axis_name(h).decode()
        self.memory_bytes = lib.ctab_table_memory_bytes(h)

    def close(self):
        if self._handle:
            self._lib.ctab_table_close(self._handle)
            self._handle = ctypes.c_void_p()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __del__(self):
        try:
            self.close()
        except Exception:
            pass

    @staticmethod
    def _wheel(wheel):
        return {"right": 0, "left": 1, 0: 0, 1: 1}[wheel]

    def query_raw(self, dy_m, second=math.nan, wheel=0):
        """The C ctab_result struct of one query."""
        out = _Result()
        self._lib.ctab_query(self._handle, dy_m, second, self._wheel(wheel), ctypes.byref(out))
        return out

    def query(self, dy_m, second=math.nan, wheel="right"):
        """Every quantity of one wheel at (dy_m, second); `second` is ignored for a table with one value."""
        return Result(self.query_raw(dy_m, second, wheel))

    def query_batch(self, dy_m, second=None, wheel="right"):
        """N queries of one wheel in one C call (ctab_query_batch) into numpy arrays: a BatchResult. `dy_m` and
        `second` are array-likes of one shape (a scalar `second` applies to every point; None for a table with one
        second-axis value)."""
        import numpy as np
        dy = np.ascontiguousarray(dy_m, dtype=np.float64).ravel()
        n = dy.size
        sec = None if second is None else np.ascontiguousarray(np.broadcast_to(np.asarray(second, np.float64),
                                                                                 np.shape(dy_m))).ravel()
        status = np.empty(n, np.int32)
        quantities = np.empty((n, self.n_slots, len(QUANTITIES)), np.float64)
        present = np.empty((n, self.n_slots), np.int8)
        self._lib.ctab_query_batch(self._handle, dy.ctypes.data, None if sec is None else sec.ctypes.data, n,
                                   self._wheel(wheel), status.ctypes.data, quantities.ctypes.data,
                                   present.ctypes.data)
        return BatchResult(status, quantities, present.astype(bool))

    def strip_profile(self, dy_m, slot, second=math.nan, wheel="right"):
        """(s_m, half_length_m, peak_pressure_Pa) lists of one slot; empty where the patch is absent."""
        where = _Location()
        self._lib.ctab_prelookup(self._handle, dy_m, second, ctypes.byref(where))
        n = max(self.strip_samples, 1)
        s, a, p0 = (ctypes.c_double * n)(), (ctypes.c_double * n)(), (ctypes.c_double * n)()
        count = ctypes.c_uint32()
        status = self._lib.ctab_strip_profile(self._handle, ctypes.byref(where), self._wheel(wheel), slot, s, a, p0, n,
                                              ctypes.byref(count))
        if status < 0:
            raise ValueError(self._lib.ctab_status_message(status).decode())
        return list(s[:count.value]), list(a[:count.value]), list(p0[:count.value])

    def creep(self, dy_m, second, wheel, xi, eta, phi_per_m, friction, method="carter",
              youngs_modulus_Pa=_creep.DEFAULT_YOUNGS_MODULUS_PA, poisson_ratio=_creep.DEFAULT_POISSON_RATIO,
              cells=0):
        """Creep forces of every patch of one wheel at (dy_m, second) (ctab_creep_prelooked): a Creep with status,
        totals and patches. Creepages as CONTACT's (docs/creep.md); method "carter" (default), "ellipse", "linear"
        or "strips"; cells per strip 0 = 16. NaN creepages or friction <= 0: status "invalid-input", zeros."""
        where, out = _Location(), _CreepResult()
        self._lib.ctab_prelookup(self._handle, dy_m, second, ctypes.byref(where))
        given = _creep.make_input(xi, eta, phi_per_m, friction, method, youngs_modulus_Pa, poisson_ratio, cells)
        self._lib.ctab_creep_prelooked(self._handle, ctypes.byref(where), self._wheel(wheel), ctypes.byref(given),
                                       ctypes.byref(out))
        return _creep.Creep(out, STATUS)

    def creep_batch(self, dy_m, second, wheel, xi, eta, phi_per_m, friction, method="carter",
                    youngs_modulus_Pa=_creep.DEFAULT_YOUNGS_MODULUS_PA, poisson_ratio=_creep.DEFAULT_POISSON_RATIO,
                    cells=0):
        """N creep calls in one C call (ctab_creep_batch); array-likes broadcast together (`wheel` "right",
        "left", 0, 1 or an int array). A dict of numpy arrays: "status" (N), the totals "fx_N", "force_lateral_N",
        "force_vertical_N", "mz_Nm" (N), per slot "slot_fx_N", "slot_fs_N", ..., "present", "slot_status"
        (N, slots), and "raw" (the C structs)."""
        wheel = self._wheel(wheel) if isinstance(wheel, (str, int)) else wheel
        return _creep.run_batch(self._lib, self._handle, _CreepResult, self.n_slots, dy_m, second, wheel,
                                (xi, eta, phi_per_m, friction), (method, youngs_modulus_Pa, poisson_ratio, cells))
