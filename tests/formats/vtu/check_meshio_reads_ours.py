"""meshio's VTU reader reads getme's .vtu files (written by vtu_write_samples in every layout)
with the points, cells and arrays that meshio's own VTK legacy reader finds in the .vtk files
they were converted from.

Usage: check_meshio_reads_ours.py OURS_DIR INPUT.vtk...
"""

import os
import sys

import meshio
import numpy as np

LAYOUTS = ["ascii", "inline", "inline_zlib", "appended", "appended_zlib"]


def same_values(name, ours, reference):
    ours = np.asarray(ours)
    reference = np.asarray(reference)
    assert ours.size == reference.size, f"{name}: {ours.shape} vs {reference.shape}"
    ours = ours.reshape(reference.shape)
    if reference.dtype.kind == "f" and ours.dtype != reference.dtype:
        # A legacy "float" array whose values are not all exactly floats (ASCII decimals) is
        # written as Float64 by getme, while meshio's legacy reader rounds it to float32.
        assert reference.dtype == np.float32 and ours.dtype == np.float64, name
        assert np.array_equal(ours.astype(np.float32), reference), name
    elif reference.dtype == np.bool_:
        # Legacy bit arrays are written as UInt8 0/1.
        assert ours.dtype == np.uint8 and np.array_equal(ours.astype(bool), reference), name
    else:
        assert ours.dtype == reference.dtype, f"{name}: {ours.dtype} vs {reference.dtype}"
        assert np.array_equal(ours, reference), name


checked = 0
for source in sys.argv[2:]:
    reference = meshio.read(source, file_format="vtk")
    stem = os.path.splitext(os.path.basename(source))[0]
    for layout in LAYOUTS:
        path = os.path.join(sys.argv[1], f"{stem}.{layout}.vtu")
        ours = meshio.read(path, file_format="vtu")
        where = f"{path}: "
        same_values(where + "points", ours.points, reference.points)
        assert [c.type for c in ours.cells] == [c.type for c in reference.cells], where
        for a, b in zip(ours.cells, reference.cells):
            assert np.array_equal(a.data, b.data), where + a.type
        assert sorted(ours.point_data) == sorted(reference.point_data), where
        for name, values in reference.point_data.items():
            same_values(where + name, ours.point_data[name], values)
        assert sorted(ours.cell_data) == sorted(reference.cell_data), where
        for name, blocks in reference.cell_data.items():
            same_values(where + name, np.concatenate(ours.cell_data[name]),
                        np.concatenate(blocks))
        checked += 1
print(f"meshio read {checked} getme .vtu files with the content of their sources")
