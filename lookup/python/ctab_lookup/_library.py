# SPDX-License-Identifier: Apache-2.0
"""Finding and loading the C library (libctab_lookup, or libctab_lookup_hdf5 for HDF5 tables).

Where the library is looked for, first found wins:
  1. the `library` argument of Table / load_library;
  2. the CTAB_LOOKUP_LIBRARY environment variable (for HDF5 tables: CTAB_LOOKUP_HDF5_LIBRARY);
  3. next to this module (a library copied into the package directory);
  4. the installed prefix: _install.py, written by `cmake --install`, names the library directory relative to
     this package and the libraries' file names;
  5. a build tree: build/lib of the checkout this file lies in.
"""
import ctypes
import os

_HERE = os.path.dirname(os.path.abspath(__file__))
_ENV = {False: "CTAB_LOOKUP_LIBRARY", True: "CTAB_LOOKUP_HDF5_LIBRARY"}
_NAMES = {False: "libctab_lookup.so", True: "libctab_lookup_hdf5.so"}


def _installed(hdf5):
    try:
        from . import _install
    except ImportError:
        return []
    name = _install.HDF5_LIBRARY if hdf5 else _install.LIBRARY
    return [os.path.normpath(os.path.join(_HERE, _install.LIBDIR_FROM_PACKAGE, name))] if name else []


def candidates(hdf5=False):
    """The paths tried, in order (the environment variable's alone when it is set)."""
    if os.environ.get(_ENV[hdf5]):
        return [os.environ[_ENV[hdf5]]]
    name = _NAMES[hdf5]
    beside = sorted(f for f in os.listdir(_HERE) if f.startswith(name))
    return ([os.path.join(_HERE, f) for f in beside] + _installed(hdf5) +
            [os.path.normpath(os.path.join(_HERE, "..", "..", "..", "build", "lib", name))])


def find(hdf5=False):
    """The first existing candidate; OSError saying where it looked and how to point elsewhere otherwise."""
    tried = candidates(hdf5)
    for path in tried:
        if os.path.exists(path):
            return path
    what = "HDF5 tables need libctab_lookup_hdf5 (installed with ctab where HDF5 is); or export a blob " \
           "(ctab export TABLE.h5 -o TABLE.blob)" if hdf5 else "the ctab lookup library"
    raise OSError("cannot find %s; looked in: %s. Set %s=/path/to/%s.N (or pass library=...)"
                  % (what, ", ".join(tried), _ENV[hdf5], _NAMES[hdf5]))


def load(path):
    """The CDLL, with an OSError that names the override when the file cannot be loaded."""
    try:
        return ctypes.CDLL(path)
    except OSError as error:
        raise OSError("%s (set CTAB_LOOKUP_LIBRARY, or CTAB_LOOKUP_HDF5_LIBRARY for HDF5 tables, to the "
                      "library's path)" % error) from None
