#!/usr/bin/env python3
"""Seed corpora and a dictionary for the fuzz harnesses (run.sh calls it).

  make_corpus.py OUT   writes OUT/fuzz_scene/ (every shipped scene, the test scenes of
  tests/data, tiny_run.toml), OUT/fuzz_overrides/ (one `--set` per key of every shipped scene,
  on that scene; fuzz_overrides.cpp's input format), OUT/fuzz_initial_file/ and OUT/fuzz_resume/
  (a few edit lists) and OUT/scene.dict (every key and section name, for libFuzzer's -dict).
"""
import hashlib
import os
import random
import sys
import tomllib

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
SCENES = os.path.join(ROOT, "scenarios", "scenes")


def toml_value(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (int, float)):
        return repr(v)
    if isinstance(v, str):
        return '"' + v.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if isinstance(v, list):
        return "[" + ", ".join(toml_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{ " + ", ".join(f"{k} = {toml_value(x)}" for k, x in v.items()) + " }"
    return repr(v)


def leaves(table, path=""):
    """(dotted key, value) of every value, arrays of tables by index, and every table whole."""
    for k, v in table.items():
        key = f"{path}.{k}" if path else k
        if isinstance(v, dict):
            yield key, v
            yield from leaves(v, key)
        elif isinstance(v, list) and v and all(isinstance(x, dict) for x in v):
            for i, x in enumerate(v):
                yield from leaves(x, f"{key}.{i}")
        else:
            yield key, v


def names(table, found):
    for k, v in table.items():
        found.add(k)
        if isinstance(v, dict):
            names(v, found)
        elif isinstance(v, list):
            for x in v:
                if isinstance(x, dict):
                    names(x, found)


def write(folder, data):
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, hashlib.sha1(data).hexdigest()), "wb") as f:
        f.write(data)


def main(out):
    scene_files = sorted(os.path.join(SCENES, f) for f in os.listdir(SCENES) if f.endswith(".toml"))
    data = os.path.join(ROOT, "tests", "data")
    test_files = [os.path.join(d, f) for d, _, fs in os.walk(data) for f in fs if f.endswith(".toml")]
    keys = set()
    for path in scene_files + sorted(test_files) + [os.path.join(HERE, "tiny_run.toml")]:
        text = open(path, "rb").read()
        write(os.path.join(out, "fuzz_scene"), text)
        names(tomllib.loads(text.decode()), keys)
    # fuzz_overrides: the first byte picks the base scene in the harness's order (sorted paths,
    # sweep files left out).
    bases = [p for p in scene_files if "sweep" not in os.path.basename(p)]
    for index, path in enumerate(bases):
        table = tomllib.load(open(path, "rb"))
        for key, value in leaves(table):
            write(os.path.join(out, "fuzz_overrides"), bytes([index]) + f"{key}={toml_value(value)}\n".encode())
        write(os.path.join(out, "fuzz_overrides"), bytes([index]) + b"--seed 7\ntime.end=0.001\n")
    rng = random.Random(1)
    for n in (0, 1, 2, 8, 32, 128):
        write(os.path.join(out, "fuzz_initial_file"), bytes(rng.randrange(256) for _ in range(n)) + bytes([n]))
    # fuzz_resume: edit lists too (the harness makes its seed runs itself); the short ones pick
    # a seed run and a resume length with few or no edits, the long ones edit both files.
    for n in (0, 1, 2, 3, 4, 8, 16, 32, 64, 128, 200):
        write(os.path.join(out, "fuzz_resume"), bytes(rng.randrange(256) for _ in range(n)) + bytes([n]))
    with open(os.path.join(out, "scene.dict"), "w") as f:
        for k in sorted(keys):
            f.write(f'"{k}"\n')
        for token in ["[[", "]]", " = ", "{ ", " }", "true", "false", "inf", "nan", "-inf", "1e308", "5e-324",
                      "\"\"\"", "'''", "0x", "1979-05-27T07:32:00Z"]:
            f.write('"' + token.replace("\\", "\\\\").replace('"', '\\"') + '"\n')


if __name__ == "__main__":
    main(sys.argv[1])
