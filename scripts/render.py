#!/usr/bin/python3
"""Pictures of particles on a mesh, like the paper's Fig. 1.

    scripts/render.py MESH PARTICLES [PARTICLES_B] [--out FILE.png] [--labels A B]

Draws the shaded mesh with the particles as dots from three views (front,
side, top). With a second particle file, two rows: the two runs side by
side on the same views (e.g. the serial reference against a device). Only
particles on the side of the surface facing the viewer are drawn. Particle
files hold one "x y z" per line (`run` writes out/particles.particles).
Uses Debian's python3-matplotlib, python3-numpy and python3-meshio
(scripts/setup.sh installs them).
"""
import argparse
import sys
from pathlib import Path

import matplotlib
import numpy as np

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402
import meshio  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

VIEWS = [("front", 15, -60), ("side", 15, 30), ("top", 89, -90)]  # (name, elevation, azimuth) in degrees
LIGHT = np.array([0.4, -0.5, 0.8]) / np.linalg.norm([0.4, -0.5, 0.8])


def read_mesh(path):
    try:
        mesh = meshio.read(path)
    except Exception as error:  # meshio raises many kinds; one line for any
        sys.exit(f"render: {path}: not a readable mesh ({error})")
    triangles = [block.data for block in mesh.cells if block.type == "triangle"]
    if not triangles:
        sys.exit(f"render: {path}: no triangles")
    return np.asarray(mesh.points, dtype=float)[:, :3], np.concatenate(triangles)


def read_particles(path):
    try:
        points = np.loadtxt(path, ndmin=2)
    except (OSError, ValueError) as error:
        sys.exit(f"render: {path}: not a particle file of 'x y z' lines ({error})")
    if points.shape[0] == 0 or points.shape[1] != 3 or not np.isfinite(points).all():
        sys.exit(f"render: {path}: expected one finite 'x y z' per line")
    return points


def vertex_normals(points, triangles):
    corners = points[triangles]
    face_normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    normals = np.zeros_like(points)
    for k in range(3):
        np.add.at(normals, triangles[:, k], face_normals)
    lengths = np.linalg.norm(normals, axis=1, keepdims=True)
    return normals / np.where(lengths > 0, lengths, 1), face_normals


def view_direction(elevation, azimuth):
    e, a = np.radians(elevation), np.radians(azimuth)
    return np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])


def draw(ax, points, triangles, particles, particle_normals, elevation, azimuth):
    corners = points[triangles]
    _, face_normals = vertex_normals(points, triangles)
    unit = face_normals / np.maximum(np.linalg.norm(face_normals, axis=1, keepdims=True), 1e-30)
    shade = 0.35 + 0.65 * np.abs(unit @ LIGHT)  # two-sided: open surfaces show their back
    colors = np.column_stack([0.78 * shade, 0.80 * shade, 0.84 * shade, np.ones_like(shade)])
    # Drawn in this order, dots on top: matplotlib cannot sort dots against
    # faces, so the particles facing away are left out instead.
    ax.computed_zorder = False
    ax.add_collection3d(Poly3DCollection(corners, facecolors=colors, edgecolors="none", zorder=1))
    towards_viewer = particle_normals @ view_direction(elevation, azimuth) > 0.05
    shown = particles[towards_viewer]
    ax.scatter(shown[:, 0], shown[:, 1], shown[:, 2], s=5, c="crimson", depthshade=False, zorder=2)
    low, high = points.min(axis=0), points.max(axis=0)
    centre, half = (low + high) / 2, (high - low).max() / 2
    ax.set(xlim=(centre[0] - half, centre[0] + half), ylim=(centre[1] - half, centre[1] + half),
           zlim=(centre[2] - half, centre[2] + half))
    ax.set_box_aspect((1, 1, 1))
    ax.view_init(elev=elevation, azim=azimuth)
    ax.set_axis_off()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mesh", type=Path, help="the mesh the particles lie on (OFF, PLY, OBJ, STL)")
    parser.add_argument("particles", nargs="+", type=Path, help="one or two particle files")
    parser.add_argument("--out", type=Path, help="PNG to write (default: next to the first particle file)")
    parser.add_argument("--labels", nargs="+", help="a title per particle file (default: their paths)")
    args = parser.parse_args()
    if len(args.particles) > 2:
        sys.exit("render: at most two particle files (side by side)")
    if args.labels and len(args.labels) != len(args.particles):
        sys.exit("render: give one --labels entry per particle file")
    points, triangles = read_mesh(args.mesh)
    normals, _ = vertex_normals(points, triangles)
    sets = [read_particles(path) for path in args.particles]
    labels = args.labels or [str(path) for path in args.particles]

    fig = plt.figure(figsize=(4.2 * len(VIEWS), 4.2 * len(sets)))
    for row, (particles, label) in enumerate(zip(sets, labels)):
        # Each particle takes the normal of its nearest vertex, to tell front from back.
        nearest = np.array([np.argmin(((points - p) ** 2).sum(axis=1)) for p in particles])
        for column, (view, elevation, azimuth) in enumerate(VIEWS):
            ax = fig.add_subplot(len(sets), len(VIEWS), row * len(VIEWS) + column + 1, projection="3d")
            draw(ax, points, triangles, particles, normals[nearest], elevation, azimuth)
            ax.set_title(f"{label}: {len(particles)} particles, {view}" if column == 0 else view, fontsize=9)
    fig.tight_layout()
    out = args.out or args.particles[0].with_suffix(".png")
    out.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(out, dpi=110)
    plt.close(fig)
    print(out)


if __name__ == "__main__":
    main()
