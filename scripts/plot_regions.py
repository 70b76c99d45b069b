#!/usr/bin/env python3
"""A picture of a coupled run's regions from its ParaView output (docs/user-guide.md, tutorials).

    /usr/bin/python3 scripts/plot_regions.py RUN_DIR STEP -o regions.png [--box xmin xmax ymin ymax]

Draws the background mesh of step STEP (RUN_DIR/vtk/grid_<STEP>.vtu) with its cells coloured by
their kind (the `cell_kind` field: MPM, FEM, buffer), the material points, the FEM region's Gauss
points and every structure's cells. Needs matplotlib (bash scripts/setup.sh --report).
"""
import argparse
import glob
import os
import re
import struct

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

TYPES = {"Float64": "d", "Int64": "q", "Int32": "i", "UInt8": "B"}


def read_vtk(path):
    """The arrays of a VTK XML file written with raw appended data and UInt64 headers."""
    raw = open(path, "rb").read()
    start = raw.index(b"<AppendedData")
    data = raw[raw.index(b"_", start) + 1:]
    arrays = {}
    for m in re.finditer(rb'<DataArray type="(\w+)" Name="(\w+)" NumberOfComponents="(\d+)"'
                         rb' format="appended" offset="(\d+)"', raw[:start]):
        kind, name, comps, offset = m.group(1).decode(), m.group(2).decode(), int(m.group(3)), int(m.group(4))
        size = struct.unpack_from("<Q", data, offset)[0]
        code = TYPES[kind]
        values = struct.unpack_from("<%d%s" % (size // struct.calcsize(code), code), data, offset + 8)
        arrays[name] = [values[i:i + comps] for i in range(0, len(values), comps)] if comps > 1 else list(values)
    return arrays


def cells(arrays):
    """Each cell's corner coordinates (x, y)."""
    points, conn, offsets = arrays["Points"], arrays["connectivity"], arrays["offsets"]
    out, begin = [], 0
    for end in offsets:
        out.append([points[i][:2] for i in conn[begin:end]])
        begin = end
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run")
    parser.add_argument("step", type=int)
    parser.add_argument("-o", "--output", required=True)
    parser.add_argument("--box", type=float, nargs=4, metavar=("XMIN", "XMAX", "YMIN", "YMAX"))
    parser.add_argument("--title", default="")
    args = parser.parse_args()
    vtk = os.path.join(args.run, "vtk")
    grid = read_vtk(os.path.join(vtk, "grid_%06d.vtu" % args.step))
    colours = {0: "#fde9c9", 1: "#c9d9ef", 2: "#ffffff"}
    names = {0: "MPM cells", 1: "FEM cells", 2: "buffer cells"}
    fig, ax = plt.subplots(figsize=(7, 7))
    polygons, kinds = cells(grid), grid["cell_kind"]
    ax.add_collection(PolyCollection(polygons, facecolors=[colours[k] for k in kinds],
                                     edgecolors="#8c8c8c", linewidths=0.4))
    for k in sorted(set(kinds)):
        ax.fill([], [], color=colours[k], ec="#8c8c8c", label=names[k])
    points = read_vtk(os.path.join(vtk, "points_%06d.vtu" % args.step))["Points"]
    ax.plot([p[0] for p in points], [p[1] for p in points], ".", ms=1.5, color="#b35806",
            label="material points")
    gauss = os.path.join(vtk, "gauss_points_%06d.vtu" % args.step)
    if os.path.exists(gauss):
        g = read_vtk(gauss)["Points"]
        ax.plot([p[0] for p in g], [p[1] for p in g], ".", ms=1.0, color="#2166ac",
                label="FEM Gauss points")
    for path in sorted(glob.glob(os.path.join(vtk, "structure_*_%06d.vtu" % args.step))):
        name = re.match(r"structure_(.*)_\d+\.vtu", os.path.basename(path)).group(1)
        ax.add_collection(PolyCollection(cells(read_vtk(path)), facecolors="#4d4d4d",
                                         edgecolors="#1a1a1a", linewidths=0.3))
        ax.fill([], [], color="#4d4d4d", label="structure '%s'" % name)
    if args.box:
        ax.set_xlim(args.box[0], args.box[1])
        ax.set_ylim(args.box[2], args.box[3])
    else:
        ax.autoscale()
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_title(args.title)
    ax.legend(loc="lower right", fontsize=8, framealpha=0.9)
    fig.tight_layout()
    fig.savefig(args.output, dpi=110)


if __name__ == "__main__":
    main()
