"""Writes .vtu inputs for formats_vtu_test with writers other than getme's, and beside each a
sidecar <file>.expected holding what the file contains, found independently of getme's reader.

- meshio's own VTU writer (meshio 7): a hybrid mesh (tetra, hexahedron, pyramid, wedge, triangle,
  quad) with point and cell data, as ASCII, base64 binary, zlib-compressed, with UInt32 and
  UInt64 headers, and as lzma (which getme must refuse by name); one regular element of each
  volume type, given to meshio in its own (Gmsh) node order.
- Files assembled here with Python's struct, base64 and zlib by the VTK XML file format
  documentation, for what meshio does not write: BigEndian, several zlib blocks, appended raw
  and appended base64 data, several pieces, field data, attribute roles.

Sidecar format, whitespace-separated:
  points N            then N lines "x y z" (float.hex)
  cells M             then M lines "vtk_type k id_1 .. id_k" (VTK node order)
  array WHERE NAME TYPE COMPONENTS TUPLES KEYWORD   (WHERE: point, cell or field; KEYWORD: the
                      legacy section getme must file it under) then one line of values
                      (integers in decimal, reals as float.hex)
Values: from meshio.read() for binary files (asserted equal to what was written) and from the
DataArray text parsed with ElementTree and float() for ASCII files, whose decimals are what the
file holds.

Usage: write_vtu_fixtures.py OUTPUT_DIR
"""

import base64
import math
import os
import struct
import sys
import xml.etree.ElementTree as ET
import zlib

import meshio
import numpy as np

OUT = sys.argv[1]
os.makedirs(OUT, exist_ok=True)

# vtkCellType.h codes of the meshio cell types used here.
VTK_CODE = {"vertex": 1, "line": 3, "triangle": 5, "quad": 9, "tetra": 10, "hexahedron": 12,
            "wedge": 13, "pyramid": 14}
# meshio's wedge is Gmsh's prism; VTK's wedge lists the first triangle the other way round
# (VTK file formats documentation, Figure 2). Every other type used here has one order.
WEDGE_TO_VTK = [0, 2, 1, 3, 5, 4]
XML_TYPE = {np.dtype(t): n for t, n in [
    (np.int8, "Int8"), (np.uint8, "UInt8"), (np.int16, "Int16"), (np.uint16, "UInt16"),
    (np.int32, "Int32"), (np.uint32, "UInt32"), (np.int64, "Int64"), (np.uint64, "UInt64"),
    (np.float32, "Float32"), (np.float64, "Float64")]}


def value_text(values):
    flat = np.asarray(values).reshape(-1)
    if flat.dtype.kind == "f":
        return " ".join(float(v).hex() for v in flat)
    return " ".join(str(int(v)) for v in flat)


def write_sidecar(path, points, cells, arrays):
    """cells: [(vtk_code, [ids])]; arrays: [(where, name, xml_type, components, values, keyword)]."""
    with open(path + ".expected", "w") as f:
        f.write(f"points {len(points)}\n")
        for p in points:
            f.write(" ".join(float(c).hex() for c in p) + "\n")
        f.write(f"cells {len(cells)}\n")
        for code, ids in cells:
            f.write(f"{code} {len(ids)} {' '.join(str(int(i)) for i in ids)}\n")
        for where, name, xml_type, components, values, keyword in arrays:
            flat = np.asarray(values).reshape(-1)
            f.write(f"array {where} {name} {xml_type} {components} {len(flat) // components} "
                    f"{keyword}\n{value_text(flat)}\n")


def cells_in_vtk_order(mesh):
    cells = []
    for block in mesh.cells:
        for ids in block.data:
            ids = list(ids)
            if block.type == "wedge":
                ids = [ids[i] for i in WEDGE_TO_VTK]
            cells.append((VTK_CODE[block.type], ids))
    return cells


def ascii_values(path):
    """DataArray name -> values parsed from its text with float() / int(), per XML type."""
    values = {}
    for array in ET.parse(path).getroot().iter("DataArray"):
        tokens = array.text.split() if array.text else []
        integer = not array.get("type").startswith("Float")
        values[array.get("Name")] = np.array(
            [int(t) for t in tokens] if integer else [float(t) for t in tokens],
            dtype=np.int64 if integer else np.float64)
    return values


# ---- meshio: a hybrid mesh ----

