#!/usr/bin/python3
"""Bit-for-bit comparison of two carom output directories (a refactor changes no result).

    /usr/bin/python3 tests/bench/compare_runs.py OLD_DIR NEW_DIR [OLD_DIR2 NEW_DIR2 ...]

Compares every dataset (values and shape, as raw bytes) and every attribute of run.h5, except
the root attributes carom_version and run_id (drawn at random for every run, so that a resume
can tell its own run's files), and report.md byte for byte. Prints one line per pair and the
first differences; exits 1 if any pair differs.
"""
import sys

import h5py
import numpy as np

IGNORED_ATTRIBUTES = {("/", "carom_version"), ("/", "run_id")}


def same(a, b):
    a, b = np.asarray(a), np.asarray(b)
    return a.shape == b.shape and a.dtype == b.dtype and a.tobytes() == b.tobytes()


def compare_h5(path_a, path_b):
    problems = []
    with h5py.File(path_a, "r") as fa, h5py.File(path_b, "r") as fb:
        names_a, names_b = [], []
        fa.visit(names_a.append)
        fb.visit(names_b.append)
        if sorted(names_a) != sorted(names_b):
            problems.append("objects differ: only old %s, only new %s"
                            % (sorted(set(names_a) - set(names_b))[:5], sorted(set(names_b) - set(names_a))[:5]))
        for name in ["/"] + sorted(set(names_a) & set(names_b)):
            oa, ob = fa[name], fb[name]
            keys = (set(oa.attrs) | set(ob.attrs))
            for key in sorted(keys):
                if (name, key) in IGNORED_ATTRIBUTES:
                    continue
                if key not in oa.attrs or key not in ob.attrs or not same(oa.attrs[key], ob.attrs[key]):
                    problems.append("%s attribute %s differs" % (name, key))
            if isinstance(oa, h5py.Dataset):
                if not isinstance(ob, h5py.Dataset) or not same(oa[()], ob[()]):
                    problems.append("%s differs" % name)
    return problems, len(names_a)


def main(argv):
    if len(argv) < 2 or len(argv) % 2:
        print(__doc__)
        return 2
    failed = False
    for old, new in zip(argv[0::2], argv[1::2]):
        problems, count = compare_h5(old + "/run.h5", new + "/run.h5")
        with open(old + "/report.md", "rb") as a, open(new + "/report.md", "rb") as b:
            if a.read() != b.read():
                problems.append("report.md differs")
        status = "identical" if not problems else "DIFFERENT"
        print("%s: %s (%d objects in run.h5, report.md)" % (new, status, count))
        for p in problems[:10]:
            print("   ", p)
        failed |= bool(problems)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
