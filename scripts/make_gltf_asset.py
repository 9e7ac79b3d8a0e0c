#!/usr/bin/env python3
"""Writes the bundled glTF asset and its OBJ twin in assets/full_suite/gltf/ (tessbench's own, CC0;
the positions are OpenSubdiv's catmark_torus as tri_torus.obj has them).

tri_torus_seams.glb   tri_torus (assets/tessbench/tri_torus.obj, 64 triangles) as an engine
                      exports it: a UV atlas cut at u = 0/1 around the ring and v = 0/1 around
                      the tube, every vertex split along those seams, and normals computed
                      after splitting (area-weighted over the faces of each split vertex), so
                      the two sides of a seam have different normals; two primitives (the
                      triangles in two halves) of one mesh under one node.
tri_torus_seams_twin.obj  the same mesh as OBJ: the welded positions in the order the glTF
                      reader welds them, one vn and one vt per glTF vertex (vt = u, 1 - v),
                      faces `f v/vt/vn`, so both files load to the same tessbench mesh.

Every float is a float32 written to the OBJ with enough digits to read back exactly; the UVs
are multiples of 1/8 and 1/4, so 1 - v is exact. The big asset for the timing line
(`--refine N` on the glb, or `--faces N`) is written elsewhere with --out.

Run from the repository root: python3 scripts/make_gltf_asset.py
The output is deterministic; the files are committed. scripts/validate_gltf.sh checks the .glb
with the Khronos glTF-Validator.
"""
import argparse
import json
import math
import os
import struct

SOURCE = "assets/tessbench/tri_torus.obj"
OUT = "assets/full_suite/gltf"


def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


def read_obj(path):
    positions, faces = [], []
    for line in open(path):
        parts = line.split()
        if not parts:
            continue
        if parts[0] == "v":
            positions.append(tuple(f32(float(t)) for t in parts[1:4]))
        elif parts[0] == "f":
            faces.append(tuple(int(t.split("/")[0]) - 1 for t in parts[1:]))
    return positions, faces


def angle_index(values):
    """Index of each angle among the distinct angles, sorted (angles within 1e-3 rad of the
    previous distinct one are the same: the file's 6 decimals move them by ~1e-6)."""
    order = sorted(range(len(values)), key=lambda i: values[i])
    index, count, last = [0] * len(values), -1, None
    for i in order:
        if last is None or values[i] - last > 1e-3:
            count += 1
            last = values[i]
        index[i] = count
    return index, count + 1


def torus_grid(positions):
    """The (ring, tube) grid index of every position of the y-axis torus."""
    radii = [math.hypot(x, z) for x, _, z in positions]
    centre = (max(radii) + min(radii)) / 2
    ring, ring_count = angle_index([math.atan2(z, x) % (2 * math.pi) for x, _, z in positions])
    tube, tube_count = angle_index(
        [math.atan2(p[1], r - centre) % (2 * math.pi) for p, r in zip(positions, radii)])
    return ring, ring_count, tube, tube_count