rng = np.random.default_rng(20240611)
points = rng.uniform(-2.0, 3.0, size=(16, 3))
hybrid_cells = [
    ("tetra", [[0, 1, 2, 3], [4, 5, 6, 7]]),
    ("hexahedron", [[0, 1, 2, 3, 4, 5, 6, 7]]),
    ("pyramid", [[8, 9, 10, 11, 12]]),
    ("wedge", [[10, 11, 12, 13, 14, 15], [0, 2, 4, 6, 8, 10]]),
    ("triangle", [[1, 3, 5], [7, 9, 11]]),
    ("quad", [[12, 13, 14, 15]]),
]
cell_blocks = [(t, np.array(c, dtype=np.int64)) for t, c in hybrid_cells]
block_sizes = [len(c) for _, c in hybrid_cells]
cell_count = sum(block_sizes)
point_data = {
    "temperature": rng.normal(size=16),
    "velocity": rng.normal(size=(16, 3)),
    "flag": (np.arange(16) % 3).astype(np.int32),
    "weights": rng.normal(size=(16, 2)).astype(np.float32),
}
cell_values = {
    "material": np.arange(cell_count, dtype=np.int32) * 7 - 20,
    "quality": rng.uniform(size=cell_count).astype(np.float32),
    "big": (np.arange(cell_count, dtype=np.int64) - 4) * (1 << 40),
    "tag": np.arange(cell_count, dtype=np.uint8) + 200,
}
cell_data = {}
for name, values in cell_values.items():
    split = np.split(values, np.cumsum(block_sizes)[:-1])
    cell_data[name] = split

variants = {
    "meshio_ascii": dict(binary=False),
    "meshio_binary": dict(binary=True, compression=None),
    "meshio_binary_uint64": dict(binary=True, compression=None, header_type="UInt64"),
    "meshio_zlib": dict(binary=True, compression="zlib"),
    "meshio_zlib_uint64": dict(binary=True, compression="zlib", header_type="UInt64"),
    "meshio_lzma": dict(binary=True, compression="lzma"),
}
for stem, options in variants.items():
    path = os.path.join(OUT, stem + ".vtu")
    mesh = meshio.Mesh(points, [(t, c.copy()) for t, c in cell_blocks],
                       point_data={k: v.copy() for k, v in point_data.items()},
                       cell_data={k: [b.copy() for b in v] for k, v in cell_data.items()})
    meshio.write(path, mesh, file_format="vtu", **options)
    if stem == "meshio_lzma":
        continue
    back = meshio.read(path)
    cells = cells_in_vtk_order(back)
    assert cells == [(VTK_CODE[t], list(ids) if t != "wedge" else [ids[i] for i in WEDGE_TO_VTK])
                     for t, block in hybrid_cells for ids in block]
    arrays = []
    if options["binary"]:
        assert np.array_equal(back.points, points)
        read_points = back.points
        for name, values in point_data.items():
            assert np.array_equal(back.point_data[name], values) and \
                back.point_data[name].dtype == values.dtype
            arrays.append(("point", name, XML_TYPE[values.dtype],
                           1 if values.ndim == 1 else values.shape[1], values, "FIELD"))
        for name, values in cell_values.items():
            read = np.concatenate(back.cell_data[name])
            assert np.array_equal(read, values) and read.dtype == values.dtype
            arrays.append(("cell", name, XML_TYPE[values.dtype], 1, read, "FIELD"))
    else:
        text = ascii_values(path)
        read_points = text["Points"].reshape(-1, 3)
        assert np.allclose(read_points, points, rtol=1e-10, atol=0)
        for name, values in point_data.items():
            assert np.allclose(text[name], values.reshape(-1), rtol=1e-6)
            arrays.append(("point", name, XML_TYPE[values.dtype],
                           1 if values.ndim == 1 else values.shape[1], text[name], "FIELD"))
        for name, values in cell_values.items():
            assert np.allclose(text[name], values, rtol=1e-6)
            arrays.append(("cell", name, XML_TYPE[values.dtype], 1, text[name], "FIELD"))
    write_sidecar(path, read_points, cells, arrays)

# ---- meshio: one regular element of each volume type, unit edges, in meshio's (Gmsh's) order,
# oriented as the paper's Fig. 1 (docs/node-orders.md) ----

s3 = math.sqrt(3.0)
regular = {
    "tetra": [[0, 0, 0], [1, 0, 0], [0.5, s3 / 2, 0], [0.5, s3 / 6, math.sqrt(2.0 / 3.0)]],
    "hexahedron": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0],
                   [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]],
    "pyramid": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0.5, 0.5, math.sqrt(2.0) / 2]],
    "wedge": [[0, 0, 0], [1, 0, 0], [0.5, s3 / 2, 0], [0, 0, 1], [1, 0, 1], [0.5, s3 / 2, 1]],
}
for cell_type, coordinates in regular.items():
    for binary in (False, True):
        path = os.path.join(OUT, f"regular_{cell_type}_{'binary' if binary else 'ascii'}.vtu")
        mesh = meshio.Mesh(np.array(coordinates, dtype=np.float64),
                           [(cell_type, np.arange(len(coordinates))[None, :])])
        meshio.write(path, mesh, file_format="vtu", binary=binary, compression=None)

