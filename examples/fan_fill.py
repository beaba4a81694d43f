#!/usr/bin/env python3
"""A hole-filling method for holebench as a program: fills every hole with a fan of
triangles around a new vertex at the centroid of the hole's boundary loop.

    python3 examples/fan_fill.py INPUT.ply OUTPUT.ply

Run it as an external method (docs/methods.md, "A program as a method"):

    holebench run --out DIR --case 'box/*' \
        --external 'name=fan_fill;command=python3 examples/fan_fill.py {input} {output}'

It reads the holed mesh as holebench writes it (binary little-endian PLY: double x, y, z;
a face list of int indices; an int "region" per face) or any ASCII or binary PLY of
triangles, and writes the input's vertices and faces unchanged (same positions, same
orientation) followed by the fans, as binary little-endian PLY. Pure Python, no packages.
"""
import struct
import sys

PLY_TYPES = {  # PLY type -> struct code
    "char": "b", "int8": "b", "uchar": "B", "uint8": "B",
    "short": "h", "int16": "h", "ushort": "H", "uint16": "H",
    "int": "i", "int32": "i", "uint": "I", "uint32": "I",
    "float": "f", "float32": "f", "double": "d", "float64": "d",
}


def read_ply(path):
    """Returns (points, faces): a list of (x, y, z) and a list of vertex index lists."""
    with open(path, "rb") as f:
        if f.readline().strip() != b"ply":
            raise ValueError(path + ": not a PLY file")
        fmt, elements = None, []  # elements: [name, count, [(name, type, count_type)]]
        while True:
            words = f.readline().decode("ascii").split()
            if not words or words[0] in ("comment", "obj_info"):
                continue
            if words[0] == "end_header":
                break
            if words[0] == "format":
                fmt = words[1]
            elif words[0] == "element":
                elements.append([words[1], int(words[2]), []])
            elif words[0] == "property" and words[1] == "list":
                elements[-1][2].append((words[4], words[3], words[2]))
            elif words[0] == "property":
                elements[-1][2].append((words[2], words[1], None))
        if fmt == "ascii":
            tokens = iter(f.read().split())
            read = lambda ply_type: (float if PLY_TYPES[ply_type] in "fd" else int)(next(tokens))
        else:
            order = "<" if fmt == "binary_little_endian" else ">"

            def read(ply_type):
                code = order + PLY_TYPES[ply_type]
                return struct.unpack(code, f.read(struct.calcsize(code)))[0]

        points, faces = [], []
        for name, count, properties in elements:
            for _ in range(count):
                values = {}
                for prop_name, prop_type, count_type in properties:
                    if count_type is None:
                        values[prop_name] = read(prop_type)
                    else:
                        values[prop_name] = [read(prop_type) for _ in range(read(count_type))]
                if name == "vertex":
                    points.append((values["x"], values["y"], values["z"]))
                elif name == "face":
                    faces.append(values.get("vertex_indices", values.get("vertex_index")))
        return points, faces


def write_ply(path, points, faces):
    with open(path, "wb") as f:
        f.write(("ply\nformat binary_little_endian 1.0\n"
                 "element vertex %d\nproperty double x\nproperty double y\nproperty double z\n"
                 "element face %d\nproperty list uchar int vertex_indices\nend_header\n"
                 % (len(points), len(faces))).encode("ascii"))
        for p in points:
            f.write(struct.pack("<3d", *p))
        for face in faces:
            f.write(struct.pack("<B%di" % len(face), len(face), *face))


def boundary_loops(faces):
    """The holes: loops of the half-edges (b, a) whose face edge (a, b) has no twin."""
    edges = set()
    for face in faces:
        for i in range(len(face)):
            edges.add((face[i], face[(i + 1) % len(face)]))
    following = {b: a for (a, b) in edges if (b, a) not in edges}  # hole half-edge b -> a
    loops = []
    while following:
        start = v = next(iter(following))
        loop = []
        while True:
            loop.append(v)
            v = following.pop(v)
            if v == start:
                break
        loops.append(loop)
    return loops


def fan_fill(points, faces):
    points, faces = list(points), list(faces)
    for loop in boundary_loops(faces):
        n = len(loop)
        centroid = tuple(sum(points[v][k] for v in loop) / n for k in range(3))
        points.append(centroid)
        c = len(points) - 1
        for i in range(n):  # the hole half-edge loop[i] -> loop[i + 1], with the face on its left
            faces.append([loop[i], loop[(i + 1) % n], c])
    return points, faces


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: fan_fill.py INPUT.ply OUTPUT.ply")
    points, faces = read_ply(sys.argv[1])
    write_ply(sys.argv[2], *fan_fill(points, faces))


if __name__ == "__main__":
    main()
