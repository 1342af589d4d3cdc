# SPDX-License-Identifier: Apache-2.0
"""CTest: the ctypes wrapper returns the C library's results bit for bit.

    /usr/bin/python3 check_wrapper.py LIBRARY TABLE.blob RESULTS
RESULTS holds raw ctab_result records written by lookup_write_synthetic_blob for the same queries.
"""
import ctypes
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import ctab_lookup  # noqa: E402


def main():
    library, blob, results = sys.argv[1:4]
    expected = open(results, "rb").read()
    size = ctypes.sizeof(ctab_lookup._Result)
    assert len(expected) % size == 0, "record size differs: %d bytes per ctab_result in Python" % size
    count = 0
    for source in (blob, open(blob, "rb").read()):  # file and memory
        with ctab_lookup.Table(source, library=library) as table:
            assert table.n_dy == 25 and table.n_second == 3 and table.n_slots == 3, "table description"
            for i in range(261):
                for k in range(3):
                    for wheel in range(2):
                        raw = table.query_raw(-13e-3 + 0.1e-3 * i, 50e3 + 27e3 * k, wheel)
                        got = bytes(raw)
                        want = expected[count % (len(expected) // size) * size:][:size]
                        assert got == want, "query %d differs from the C result" % count
                        count += 1
            r = table.query(float("nan"), 60e3, "left")
            assert r.status == "invalid-input" and not r.patches and math.isfinite(r.roll_rad)
            r = table.query(7.2e-3, 60e3, "right")
            assert r.status == "ok" and 1 in r.patches and r.patches[1]["normal_force_N"] > 0
            s, a, p0 = table.strip_profile(2e-3, 0, 60e3)
            assert len(s) == 5 and s[0] < s[-1]
            c = table.creep(2e-3, 60e3, "right", 1e-3, 0.0, 0.0, 0.3)
            b = table.creep_batch([2e-3], 60e3, "right", 1e-3, 0.0, 0.0, 0.3)
            assert c.status == "ok" and c.patches and bytes(b["raw"][0]) == bytes(c.raw), "creep"
            c = table.creep(2e-3, 60e3, "right", math.nan, 0.0, 0.0, 0.3)
            assert c.status == "invalid-input" and not c.patches and c.fx_N == 0.0
    lib = ctab_lookup.load_library(library)  # checks every mirrored struct's size against ctab_struct_size
    assert lib.ctab_struct_size(b"ctab_creep_result") == 1064 and lib.ctab_struct_size(b"no_such_struct") == 0
    ctab_lookup._MIRRORED["ctab_creep_input"] = ctab_lookup._Patch  # a mirror of the wrong size must not load
    try:
        ctab_lookup.load_library(library)
        raise AssertionError("a struct of the wrong size must fail the load")
    except OSError as error:
        assert "ctab_creep_input is 56 bytes in the library" in str(error), str(error)
    ctab_lookup._MIRRORED["ctab_creep_input"] = ctab_lookup._creep.CreepInput
    try:
        ctab_lookup.Table("/nonexistent.blob", library=library)
        raise AssertionError("opening a missing file must fail")
    except ValueError as error:
        assert "cannot open" in str(error)
    print("ctab_lookup: %d queries bit-identical to the C library" % count)


if __name__ == "__main__":
    main()
