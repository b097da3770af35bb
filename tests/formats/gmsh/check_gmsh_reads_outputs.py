#!/usr/bin/python3
"""Gmsh itself reads the files formats_gmsh_test wrote (GmshOutputs): every X.msh in the
directory must open with Gmsh's own reader and hold what X.summary says — the node count, the
element count of each Gmsh type, the physical groups (dim, tag, name, element count) and the
views (kind, time step, entry count, name).

usage: check_gmsh_reads_outputs.py OUTPUT_DIR
"""

import collections
import glob
import os
import sys

import gmsh


def read_summary(path):
    summary = {"nodes": 0, "elements": {}, "groups": {}, "views": {}}
    with open(path) as lines:
        for line in lines:
            words = line.rstrip("\n").split(" ")
            if words[0] == "nodes":
                summary["nodes"] = int(words[1])
            elif words[0] == "elements":
                summary["elements"][int(words[1])] = int(words[2])
            elif words[0] == "group":
                summary["groups"][(int(words[1]), int(words[2]))] = (" ".join(words[4:]),
                                                                     int(words[3]))
            elif words[0] == "view":
                summary["views"][(words[1], " ".join(words[4:]), int(words[2]))] = int(words[3])
    return summary


def what_gmsh_reads(path):
    gmsh.open(path)
    found = {"nodes": len(gmsh.model.mesh.getNodes()[0]), "elements": {}, "groups": {},
             "views": {}}
    types, tags, _ = gmsh.model.mesh.getElements()
    found["elements"] = {int(t): len(element_tags) for t, element_tags in zip(types, tags)}
    for dim, tag in gmsh.model.getPhysicalGroups():
        count = 0
        for entity in gmsh.model.getEntitiesForPhysicalGroup(dim, tag):
            count += sum(len(t) for t in gmsh.model.mesh.getElements(dim, entity)[1])
        found["groups"][(dim, tag)] = (gmsh.model.getPhysicalName(dim, tag), count)
    for view in gmsh.view.getTags():
        index = gmsh.view.getIndex(view)
        name = gmsh.option.getString(f"View[{index}].Name")
        for step in range(int(gmsh.option.getNumber(f"View[{index}].NbTimeStep"))):
            kind, data_tags, _, _, _ = gmsh.view.getModelData(view, step)
            if len(data_tags) > 0:
                found["views"][(kind, name, step)] = len(data_tags)
        gmsh.view.remove(view)
    return found


def main():
    directory = sys.argv[1]
    files = sorted(glob.glob(os.path.join(directory, "*.msh")))
    if len(files) < 12:
        print(f"expected at least 12 files in {directory}, found {len(files)}")
        return 1
    failed = 0
    for path in files:
        expected = read_summary(path[:-4] + ".summary")
        # A fresh Gmsh per file: after one failed open, Gmsh 4.8 only logs later errors.
        gmsh.initialize()
        gmsh.option.setNumber("General.Terminal", 0)
        try:
            found = what_gmsh_reads(path)
        except Exception as error:  # Gmsh raises a bare Exception
            print(f"FAIL {os.path.basename(path)}: Gmsh cannot read it: {error}")
            failed += 1
            continue
        finally:
            gmsh.finalize()
        problems = [f"{key}: expected {expected[key]}, Gmsh read {found[key]}"
                    for key in expected if expected[key] != found[key]]
        if problems:
            print(f"FAIL {os.path.basename(path)}: " + "; ".join(problems))
            failed += 1
        else:
            print(f"ok   {os.path.basename(path)}: {expected['nodes']} nodes, "
                  f"{sum(expected['elements'].values())} elements, "
                  f"{len(expected['groups'])} groups, {len(expected['views'])} views")
    print(f"{len(files) - failed} passed, {failed} failed")
    return 1 if failed else 0


sys.exit(main())
