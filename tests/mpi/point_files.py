"""The points' ParaView files of a run as the tests read them back: a serial run's .vtu, a
distributed run's .pvtu and the pieces it names (one .vtu per process), each piece read with
meshio, a reader independent of geompm's writer. meshio 5.0 has no .pvtu reader: the .pvtu's
structure is checked here against what ParaView's reader expects (the arrays every piece holds,
declared once with their types and components; the pieces by file name beside it), and each
piece is read as the .vtu it is.
"""
import os
from xml.etree import ElementTree

import meshio
import numpy as np


def series(output, name="points.pvd"):
    """The (time, file) entries of a .pvd series, file relative to the output directory."""
    root = ElementTree.parse(os.path.join(output, name)).getroot()
    return [(float(d.attrib["timestep"]), d.attrib["file"]) for d in root.iter("DataSet")]


def _vtu_arrays(path):
    """Name -> (type, components) of a .vtu's point data, from its XML header."""
    with open(path, "rb") as f:
        header = f.read().split(b"<AppendedData", 1)[0].decode()
    root = ElementTree.fromstring(header + "</VTKFile>")
    arrays = {}
    for array in root.find("UnstructuredGrid/Piece/PointData"):
        arrays[array.attrib["Name"]] = (array.attrib["type"], array.attrib["NumberOfComponents"])
    count = int(root.find("UnstructuredGrid/Piece").attrib["NumberOfPoints"])
    return arrays, count


def read_pvtu(path):
    """The pieces of a .pvtu, checked: returns [(piece file, meshio mesh or None if empty)]."""
    root = ElementTree.parse(path).getroot()
    if root.tag != "VTKFile" or root.attrib.get("type") != "PUnstructuredGrid":
        raise AssertionError(f"{path}: not a VTKFile of type PUnstructuredGrid")
    grid = root.find("PUnstructuredGrid")
    declared = {a.attrib["Name"]: (a.attrib["type"], a.attrib["NumberOfComponents"])
                for a in grid.find("PPointData")}
    points = grid.find("PPoints/PDataArray")
    if points is None or points.attrib["NumberOfComponents"] != "3":
        raise AssertionError(f"{path}: no PPoints of 3 components")
    pieces = []
    for piece in grid.findall("Piece"):
        file = os.path.join(os.path.dirname(path), piece.attrib["Source"])
        if not os.path.isfile(file):
            raise AssertionError(f"{path} names {piece.attrib['Source']}, which is not there")
        arrays, count = _vtu_arrays(file)
        if arrays != declared:
            raise AssertionError(f"{file}: arrays {arrays} where {path} declares {declared}")
        # meshio 5.0 cannot read a file with no cells: an empty piece is checked by its header.
        pieces.append((file, meshio.read(file) if count > 0 else None))
    if not pieces:
        raise AssertionError(f"{path}: no pieces")
    return pieces


def read_points(path):
    """Every point of a .vtu or .pvtu: (fields by name, position under "position", ordered by
    id; per point the piece it came from, 0 for a .vtu). Raises AssertionError if a point is in
    the file more than once."""
    if path.endswith(".pvtu"):
        meshes = [mesh for _, mesh in read_pvtu(path)]
    else:
        meshes = [meshio.read(path)]
    fields, piece = {}, []
    for k, mesh in enumerate(meshes):
        if mesh is None:
            continue
        piece.append(np.full(len(mesh.points), k))
        for name, values in list(mesh.point_data.items()) + [("position", mesh.points)]:
            fields.setdefault(name, []).append(values)
    fields = {name: np.concatenate(values) for name, values in fields.items()}
    piece = np.concatenate(piece)
    ids = fields["id"].ravel()
    if len(np.unique(ids)) != len(ids):
        raise AssertionError(f"{path}: a point is in the file more than once")
    order = np.argsort(ids)
    return {name: values[order] for name, values in fields.items()}, piece[order]
