"""How far apart particle i lands across real shapes whose vertex map is known.

    scripts/correspondence_error.py MAP_POPULATION.json PARTICLES... [--json FILE]

correspondence_error.py's measure for populations that are not generated (it calls spread()
here for a population whose shapes name a map): shapes each remeshed on their own, with a known
map given as vertex lists (FAUST-like .vts files: line k holds the vertex of this shape that is
sample k, the same sample on every shape).
MAP_POPULATION.json (what scripts/real_population.sh writes):

    {"one_based": true, "reference": 0,
     "shapes": [{"mesh": "shapes/tr_reg_000.off", "map": "maps/tr_reg_000.vts"}, ...]}

Paths are relative to the JSON's folder. Each particle is put at the sample whose vertex on its
own shape is nearest it, and that sample's place on the reference shape stands for it (the mean
place of all the samples the map sends to that vertex, where it sends several). The spread
of particle i is the mean straight-line distance of its places on the reference shape from their
centroid, in particle spacings of the reference shape (sqrt(2 A / (sqrt(3) n)), A its area):
0 is a perfect correspondence. Straight lines, not geodesics: parts that touch through the air
(an arm against the body) read closer than they are. Prints the median, mean and 90th percentile
over the particles, the largest distance from a particle to its sample's vertex (the map's
own resolution on the shape), and per shape (in --json's per_shape) how far its particles lie from
particle i's centroid on average. Also in √A: the mean distance from the centroid, and the mean
distance between two shapes' places (the measure shape-matching papers publish, with geodesics). Files are matched to shapes by stem, as correspondence_error.py
matches them. Uses Debian's python3-numpy.
"""
import math
import sys
from pathlib import Path

import numpy as np

from correspondence_error import shape_of, stacked  # files matched to shapes by their mesh's stem


def off_mesh(path):
    """Vertices and triangles of an OFF file."""
    words = Path(path).read_text().split()
    if not words or words[0] != "OFF":
        sys.exit(f"map_correspondence_error: {path}: not an OFF file")
    vertices, faces = int(words[1]), int(words[2])
    points = np.array(words[4:4 + 3 * vertices], dtype=float).reshape(vertices, 3)
    rest, triangles, at = words[4 + 3 * vertices:], [], 0
    for _ in range(faces):
        corners = int(rest[at])
        ids = [int(v) for v in rest[at + 1:at + 1 + corners]]
        triangles += [(ids[0], ids[k], ids[k + 1]) for k in range(1, corners - 1)]
        at += 1 + corners
    return points, np.array(triangles, dtype=int)


def area(points, triangles):
    a, b, c = (points[triangles[:, k]] for k in range(3))
    return 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1).sum()


def reference_places(points, sample_places, reference_samples):
    """For each of POINTS, the mean reference place of the samples nearest it, and the distance to them.

    A map may send several samples to one vertex; each point takes them all, averaged.
    """
    places, distance = np.empty((len(points), 3)), np.empty(len(points))
    for start in range(0, len(points), 256):
        squared = ((points[start:start + 256, None, :] - sample_places[None, :, :]) ** 2).sum(axis=2)
        least = squared.min(axis=1, keepdims=True)
        ties = squared <= least * (1 + 1e-9) + 1e-300
        places[start:start + 256] = (ties @ reference_samples) / ties.sum(axis=1, keepdims=True)
        distance[start:start + 256] = np.sqrt(least[:, 0])
    return places, distance


def spread(population, folder, files):
    base = 1 if population.get("one_based", True) else 0
    shapes = population["shapes"]
    sample_vertices = {}
    for shape in shapes:
        sample_vertices[shape["mesh"]] = np.loadtxt(folder / shape["map"], dtype=int, ndmin=1) - base
    reference = shapes[population.get("reference", 0)]
    reference_points, reference_triangles = off_mesh(folder / reference["mesh"])
    reference_samples = reference_points[sample_vertices[reference["mesh"]]]
    places, off_map = [], 0.0
    for file in files:
        shape = shape_of(file, shapes)
        points, _ = off_mesh(folder / shape["mesh"])
        place, distance = reference_places(np.loadtxt(file, ndmin=2), points[sample_vertices[shape["mesh"]]],
                                           reference_samples)
        places.append(place)
        off_map = max(off_map, float(distance.max()))
    places = stacked(places)
    n = places.shape[1]
    root_area = math.sqrt(area(reference_points, reference_triangles))
    spacing = root_area * math.sqrt(2 / (math.sqrt(3) * n))
    offset = np.linalg.norm(places - places.mean(axis=0), axis=2) / spacing
    per_particle = offset.mean(axis=0)
    # What papers publish: the mean error between two shapes (geodesic there, straight here) over
    # √A; about 1.4 times the mean distance from the centroid for errors independent per shape.
    apart = [np.linalg.norm(places[a] - places[b], axis=1).mean()
             for a in range(len(places)) for b in range(a + 1, len(places))]
    return {"shapes": len(files), "particles": n, "median": float(np.median(per_particle)),
            "mean": float(per_particle.mean()), "p90": float(np.percentile(per_particle, 90)),
            "from_centroid_root_area": float(per_particle.mean() * spacing / root_area),
            "between_shapes_root_area": float(np.mean(apart) / root_area),
            "largest_off_map": off_map, "spacing": spacing,
            "per_shape": [{"file": str(file), "mean": float(offset[s].mean())} for s, file in enumerate(files)]}