# ---- Assembled by hand (VTK XML file format documentation) ----


def pack(order, fmt, values):
    return struct.pack(order + fmt * len(values), *values)


def header_block(order, header_fmt, data):
    """Uncompressed binary array: the byte count, then the data."""
    return struct.pack(order + header_fmt, len(data)) + data


def zlib_block(order, header_fmt, data, block_size):
    blocks = [data[i:i + block_size] for i in range(0, len(data), block_size)]
    compressed = [zlib.compress(b) for b in blocks]
    last = len(data) % block_size
    header = struct.pack(order + header_fmt * (3 + len(blocks)), len(blocks), block_size, last,
                         *[len(c) for c in compressed])
    return header, b"".join(compressed)


# A tetra, a wedge and a triangle (VTK order) on 10 points, exact binary fractions; the tetra
# uses points 0-3 only, so the file with two pieces can split there.
tet_points = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0],
              [0.0, 0.0, 2.0], [0.0, 1.0, 2.0], [1.0, 0.0, 2.0],
              [0.0, 0.0, 3.5], [0.0, 1.0, 3.5], [1.0, 0.0, 3.5]]
hand_cells = [(10, [0, 1, 2, 3]), (13, [4, 5, 6, 7, 8, 9]), (5, [7, 8, 9])]
connectivity = [i for _, ids in hand_cells for i in ids]
types = [code for code, _ in hand_cells]
# (name, struct format, XML type, components, values, role attribute or None, legacy keyword)
hand_point_arrays = [
    ("pressure", "d", "Float64", 1, [0.5 * i - 1 for i in range(10)], "Scalars", "SCALARS"),
    ("small", "b", "Int8", 1, [-128, -1, 0, 1, 2, 3, 127, 4, 5, 6], None, "SCALARS"),
    ("flow", "f", "Float32", 3, [0.25 * i for i in range(30)], "Vectors", "VECTORS"),
    ("wide", "H", "UInt16", 2, [65535] + list(range(19)), None, "SCALARS"),
    ("huge", "Q", "UInt64", 1, [2 ** 64 - 1, 2 ** 63] + list(range(8)), None, "SCALARS"),
    ("many", "i", "Int32", 6, list(range(-30, 30)), None, "FIELD"),
]
hand_cell_arrays = [
    ("ids", "q", "Int64", 1, [-(2 ** 63), 7, 2 ** 63 - 1], "GlobalIds", "GLOBAL_IDS"),
    ("short", "h", "Int16", 1, [-32768, 0, 32767], None, "FIELD"),
    ("level", "I", "UInt32", 1, [4294967295, 1, 2], "Scalars", "SCALARS"),
]
hand_field_arrays = [("time", "d", "Float64", 1, [1.5, 2.5]), ("step", "B", "UInt8", 1, [3, 9, 27])]


def expected_arrays():
    arrays = []
    for where, group in (("point", hand_point_arrays), ("cell", hand_cell_arrays)):
        for name, _, xml_type, components, values, _, keyword in group:
            arrays.append((where, name, xml_type, components,
                           np.array(values, dtype=np.float64 if xml_type.startswith("Float")
                                    else object), keyword))
    for name, _, xml_type, components, values in hand_field_arrays:
        arrays.append(("field", name, xml_type, components,
                       np.array(values, dtype=np.float64 if xml_type.startswith("Float")
                                else object), "FIELD"))
    return arrays


def roles(group):
    return "".join(f' {role}="{name}"' for name, _, _, _, _, role, _ in group if role)


