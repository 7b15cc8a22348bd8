#!/usr/bin/python3
"""Write a closed, smooth, lumpy creature-like triangle mesh as an OBJ file.

The fallback for scenes/seed-glass-armadillo when the Stanford Armadillo
(../shared/meshes/armadillo.obj, research-use licence, never committed) is
absent. The surface is star-shaped: an icosphere (20 * 4^level triangles,
~20k at the default level 5) whose vertices are pushed along their direction
to a radius r(d) = ellipsoid + Gaussian lobes (head, arms, legs, ears) +
low-frequency ripples. A star-shaped radial surface with r > 0 everywhere is
closed and never self-intersects, so glass refracts through it correctly.
Vertex normals are the area-weighted face normals (smooth shading).

It is placed in the Armadillo's own frame (y up, feet at y = -54.2, 151
units tall, facing +z) so the scene's one to_world serves both meshes.

    /usr/bin/python3 tools/scenes/make_blob_mesh.py out/blob.obj [--level 5]
"""
import argparse
import numpy as np

# Lobes: (direction, height, angular width in radians). Together they read as
# a squat creature: a head with two ears on top, two arms, two legs, a belly.
LOBES = [
    ((0.0, 1.0, 0.15), 0.45, 0.35),    # head
    ((-0.35, 1.0, 0.0), 0.35, 0.14),   # left ear
    ((0.35, 1.0, 0.0), 0.35, 0.14),    # right ear
    ((-1.0, 0.25, 0.45), 0.55, 0.22),  # left arm, reaching forward
    ((1.0, 0.25, 0.45), 0.55, 0.22),   # right arm
    ((-0.45, -1.0, 0.1), 0.45, 0.28),  # left leg
    ((0.45, -1.0, 0.1), 0.45, 0.28),   # right leg
    ((0.0, -0.1, 1.0), 0.18, 0.5),     # belly
    ((0.0, 0.2, -1.0), 0.12, 0.6),     # back
]
ARMADILLO_MIN_Y = -54.2   # the Stanford Armadillo's bounding box (y up)
ARMADILLO_HEIGHT = 151.3


def icosphere(level):
    t = (1.0 + 5.0 ** 0.5) / 2.0
    v = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
         (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
         (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
         (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    verts = [np.array(p, float) / np.linalg.norm(p) for p in v]
    faces = f
    for _ in range(level):
        midpoint = {}

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in midpoint:
                m = verts[a] + verts[b]
                verts.append(m / np.linalg.norm(m))
                midpoint[key] = len(verts) - 1
            return midpoint[key]

        new_faces = []
        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            new_faces += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = new_faces
    return np.array(verts), np.array(faces, dtype=np.int64)


def radius(d):
    """Radius of the creature along unit directions d (N x 3)."""
    # A body taller than wide: an ellipsoid with semi-axes (0.75, 1, 0.6).
    r = 1.0 / np.sqrt((d[:, 0] / 0.75) ** 2 + d[:, 1] ** 2 + (d[:, 2] / 0.6) ** 2)
    for direction, height, width in LOBES:
        u = np.array(direction, float)
        u /= np.linalg.norm(u)
        angle = np.arccos(np.clip(d @ u, -1.0, 1.0))
        r += height * np.exp(-(angle / width) ** 2)
    # Low-frequency ripples: armour-like lumps, small enough to stay star-shaped.
    r *= 1.0 + 0.04 * np.sin(7 * d[:, 0]) * np.sin(6 * d[:, 1] + 1.0) * np.cos(5 * d[:, 2])
    return r


def vertex_normals(p, faces):
    n = np.zeros_like(p)
    fn = np.cross(p[faces[:, 1]] - p[faces[:, 0]], p[faces[:, 2]] - p[faces[:, 0]])  # length = 2 area
    for k in range(3):
        np.add.at(n, faces[:, k], fn)
    return n / np.linalg.norm(n, axis=1, keepdims=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("output", help="OBJ file to write")
    parser.add_argument("--level", type=int, default=5, help="icosphere subdivisions (triangles = 20 * 4^level)")
    args = parser.parse_args()
    d, faces = icosphere(args.level)
    p = d * radius(d)[:, None]
    # Into the Armadillo's frame: feet at its min y, its height, centred in x and z.
    scale = ARMADILLO_HEIGHT / (p[:, 1].max() - p[:, 1].min())
    p = p * scale
    p[:, 1] += ARMADILLO_MIN_Y - p[:, 1].min()
    p[:, 0] -= 0.5 * (p[:, 0].max() + p[:, 0].min())
    p[:, 2] -= 0.5 * (p[:, 2].max() + p[:, 2].min())
    n = vertex_normals(p, faces)
    with open(args.output, "w") as out:
        out.write("# femto tools/scenes/make_blob_mesh.py: a lumpy creature, fallback for the Armadillo\n")
        out.write("".join(f"v {x:.5f} {y:.5f} {z:.5f}\n" for x, y, z in p))
        out.write("".join(f"vn {x:.5f} {y:.5f} {z:.5f}\n" for x, y, z in n))
        out.write("".join(f"f {a}//{a} {b}//{b} {c}//{c}\n" for a, b, c in faces + 1))
    print(f"{args.output}: {len(p)} vertices, {len(faces)} triangles")


if __name__ == "__main__":
    main()