def unwrap(indices, count):
    """Grid indices of a face's corners with the wrap-around side moved past the end."""
    if max(indices) - min(indices) > count // 2:
        return [i + count if i < count // 2 else i for i in indices]
    return list(indices)


def split_vertices(positions, faces):
    """glTF vertices (position, u, v) and each face's vertex indices, in first-use order."""
    ring, ring_count, tube, tube_count = torus_grid(positions)
    vertices, key_to_vertex, split_faces = [], {}, []
    for face in faces:
        us = unwrap([ring[p] for p in face], ring_count)
        vs = unwrap([tube[p] for p in face], tube_count)
        corners = []
        for p, u, v in zip(face, us, vs):
            key = (p, u, v)
            if key not in key_to_vertex:
                key_to_vertex[key] = len(vertices)
                vertices.append((p, u / ring_count, v / tube_count))
            corners.append(key_to_vertex[key])
        split_faces.append(corners)
    return vertices, split_faces


def subdivide(positions, vertices, faces):
    """Each triangle into four at its edge midpoints (positions and uvs linear): midpoints of
    one position pair are one position on both sides of a seam, so seams stay seams."""
    positions, vertices = list(positions), list(vertices)
    position_of, vertex_of, out = {}, {}, []

    def midpoint(a, b):
        (pa, ua, va), (pb, ub, vb) = vertices[a], vertices[b]
        pair = (min(pa, pb), max(pa, pb))
        if pair not in position_of:
            position_of[pair] = len(positions)
            positions.append(tuple(f32((x + y) / 2) for x, y in zip(positions[pa], positions[pb])))
        key = (position_of[pair], (ua + ub) / 2, (va + vb) / 2)
        if key not in vertex_of:
            vertex_of[key] = len(vertices)
            vertices.append(key)
        return vertex_of[key]

    for a, b, c in faces:
        ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
        out += [[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]
    return positions, vertices, out


def split_normals(positions, vertices, faces):
    """Per glTF vertex: the area-weighted normal of the faces that use that vertex."""
    sums = [[0.0, 0.0, 0.0] for _ in vertices]
    for face in faces:
        a, b, c = (positions[vertices[k][0]] for k in face)
        e1 = [b[i] - a[i] for i in range(3)]
        e2 = [c[i] - a[i] for i in range(3)]
        n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
             e1[0] * e2[1] - e1[1] * e2[0]]
        for k in face:
            for i in range(3):
                sums[k][i] += n[i]
    normals = []
    for s in sums:
        length = math.sqrt(sum(c * c for c in s))
        normals.append(tuple(f32(c / length) for c in s))
    return normals


def glb(positions, vertices, normals, faces, halves):
    """The .glb bytes: one mesh of `halves` primitives, each with its own vertices."""
    binary, views, accessors, primitives = bytearray(), [], [], []

    def add(data, count, kind, component, target, bounds=False, values=None):
        while len(binary) % 4:
            binary.append(0)
        views.append({"buffer": 0, "byteOffset": len(binary), "byteLength": len(data),
                      "target": target})
        binary.extend(data)
        accessor = {"bufferView": len(views) - 1, "componentType": component, "count": count,
                    "type": kind}
        if bounds:
            accessor["min"] = [min(v[i] for v in values) for i in range(3)]
            accessor["max"] = [max(v[i] for v in values) for i in range(3)]
        accessors.append(accessor)
        return len(accessors) - 1

    primitive_used, per_half = primitive_vertices(faces, halves)
    for h, used in enumerate(primitive_used):
        part = faces[h * per_half:(h + 1) * per_half]
        local = {k: i for i, k in enumerate(used)}
        pos = [positions[vertices[k][0]] for k in used]
        attributes = {
            "POSITION": add(b"".join(struct.pack("<3f", *p) for p in pos), len(pos), "VEC3",
                            5126, 34962, True, pos),
            "NORMAL": add(b"".join(struct.pack("<3f", *normals[k]) for k in used), len(used),
                          "VEC3", 5126, 34962),
            "TEXCOORD_0": add(b"".join(struct.pack("<2f", vertices[k][1], 1 - vertices[k][2])
                                       for k in used), len(used), "VEC2", 5126, 34962),
        }
        indices = [local[k] for face in part for k in face]
        index = add(struct.pack(f"<{len(indices)}H", *indices), len(indices), "SCALAR", 5123,
                    34963)
        primitives.append({"attributes": attributes, "indices": index, "mode": 4})
    gltf = {"asset": {"version": "2.0", "generator": "tessbench scripts/make_gltf_asset.py"},
            "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0, "name": "torus"}],
            "meshes": [{"name": "tri_torus_seams", "primitives": primitives}],
            "accessors": accessors, "bufferViews": views,
            "buffers": [{"byteLength": len(binary)}]}
    text = json.dumps(gltf, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    binary.extend(b"\0" * (-len(binary) % 4))
    total = 12 + 8 + len(text) + 8 + len(binary)
    return (struct.pack("<4sII", b"glTF", 2, total) + struct.pack("<I4s", len(text), b"JSON") +
            text + struct.pack("<I4s", len(binary), b"BIN\0") + bytes(binary))


def primitive_vertices(faces, halves):
    """Per primitive: the glTF vertices it uses, ascending (its own copies in the .glb)."""
    per_half = (len(faces) + halves - 1) // halves
    return [sorted({k for face in faces[h * per_half:(h + 1) * per_half] for k in face})
            for h in range(halves)], per_half


def twin_obj(positions, vertices, normals, faces, halves):
    """The OBJ twin: positions in the order the glTF reader welds them (primitive by
    primitive, vertex by vertex), one vt and vn per glTF vertex in the reader's order."""
    used, per_half = primitive_vertices(faces, halves)
    order, slot, number = [], {}, {}
    for h, ks in enumerate(used):
        for k in ks:
            number[(h, k)] = len(number) + 1
            if vertices[k][0] not in slot:
                slot[vertices[k][0]] = len(order) + 1
                order.append(vertices[k][0])
    lines = ["# Generated by scripts/make_gltf_asset.py (tessbench, CC0): the OBJ twin of",
             "# tri_torus_seams.glb (positions: OpenSubdiv's catmark_torus, Modified Apache 2.0)"]
    lines += ["v " + " ".join(repr(c) for c in positions[p]) for p in order]
    by_number = sorted(number, key=number.get)
    lines += ["vt %r %r" % (vertices[k][1], vertices[k][2]) for _, k in by_number]
    lines += ["vn " + " ".join(repr(c) for c in normals[k]) for _, k in by_number]
    for f, face in enumerate(faces):
        h = f // per_half
        lines.append("f " + " ".join(f"{slot[vertices[k][0]]}/{number[(h, k)]}/{number[(h, k)]}"
                                     for k in face))
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", default=OUT, help="output folder (default assets/full_suite/gltf)")
    parser.add_argument("--subdivide", type=int, default=0,
                        help="split every triangle into 4 this many times first (4^N x 64 "
                             "triangles; written as tri_torus_seams_sN.glb/_twin.obj, not bundled)")
    args = parser.parse_args()
    positions, faces = read_obj(SOURCE)
    vertices, split_faces = split_vertices(positions, faces)
    for _ in range(args.subdivide):
        positions, vertices, split_faces = subdivide(positions, vertices, split_faces)
    normals = split_normals(positions, vertices, split_faces)
    halves = 2
    stem = "tri_torus_seams" + (f"_s{args.subdivide}" if args.subdivide else "")
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, stem + ".glb"), "wb") as f:
        f.write(glb(positions, vertices, normals, split_faces, halves))
    with open(os.path.join(args.out, stem + "_twin.obj"), "w") as f:
        f.write(twin_obj(positions, vertices, normals, split_faces, halves))
    print(f"{len(split_faces)} triangles, {len(positions)} positions, {len(vertices)} glTF vertices")


if __name__ == "__main__":
    main()
