#!/usr/bin/python3
"""Compares, with netCDF's own `ncdump` (Debian netcdf-bin), the Exodus variables of an input
written by write_fixtures.py (NAME.exo) and of getme's copy of it (ours_NAME.exo, written by
formats_exodus_test): every one of coordinates, connectivity with its element type, block/set ids
and names, side set elements and sides, node sets and number maps that the input has must be in
the copy and print identically. This judges the
written file at the netCDF level, below both the Exodus library and meshio.

Usage: check_with_ncdump.py FIXTURE_DIR NAME...
"""

import re
import subprocess
import sys

VARIABLES = ["coordx", "coordy", "coordz", "eb_prop1", "eb_names", "ss_prop1", "ss_names",
             "ns_prop1", "ns_names", "node_num_map", "elem_num_map"]
NUMBERED = ["connect", "elem_ss", "side_ss", "node_ns"]


def dump(path, variable):
    """The data of one variable as `ncdump -v` prints it, and its elem_type attribute if any."""
    text = subprocess.run(["ncdump", "-v", variable, path], check=True, capture_output=True,
                          text=True).stdout
    data = text[text.index(f" {variable} =", text.index("data:")):].rstrip("}\n ")
    elem_type = re.findall(variable + r':elem_type = "([^"]*)"', text)
    return data, elem_type


def variables_of(path):
    header = subprocess.run(["ncdump", "-h", path], check=True, capture_output=True,
                            text=True).stdout
    present = set(re.findall(r"^\s+\w+ (\w+)\(", header, re.MULTILINE))
    names = [v for v in VARIABLES if v in present]
    for prefix in NUMBERED:
        names += sorted((v for v in present if re.fullmatch(prefix + r"\d+", v)),
                        key=lambda v: int(v[len(prefix):]))
    return names


def main():
    directory = sys.argv[1]
    failed = False
    for name in sys.argv[2:]:
        source, ours = f"{directory}/{name}.exo", f"{directory}/ours_{name}.exo"
        wanted = variables_of(source)
        present = variables_of(ours)
        problems = [f"{v} missing" for v in wanted if v not in present]
        problems += [f"{v} differs" for v in wanted
                     if v in present and dump(source, v) != dump(ours, v)]
        print(f"{name}: {'ok (' + ', '.join(wanted) + ')' if not problems else '; '.join(problems)}")
        failed |= bool(problems)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
