#!/usr/bin/python3
"""How far apart particle i lands across a population whose true correspondence is known.

    scripts/correspondence_error.py POPULATION.json PARTICLES... [--json FILE]

POPULATION.json is what `meshparticles generate --population N --family ellipsoid`
(or radii, or bent) writes beside its meshes: each shape's parameters and pose; or a population of
real shapes with a known vertex map, scored by scripts/map_correspondence_error.py (which
says how). PARTICLES are
"x y z" rows in the shapes' own (world) coordinates, row i the same particle
on every shape: `correspond`'s shapes/NNN_STEM.particles, `batch`'s
STEM/particles.particles, or any tool's file named after its mesh's stem.

Each particle's place is mapped back to the shapes' common parameter, the
unit sphere (u = normalize(diag(axes)^-1 x) of its unposed position x; for the bent family, of x
unbent off its arc first). The
spread of particle i is the mean great-circle distance of its places from
their mean direction, in particle spacings of the parameter sphere
(sqrt(8 pi / (sqrt(3) n)), the hexagonal spacing of n points on it). 0 is a
perfect correspondence; particles placed at random spread about 5 spacings
at n = 256. Prints the median, mean and 90th percentile over the particles,
the largest distance of a particle from its shape's surface (a particle
off the surface maps to a wrong parameter), and per shape (in --json's
per_shape) how far its particles lie from particle i's mean place on
average, and by what angle its particles are turned from those places as a
whole (a shape posed wrongly is turned by tens of degrees) and from the
first shape's (the template's, for correspond). Uses Debian's
python3-numpy.
"""
import argparse
import json
import math
import sys
from pathlib import Path

import numpy as np


def shape_of(file, shapes):
    """The population's shape a particle file belongs to, by its mesh's stem."""
    path = Path(file)
    for shape in shapes:
        stem = Path(shape["mesh"]).stem
        if path.stem == stem or path.stem.endswith("_" + stem) or path.parent.name == stem:
            return shape
    sys.exit(f"correspondence_error: {file}: no shape of the population is named like it")


def parameters(points, shape, population):
    """Each point's parameter on the unit sphere, and how far the point is off its shape's surface."""
    rotation = np.array(shape["rotation"])
    axes = np.array(shape["axes"])
    unposed = (points - np.array(shape["translation"])) @ rotation / shape["scale"]
    if population.get("family") in ("bent", "bent-either"):
        return bent_parameters(unposed, shape, population)
    u = unposed / axes
    u /= np.linalg.norm(u, axis=1, keepdims=True)
    bump = np.exp(-(1 - u @ np.array(population["bump_direction"])) / population["bump_width"])
    knob = np.exp(-(1 - u @ np.array(population["knob_direction"])) / population["knob_width"])
    radius = 1 + shape["bump_height"] * bump + shape["knob_height"] * knob
    on_surface = radius[:, None] * axes * u
    return u, np.linalg.norm(unposed - on_surface, axis=1)


def bent_parameters(unposed, shape, population):
    """The bent family's parameters: each unposed point unbent off its arc onto the straight body, whose
    parameter is the ellipsoid families' (population.json's "parameter" and "surface" say how)."""
    axes, bend_radius = np.array(shape["axes"]), shape["bend_radius"]
    # A body bent towards -x is the body turned half round its long axis,
    # bent towards +x and turned back (proper rotations: the bumps keep
    # their side).
    turn_half = np.array([-1.0, -1.0, 1.0]) if shape.get("bend_side", 1) < 0 else np.ones(3)
    unposed = unposed * turn_half
    across = np.hypot(unposed[:, 0] - bend_radius, unposed[:, 2])
    angle = np.arctan2(unposed[:, 2], bend_radius - unposed[:, 0])
    straight = np.stack([bend_radius - across, unposed[:, 1], bend_radius * angle], axis=1) * turn_half
    u = straight / axes
    u /= np.linalg.norm(u, axis=1, keepdims=True)
    radius = 1 - shape["waist_depth"] * np.exp(-(u[:, 2] / population["waist_width"]) ** 2)
    for bump, height in zip(population["bumps"], shape["bump_heights"]):
        radius += height * np.exp(-(1 - u @ np.array(bump["direction"])) / bump["width"])
    on_straight = radius[:, None] * axes * u * turn_half
    turn = on_straight[:, 2] / bend_radius
    on_surface = np.stack([bend_radius - (bend_radius - on_straight[:, 0]) * np.cos(turn), on_straight[:, 1],
                           (bend_radius - on_straight[:, 0]) * np.sin(turn)], axis=1)
    return u, np.linalg.norm(unposed - on_surface, axis=1)


