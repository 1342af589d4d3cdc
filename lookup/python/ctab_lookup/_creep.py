# SPDX-License-Identifier: Apache-2.0
"""Creep forces through the C API's creep section (ctab_creep_prelooked, ctab_creep_batch): the structs mirrored
with ctypes, the method names, and the conversion of the C results into dicts and numpy arrays. Table.creep and
Table.creep_batch (__init__.py) call these; docs/creep.md describes the solver, its frames and signs."""
import ctypes

METHODS = {"carter": 0, "ellipse": 1, "linear": 2, "strips": 3}  # ctab_creep_method
PATCH_FIELDS = ("fx_N", "fs_N", "mz_Nm", "force_lateral_N", "force_vertical_N", "normal_force_N", "slip_fraction")
TOTALS = ("fx_N", "force_lateral_N", "force_vertical_N", "mz_Nm")
DEFAULT_YOUNGS_MODULUS_PA, DEFAULT_POISSON_RATIO = 208e9, 0.3  # the generator's defaults, as `ctab query`'s


class CreepInput(ctypes.Structure):
    _fields_ = [("xi", ctypes.c_double), ("eta", ctypes.c_double), ("phi_per_m", ctypes.c_double),
                ("friction", ctypes.c_double), ("youngs_modulus_Pa", ctypes.c_double),
                ("poisson_ratio", ctypes.c_double), ("method", ctypes.c_int32), ("cells", ctypes.c_int32)]


class CreepPatch(ctypes.Structure):
    _fields_ = [(name, ctypes.c_double) for name in PATCH_FIELDS] + [("present", ctypes.c_int32),
                                                                     ("status", ctypes.c_int32)]


def result_type(max_slots):
    """The ctab_creep_result struct for CTAB_MAX_SLOTS = max_slots."""
    class CreepResult(ctypes.Structure):
        _fields_ = [("status", ctypes.c_int32), ("n_slots", ctypes.c_int32)] + \
                   [(name, ctypes.c_double) for name in TOTALS] + [("patch", CreepPatch * max_slots)]
    return CreepResult


def declare(lib, location, result):
    """Prototypes of the creep functions; `location` is the ctab_location struct."""
    P, c = ctypes.POINTER, ctypes
    lib.ctab_creep_prelooked.argtypes = [c.c_void_p, P(location), c.c_int32, P(CreepInput), P(result)]
    lib.ctab_creep_prelooked.restype = c.c_int
    lib.ctab_creep_batch.argtypes = [c.c_void_p, c.c_size_t, c.c_void_p, c.c_void_p, c.c_void_p, c.c_void_p,
                                     c.c_void_p]
    lib.ctab_creep_batch.restype = c.c_int


def method_value(method):
    """A method's ctab_creep_method value from its name ("carter", "ellipse", "linear", "strips") or value."""
    if method in METHODS.values():
        return method
    if method not in METHODS:
        raise ValueError("creep method %r: one of %s" % (method, ", ".join(METHODS)))
    return METHODS[method]


def make_input(xi, eta, phi_per_m, friction, method, youngs_modulus_Pa, poisson_ratio, cells):
    return CreepInput(xi, eta, phi_per_m, friction, youngs_modulus_Pa, poisson_ratio, method_value(method), cells)


class Creep:
    """One wheel's creep forces: status ("ok", "clamped", "invalid-input", ...), the wheel totals (fx_N,
    force_lateral_N, force_vertical_N, mz_Nm) and `patches` = {slot: {field: value, "status": int}} of the present
    patches; `raw` is the C struct."""

    def __init__(self, raw, status_names):
        self.raw = raw
        self.status = status_names.get(raw.status, str(raw.status))
        for name in TOTALS:
            setattr(self, name, getattr(raw, name))
        self.patches = {s: dict({f: getattr(raw.patch[s], f) for f in PATCH_FIELDS}, status=raw.patch[s].status)
                        for s in range(raw.n_slots) if raw.patch[s].present}


def run_batch(lib, handle, result, n_slots, dy_m, second, wheel, creepage, options):
    """ctab_creep_batch over broadcast arrays: a dict of numpy arrays. `creepage` = (xi, eta, phi_per_m, friction)
    array-likes; `options` = (method, youngs_modulus_Pa, poisson_ratio, cells)."""
    import numpy as np
    arrays = np.broadcast_arrays(*(np.asarray(a, np.float64) for a in (dy_m, second) + tuple(creepage)),
                                 np.asarray(wheel, np.int32))
    shape = arrays[0].shape
    n = arrays[0].size
    inputs = np.zeros(n, np.dtype(CreepInput))
    for name, values in zip(("xi", "eta", "phi_per_m", "friction"), arrays[2:6]):
        inputs[name] = values.ravel()
    method, youngs_modulus_Pa, poisson_ratio, cells = options
    inputs["youngs_modulus_Pa"], inputs["poisson_ratio"] = youngs_modulus_Pa, poisson_ratio
    inputs["method"], inputs["cells"] = method_value(method), cells
    dy, sec = (np.ascontiguousarray(a.ravel()) for a in arrays[:2])
    wheels = np.ascontiguousarray(arrays[6].ravel())
    out = np.zeros(n, np.dtype(result))
    lib.ctab_creep_batch(handle, n, dy.ctypes.data, sec.ctypes.data, wheels.ctypes.data, inputs.ctypes.data,
                         out.ctypes.data)
    patch = out["patch"][:, :n_slots]
    answer = {"status": out["status"].reshape(shape), "present": patch["present"].astype(bool).reshape(shape + (-1,)),
              "slot_status": patch["status"].reshape(shape + (-1,)), "raw": out}
    answer.update({name: out[name].reshape(shape) for name in TOTALS})
    answer.update({"slot_" + name: patch[name].reshape(shape + (-1,)) for name in PATCH_FIELDS})
    return answer
