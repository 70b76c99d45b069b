#!/usr/bin/python3
"""Reads a .vtu file with meshio (a reader independent of geompm's writer) and prints what it
found in a line-based format that the C++ tests parse without a JSON library:

    POINTS <count>
    <x> <y> <z>                                   (one line per point)
    CELLS <meshio cell type> <count> <nodes per cell>
    <node> <node> ...                             (one line per cell)
    POINT_DATA <dtype> <components> <count> <name>
    <value> ...                                   (one line per point, all components)
    CELL_DATA <block> <dtype> <components> <count> <name>
    <value> ...                                   (one line per cell of that block)
    END

Floats are printed with repr(), the shortest text that reads back as the same double, so the
tests can compare values exactly. Exit status 1 (and a message on stderr) if meshio fails.

    read_vtu.py --check-layout FILE.vtu

checks the appended raw layout without meshio (which, in 5.0, cannot read a file with no
cells): the XML header must parse, and the blocks of the <AppendedData> section (each a
header_type byte count followed by the bytes) must tile it exactly, each of the size its
DataArray implies from NumberOfPoints, NumberOfCells and NumberOfComponents. Prints
"LAYOUT <points> <cells> <arrays>" and END.

Run with /usr/bin/python3, which has python3-meshio.
"""
import re
import struct
import sys
from xml.etree import ElementTree

import meshio
import numpy as np

ITEM_SIZE = {"Float32": 4, "Float64": 8, "Int8": 1, "UInt8": 1, "Int16": 2, "UInt16": 2,
             "Int32": 4, "UInt32": 4, "Int64": 8, "UInt64": 8}


def text(value):
    if np.issubdtype(type(value), np.integer):
        return str(int(value))
    return repr(float(value))


def rows(array):
    array = np.asarray(array)
    if array.ndim == 1:
        array = array.reshape(-1, 1)
    return array.reshape(array.shape[0], -1)


def components(array):
    return rows(array).shape[1] if np.asarray(array).ndim > 1 else 1


def check_layout(file):
    raw = open(file, "rb").read()
    start = re.search(rb'<AppendedData encoding="raw">\s*_', raw)
    end = raw.rfind(b"\n  </AppendedData>")
    if not start or end < start.end():
        sys.exit("no <AppendedData encoding=\"raw\"> ... _ ... </AppendedData> section")
    data = raw[start.end():end]
    root = ElementTree.fromstring(raw[: start.start()] + b"<AppendedData>" + raw[end + 1 :])
    if root.get("header_type") != "UInt64" or root.get("byte_order") != "LittleEndian":
        sys.exit("expected header_type UInt64 and byte_order LittleEndian")
    piece = root.find("UnstructuredGrid/Piece")
    points, cells = int(piece.get("NumberOfPoints")), int(piece.get("NumberOfCells"))

    def block(array):
        offset = int(array.get("offset"))
        (size,) = struct.unpack_from("<Q", data, offset)
        return offset, size, data[offset + 8 : offset + 8 + size]

    arrays = piece.findall(".//DataArray")
    expected = {}
    for array in arrays:
        if array.get("format") != "appended":
            sys.exit(f"array {array.get('Name')} is not appended")
        count = {"PointData": points, "Points": points, "CellData": cells, "Cells": cells}
        parent = next(p for p in piece.iter() if array in list(p)).tag
        values = count[parent] * int(array.get("NumberOfComponents", "1"))
        if parent == "Cells" and array.get("Name") == "connectivity":
            offsets = next(a for a in arrays if a.get("Name") == "offsets")
            _, _, body = block(offsets)
            values = int(np.frombuffer(body, "<i8")[-1]) if cells else 0
        size = values * ITEM_SIZE[array.get("type")]
        expected[int(array.get("offset"))] = (array.get("Name"), size)

    position = 0
    for offset in sorted(expected):
        name, size_expected = expected[offset]
        if offset != position:
            sys.exit(f"array {name} at offset {offset}, expected {position} (gap or overlap)")
        _, size, _ = block(next(a for a in arrays if int(a.get("offset")) == offset))
        if size != size_expected:
            sys.exit(f"array {name}: block of {size} bytes, expected {size_expected}")
        position = offset + 8 + size
    if position != len(data):
        sys.exit(f"{len(data) - position} bytes after the last block")
    print(f"LAYOUT {points} {cells} {len(arrays)}")
    print("END")


def main():
    if len(sys.argv) == 3 and sys.argv[1] == "--check-layout":
        check_layout(sys.argv[2])
        return
    if len(sys.argv) != 2:
        sys.exit("usage: read_vtu.py [--check-layout] FILE.vtu")
    try:
        mesh = meshio.read(sys.argv[1])
    except Exception as error:  # noqa: BLE001 - any reader failure is a test failure
        sys.exit(f"meshio cannot read {sys.argv[1]}: {error!r}")

    out = [f"POINTS {len(mesh.points)}"]
    out += [" ".join(text(v) for v in p) for p in rows(mesh.points)]
    for block in mesh.cells:
        data = rows(block.data)
        out.append(f"CELLS {block.type} {data.shape[0]} {data.shape[1]}")
        out += [" ".join(text(v) for v in cell) for cell in data]
    for name, array in mesh.point_data.items():
        array = np.asarray(array)
        out.append(f"POINT_DATA {array.dtype} {components(array)} {array.shape[0]} {name}")
        out += [" ".join(text(v) for v in row) for row in rows(array)]
    for name, blocks in mesh.cell_data.items():
        for index, array in enumerate(blocks):
            array = np.asarray(array)
            out.append(
                f"CELL_DATA {index} {array.dtype} {components(array)} {array.shape[0]} {name}"
            )
            out += [" ".join(text(v) for v in row) for row in rows(array)]
    out.append("END")
    print("\n".join(out))


if __name__ == "__main__":
    main()