def stacked(per_shape):
    """The files' points as one array, shapes x particles x 3; refused unless every file has as many."""
    counts = {len(points) for points in per_shape}
    if len(counts) != 1:
        sys.exit(f"correspondence_error: the files hold different numbers of particles: {sorted(counts)}")
    return np.stack(per_shape)


def spread(population, files):
    shapes = population["shapes"]
    per_shape, off_surface = [], 0.0
    for file in files:
        points = np.loadtxt(file, ndmin=2)
        u, off = parameters(points, shape_of(file, shapes), population)
        per_shape.append(u)
        off_surface = max(off_surface, float(off.max()))
    u = stacked(per_shape)
    mean = u.sum(axis=0)
    mean /= np.linalg.norm(mean, axis=1, keepdims=True)
    angle = np.arccos(np.clip(np.einsum("spk,pk->sp", u, mean), -1, 1))
    n = u.shape[1]
    spacing = math.sqrt(8 * math.pi / (math.sqrt(3) * n))
    per_particle = angle.mean(axis=0) / spacing
    return {
        "shapes": len(files),
        "particles": n,
        "median": float(np.median(per_particle)),
        "mean": float(per_particle.mean()),
        "p90": float(np.percentile(per_particle, 90)),
        "largest_off_surface": off_surface,
        "per_shape": [{"file": str(file), "mean": float(angle[s].mean() / spacing), "turn_degrees": turn_degrees(u[s], mean),
                       "turn_from_first_degrees": turn_degrees(u[s], u[0])}
                      for s, file in enumerate(files)],
    }


def turn_degrees(u, mean):
    """The angle of the rotation that best takes the particles' mean directions onto one shape's: a shape
    posed wrongly (turned, or upside down) is turned as a whole."""
    left, _, right = np.linalg.svd(mean.T @ u)
    proper = np.diag([1, 1, np.sign(np.linalg.det(right.T @ left.T))])
    turn = right.T @ proper @ left.T
    return math.degrees(math.acos(np.clip((np.trace(turn) - 1) / 2, -1, 1)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("population", type=Path)
    parser.add_argument("particles", nargs="+", type=Path)
    parser.add_argument("--json", type=Path, help="also write the figures here")
    args = parser.parse_args()
    if len(args.particles) < 2:
        sys.exit("correspondence_error: give the particle files of at least 2 shapes")
    population = json.loads(args.population.read_text())
    if "map" in population["shapes"][0]:  # real shapes with a known vertex map
        from map_correspondence_error import spread as spread_by_map
        result = spread_by_map(population, args.population.parent, args.particles)
        spacings, off = "particle spacings of the reference shape", ("a mapped vertex", result["largest_off_map"])
    else:
        result = spread(population, args.particles)
        spacings, off = "particle spacings", ("a surface", result["largest_off_surface"])
    print(f"spread of particle i across {result['shapes']} shapes, in {spacings} (n = {result['particles']}): "
          f"median {result['median']:.3f}, mean {result['mean']:.3f}, 90th percentile {result['p90']:.3f}; "
          f"largest distance off {off[0]} {off[1]:.2g}")
    worst = max(result["per_shape"], key=lambda shape: shape["mean"])
    line = (f"furthest shape from the others: {Path(worst['file']).name}, its particles {worst['mean']:.3f} spacings "
            f"from particle i's mean place on average")
    if "turn_degrees" in worst:
        turned = max(result["per_shape"], key=lambda shape: shape["turn_degrees"])
        line += f"; most turned: {Path(turned['file']).name}, {turned['turn_degrees']:.0f} degrees"
    print(line)
    if "between_shapes_root_area" in result:
        print(f"in the reference's square root of area: {result['from_centroid_root_area']:.4f} from particle i's "
              f"centroid, {result['between_shapes_root_area']:.4f} between two shapes (mean)")
    if args.json:
        args.json.write_text(json.dumps(result, indent=2) + "\n")


if __name__ == "__main__":
    main()
