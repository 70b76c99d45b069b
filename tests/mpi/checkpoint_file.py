"""A reader of geompm's checkpoint.bin for the mpi tests (docs/checkpoint-format.md): the header
checked (magic, length, FNV-1a 64 checksum), the sections by name, and the `points` section's
arrays.
"""
import struct

# The points section's arrays (MaterialPoints::save): name, struct format of one value.
POINT_ARRAYS = [
    ("id", "i"), ("body", "i"), ("material", "i"), ("sets", "Q"),
    ("position", "3d"), ("initial_position", "3d"), ("displacement", "3d"),
    ("phase_displacement", "3d"), ("velocity", "3d"), ("acceleration", "3d"),
    ("mass", "d"), ("volume", "d"), ("initial_volume", "d"), ("initial_half_size", "3d"),
    ("stress", "9d"), ("deformation_gradient", "9d"), ("domain_stretch", "d"),
    ("volume_mismatch", "d"), ("elastic_left_cauchy_green", "9d"), ("internal", "4d"),
    ("cell", "i"), ("local", "3d"),
]


def fnv1a_64(data):
    h = 0xcbf29ce484222325
    for byte in data:
        h = ((h ^ byte) * 0x100000001b3) & 0xFFFFFFFFFFFFFFFF
    return h


def sections(path):
    """The checkpoint's sections, {name: bytes} in the file's order; asserts a sound header."""
    with open(path, "rb") as f:
        data = f.read()
    assert data[:8] == b"GEOMPMCK", f"{path}: not a checkpoint"
    _, length, checksum = struct.unpack_from("<IQQ", data, 8)
    assert len(data) == 28 + length, f"{path}: {len(data)} bytes, announces {28 + length}"
    assert fnv1a_64(data[28:]) == checksum, f"{path}: checksum"
    at = 28

    def text():
        nonlocal at
        (n,) = struct.unpack_from("<Q", data, at)
        at += 8 + n
        return data[at - n:at]

    text()  # geompm version
    at += 8  # model hash
    (count,) = struct.unpack_from("<I", data, at)
    at += 4
    found = {}
    for _ in range(count):
        name = text().decode()
        found[name] = text()
    assert at == len(data)
    return found


def point_arrays(points):
    """The `points` section's arrays: {name: [value, ...]}, a value a tuple of numbers."""
    arrays, at = {}, 0
    for name, value in POINT_ARRAYS:
        (count,) = struct.unpack_from("<Q", points, at)
        at += 8
        size = struct.calcsize("<" + value)
        arrays[name] = [struct.unpack_from("<" + value, points, at + k * size) for k in range(count)]
        at += count * size
    assert at == len(points), "bytes left over in the points section"
    return arrays
