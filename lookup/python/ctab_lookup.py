"""Thin ctypes wrapper over the ctab lookup C API (lookup/include/ctab/lookup/ctab_lookup.h).

The same compiled code as a HIL target: results are those of the C library, bit for bit. The shared library
(build/lib/libctab_lookup.so, CMake target ctab_lookup_shared) loads blobs (`ctab export FILE.h5 -o FILE.blob`);
it is found through the path argument, else the CTAB_LOOKUP_LIBRARY environment variable, else
../../build/lib/libctab_lookup.so next to this file. No installation needed:

    import sys; sys.path.insert(0, "lookup/python")
    import ctab_lookup
    with ctab_lookup.Table("build/default_table.blob") as table:
        r = table.query(dy_m=2e-3, wheel="right")
        print(r.status, r.patches[0]["normal_force_N"])
"""
import ctypes
import math
import os

MAX_SLOTS = 16
QUANTITIES = ("normal_force_N", "force_lateral_N", "force_vertical_N", "area_m2", "max_pressure_Pa", "approach_m",
              "contact_angle_rad", "plane_angle_rad", "s_origin_y_rail_m", "s_origin_z_rail_m", "y_wheel_m",
              "y_rail_m", "y_cop_rail_m", "rolling_radius_m", "semi_axis_a_m", "semi_axis_b_m", "s_min_m", "s_max_m")
STATUS = {0: "ok", 1: "clamped", -1: "invalid-input", -2: "not-loaded"}
ERR_OUT_OF_MEMORY = -17  # CTAB_ERR_OUT_OF_MEMORY
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


class _Options(ctypes.Structure):
    _fields_ = [("interpolation", ctypes.c_int32), ("single_precision", ctypes.c_int32)]


def _default_library():
    here = os.path.dirname(os.path.abspath(__file__))
    return os.environ.get("CTAB_LOOKUP_LIBRARY", os.path.join(here, "..", "..", "build", "lib", "libctab_lookup.so"))


def load_library(path=None):
    """The C library with its prototypes declared."""
    lib = ctypes.CDLL(path or _default_library())
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
    return lib


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


class Table:
    """A loaded table (blob file or bytes). Use as a context manager or call close()."""

    def __init__(self, source, interpolation=LINEAR, single_precision=False, library=None):
        self._lib = load_library(library)
        self._handle = ctypes.c_void_p()
        options = _Options(interpolation, 1 if single_precision else 0)
        if isinstance(source, (bytes, bytearray)):
            self._buffer = ctypes.create_string_buffer(bytes(source), len(source))
            status = self._lib.ctab_table_open_memory(self._buffer, len(source), options, ctypes.byref(self._handle))
        else:
            status = self._lib.ctab_table_open(os.fsencode(source), options, ctypes.byref(self._handle))
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