def hand_file(path, order_name, header_type, encode, pieces=1, version="1.0", compressor=None):
    """encode(data_bytes) -> (format attribute text, inline text or None, appended bytes)."""
    order = ">" if order_name == "BigEndian" else "<"
    appended = bytearray()

    def data_array(name, fmt, xml_type, components, values, extra=""):
        raw = pack(order, fmt, values)
        fmt_attr, inline, blob = encode(order, raw, len(appended))
        appended.extend(blob)
        text = f'<DataArray type="{xml_type}" Name="{name}" NumberOfComponents="{components}"' \
               f'{extra} {fmt_attr}>'
        return text + (inline or "") + "</DataArray>\n" if inline is not None else \
            text[:-1] + "/>\n"

    body = ['<?xml version="1.0"?>\n<!-- assembled by write_vtu_fixtures.py -->\n',
            f'<VTKFile type="UnstructuredGrid" version="{version}" byte_order="{order_name}"'
            + (f' header_type="{header_type}"' if header_type else "")
            + (f' compressor="{compressor}"' if compressor else "") + ">\n<UnstructuredGrid>\n"]
    body.append("<FieldData>\n")
    for name, fmt, xml_type, components, values in hand_field_arrays:
        body.append(data_array(name, fmt, xml_type, components, values,
                               f' NumberOfTuples="{len(values)}"'))
    body.append("</FieldData>\n")
    # Several pieces split the points and cells; point and cell data split the same way.
    point_splits = [(0, 10)] if pieces == 1 else [(0, 4), (4, 10)]
    cell_splits = [(0, 3)] if pieces == 1 else [(0, 1), (1, 3)]
    for (p0, p1), (c0, c1) in zip(point_splits, cell_splits):
        body.append(f'<Piece NumberOfPoints="{p1 - p0}" NumberOfCells="{c1 - c0}">\n')
        body.append(f"<PointData{roles(hand_point_arrays)}>\n")
        for name, fmt, xml_type, components, values, _, _ in hand_point_arrays:
            body.append(data_array(name, fmt, xml_type, components,
                                   values[p0 * components:p1 * components]))
        body.append(f"</PointData>\n<CellData{roles(hand_cell_arrays)}>\n")
        for name, fmt, xml_type, components, values, _, _ in hand_cell_arrays:
            body.append(data_array(name, fmt, xml_type, components, values[c0:c1]))
        body.append("</CellData>\n<Points>\n")
        body.append(data_array("Points", "f", "Float32", 3,
                               [c for p in tet_points[p0:p1] for c in p]))
        body.append("</Points>\n<Cells>\n")
        local = [[i - p0 for i in ids] for _, ids in hand_cells[c0:c1]]
        body.append(data_array("connectivity", "i", "Int32", 1, [i for ids in local for i in ids]))
        body.append(data_array("offsets", "q", "Int64", 1,
                               list(np.cumsum([len(ids) for ids in local]))))
        body.append(data_array("types", "B", "UInt8", 1, types[c0:c1]))
        body.append("</Cells>\n</Piece>\n")
    body.append("</UnstructuredGrid>\n")
    text = "".join(body).encode()
    if encode.appended_encoding:
        blob = bytes(appended)
        text += (f'<AppendedData encoding="{encode.appended_encoding}">\n_').encode() + blob + \
            b"\n</AppendedData>\n"
    text += b"</VTKFile>\n"
    with open(path, "wb") as f:
        f.write(text)
    write_sidecar(path, tet_points, hand_cells, expected_arrays())


def inline_uncompressed(header_fmt):
    def encode(order, raw, _):
        return 'format="binary"', base64.b64encode(header_block(order, header_fmt, raw)).decode(), b""
    encode.appended_encoding = None
    return encode


def inline_zlib(header_fmt, block_size):
    def encode(order, raw, _):
        header, data = zlib_block(order, header_fmt, raw, block_size)
        # VTK encodes the header and the blocks separately.
        text = base64.b64encode(header).decode() + "\n" + base64.b64encode(data).decode()
        return 'format="binary"', text, b""
    encode.appended_encoding = None
    return encode


def appended_raw(header_fmt, block_size=None):
    def encode(order, raw, offset):
        if block_size:
            header, data = zlib_block(order, header_fmt, raw, block_size)
            blob = header + data
        else:
            blob = header_block(order, header_fmt, raw)
        return f'format="appended" offset="{offset}"', None, blob
    encode.appended_encoding = "raw"
    return encode


def appended_base64(header_fmt, block_size=None):
    def encode(order, raw, offset):
        if block_size:
            header, data = zlib_block(order, header_fmt, raw, block_size)
        else:
            header, data = struct.pack(order + header_fmt, len(raw)), raw
        # Header and data encoded apart, as VTK does.
        blob = base64.b64encode(header) + base64.b64encode(data)
        return f'format="appended" offset="{offset}"', None, blob
    encode.appended_encoding = "base64"
    return encode


hand_file(os.path.join(OUT, "hand_big_endian_uint32.vtu"), "BigEndian", None,
          inline_uncompressed("I"), version="0.1")
hand_file(os.path.join(OUT, "hand_big_endian_zlib_uint64.vtu"), "BigEndian", "UInt64",
          inline_zlib("Q", 16), compressor="vtkZLibDataCompressor")
hand_file(os.path.join(OUT, "hand_appended_raw_two_pieces.vtu"), "LittleEndian", "UInt32",
          appended_raw("I"), pieces=2)
hand_file(os.path.join(OUT, "hand_appended_raw_zlib.vtu"), "LittleEndian", "UInt64",
          appended_raw("Q", 24), version="2.2", compressor="vtkZLibDataCompressor")
hand_file(os.path.join(OUT, "hand_appended_base64.vtu"), "LittleEndian", "UInt64",
          appended_base64("Q"))
hand_file(os.path.join(OUT, "hand_appended_base64_zlib.vtu"), "BigEndian", "UInt32",
          appended_base64("I", 10), compressor="vtkZLibDataCompressor")
