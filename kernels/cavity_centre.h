// The centre of a particle's cavity: the point of its region of the
// geodesic Voronoi diagram farthest, along the surface, from the particles
// around it. Farthest-point optimization moves a particle there (spread's
// evening, host/particles/local_farthest_points); taken away, a particle
// leaves its region to its neighbours, so the farthest point from them
// lies in it.
//
// Each particle around brings its ball (the vertices within a reach of it,
// with fast marching's distances). In a triangle whose three corners a
// ball reaches, that particle is a source laid in the triangle's plane
// (planar_source.h), so a triangle's farthest point from all of them is
// plane geometry: the centre of the circle through three sources, a point
// of an edge two sources are equally near, or a corner. Straight lines in a
// tangent plane, used up to 0.24.0, misread a curved part's neighbours by
// several per cent, and the move most needed was never proposed
// (docs/ALGORITHM.md, "Evening").
//
// One definition for the host (host/particles/cavity_centre, C++) and the
// device (evening_moves.cl, one work-item a particle), in double as
// planar_source.h: the same bits on both. Each call works in its own
// scratch, whose sizes cavity_scratch_sizes gives before the call.
#ifndef CAVITY_CENTRE_H
#define CAVITY_CENTRE_H

#include "host_or_device.h"
#include "planar_source.h"

// A ball's entry: a vertex and its distance from the ball's particle.
typedef struct {
  unsigned int vertex;
  float distance;
} ball_entry;

// The surface: its vertices, triangles (3 corners each) and each vertex's
// triangles (fans[fan_start[v]] to fans[fan_start[v + 1] - 1]).
typedef struct {
  const GLOBAL_MEMORY vec3d* positions;
  const GLOBAL_MEMORY unsigned int* triangles;
  const GLOBAL_MEMORY unsigned int* fan_start;
  const GLOBAL_MEMORY unsigned int* fans;
} cavity_surface;

// The particles: where each stands and its ball, entries[ball_start[k]] to
// entries[ball_start[k] + ball_size[k] - 1], in increasing vertex order.
typedef struct {
  const GLOBAL_MEMORY vec3d* points;
  const GLOBAL_MEMORY ball_entry* entries;
  const GLOBAL_MEMORY unsigned int* ball_start;
  const GLOBAL_MEMORY unsigned int* ball_size;
} cavity_particles;

// One particle's cavity.
typedef struct {
  unsigned int triangle;  // where the particle stands: its triangle
  vec3d at;               // and its point
  const GLOBAL_MEMORY unsigned int* region;  // the vertices it owns
  unsigned int region_size;
  const GLOBAL_MEMORY unsigned int* near;  // the particles whose regions touch its own
  unsigned int near_size;
  // Particles further out: each counts only where its straight line (no
  // longer than its way along the surface) to some vertex of the region is
  // under the widest gap found without them.
  const GLOBAL_MEMORY unsigned int* further;
  unsigned int further_size;
} cavity;

// What a call works in. The triangles of the cavity's fans (at most
// `triangles` of cavity_scratch_sizes), each once, and a hash table that
// finds each one's place; their corners (at most `corners`), each once, a
// row of the table, and a hash table that finds each one's row; the table,
// a column a source (at most `sources`), its distance at each row (+inf
// beyond its ball); per row the nearest source's distance; per triangle
// its corners' rows, each corner's way to the farther other corner, and a
// bound on its farthest point. No sort: the hash tables keep first
// arrivals' order, which no result depends on (the search's ties go by
// triangle index), where a heap sort of the corners made the host's
// evening a fifth slower.
typedef struct {
  GLOBAL_MEMORY unsigned int* triangles;    // triangles
  GLOBAL_MEMORY double* bounds;             // triangles
  GLOBAL_MEMORY unsigned int* triangle_slots;  // 2 x triangle_slots: the triangles' index, by hash
  GLOBAL_MEMORY unsigned int* vertex_slots;    // 2 x vertex_slots: the rows, by hash
  GLOBAL_MEMORY unsigned int* vertices;     // corners
  GLOBAL_MEMORY unsigned int* corner_rows;  // corners
  GLOBAL_MEMORY double* ways;               // corners
  GLOBAL_MEMORY float* nearest;             // corners
  GLOBAL_MEMORY float* table;               // sources x corners
  GLOBAL_MEMORY planar_source* planar;      // sources
  GLOBAL_MEMORY unsigned int* near;         // sources
} cavity_scratch;

// The scratch's sizes for `c`: triangles, corners (3 a triangle), sources,
// and the hash tables' slots (a power of two, at least twice the entries).
typedef struct {
  unsigned int triangles, corners, sources, triangle_slots, vertex_slots;
} cavity_scratch_size;

static inline unsigned int hash_slots_for(unsigned int entries) {
  unsigned int slots = 16;
  while (slots < 2 * entries) slots *= 2;
  return slots;
}

static inline cavity_scratch_size cavity_scratch_sizes(cavity_surface mesh, cavity c) {
  cavity_scratch_size size;
  size.triangles = 1;
  for (unsigned int r = 0; r < c.region_size; ++r) {
    size.triangles += mesh.fan_start[c.region[r] + 1] - mesh.fan_start[c.region[r]];
  }
  size.corners = 3 * size.triangles;
  size.sources = c.near_size + c.further_size;
  size.triangle_slots = hash_slots_for(size.triangles);
  size.vertex_slots = hash_slots_for(size.corners);
  return size;
}

// What cavity_centre found: the farthest point (its triangle, the corners'
// weights and the point), its distance from the nearest particle around,
// and the same from where the particle stands.
typedef struct {
  unsigned int triangle;
  double weights[3];
  vec3d at;
  double away, here;
} cavity_found;

// A set of ids, each with the place it was given: open addressing in
// `slots` (a power of two of them, two words each: the id + 1, 0 where
// empty, and its place), the places given in order of first insertion.
typedef struct {
  GLOBAL_MEMORY unsigned int* slots;
  unsigned int mask;  // slots - 1
} id_places;

static inline id_places empty_id_places(GLOBAL_MEMORY unsigned int* slots, unsigned int count) {
  for (unsigned int k = 0; k < 2 * count; ++k) slots[k] = 0;
  id_places places;
  places.slots = slots;
  places.mask = count - 1;
  return places;
}

// Where id's slot is, or the empty one it would take.
static inline unsigned int id_slot(id_places places, unsigned int id) {
  unsigned int slot = (id * 2654435761u) & places.mask;
  while (places.slots[2 * slot] != 0 && places.slots[2 * slot] != id + 1) slot = (slot + 1) & places.mask;
  return slot;
}

// id's place; `next` where it is new (and next then counts it).
static inline unsigned int id_place(id_places places, unsigned int id, unsigned int* next) {
  const unsigned int slot = id_slot(places, id);
  if (places.slots[2 * slot] == 0) {
    places.slots[2 * slot] = id + 1;
    places.slots[2 * slot + 1] = (*next)++;
  }
  return places.slots[2 * slot + 1];
}

// id's place, or `none` where it has none.
static inline unsigned int id_place_or(id_places places, unsigned int id, unsigned int none) {
  const unsigned int slot = id_slot(places, id);
  return places.slots[2 * slot] == 0 ? none : places.slots[2 * slot + 1];
}

// The work of one call: the scratch and how much of it is in use.
typedef struct {
  cavity_scratch s;
  id_places triangle_places, rows_of;
  unsigned int triangles, rows, sources;
} cavity_work;

// The triangles of the cavity (the fans of its region's vertices, and the
// particle's own triangle) and their corners, each corner given its row
// and its way to the farther other corner of its triangle.
static inline void gather_cavity(cavity_surface mesh, cavity c, cavity_scratch_size size, cavity_work* w) {
  w->triangle_places = empty_id_places(w->s.triangle_slots, size.triangle_slots);
  w->rows_of = empty_id_places(w->s.vertex_slots, size.vertex_slots);
  w->triangles = 0;
  for (unsigned int r = 0; r < c.region_size; ++r) {
    const unsigned int v = c.region[r];
    for (unsigned int k = mesh.fan_start[v]; k < mesh.fan_start[v + 1]; ++k) {
      const unsigned int before = w->triangles;
      if (id_place(w->triangle_places, mesh.fans[k], &w->triangles) == before) w->s.triangles[before] = mesh.fans[k];
    }
  }
  const unsigned int before = w->triangles;
  if (id_place(w->triangle_places, c.triangle, &w->triangles) == before) w->s.triangles[before] = c.triangle;
  w->rows = 0;
  for (unsigned int i = 0; i < w->triangles; ++i) {
    const GLOBAL_MEMORY unsigned int* corner = mesh.triangles + 3 * w->s.triangles[i];
    for (unsigned int k = 0; k < 3; ++k) {
      const vec3d here = mesh.positions[corner[k]];
      w->s.ways[3 * i + k] = larger(vec3d_distance(here, mesh.positions[corner[(k + 1) % 3]]),
                                    vec3d_distance(here, mesh.positions[corner[(k + 2) % 3]]));
      const unsigned int rows = w->rows;
      const unsigned int row = id_place(w->rows_of, corner[k], &w->rows);
      if (row == rows) w->s.vertices[row] = corner[k];
      w->s.corner_rows[3 * i + k] = row;
    }
  }
  for (unsigned int r = 0; r < w->rows; ++r) w->s.nearest[r] = INFINITY;
  w->sources = 0;
}

// Particle k's ball added as a source: its column of the table (its
// distances at the rows; +inf beyond it), and each row's nearest lowered.
static inline void add_cavity_source(cavity_particles particles, unsigned int k, cavity_work* w) {
  GLOBAL_MEMORY float* column = w->s.table + w->sources * w->rows;
  ++w->sources;
  for (unsigned int r = 0; r < w->rows; ++r) column[r] = INFINITY;
  const GLOBAL_MEMORY ball_entry* entry = particles.entries + particles.ball_start[k];
  const GLOBAL_MEMORY ball_entry* end = entry + particles.ball_size[k];
  for (; entry != end; ++entry) {
    const unsigned int row = id_place_or(w->rows_of, entry->vertex, w->rows);
    if (row < w->rows) column[row] = entry->distance;
  }
  for (unsigned int r = 0; r < w->rows; ++r) w->s.nearest[r] = column[r] < w->s.nearest[r] ? column[r] : w->s.nearest[r];
}

// Per triangle, a bound on how far any of its points is from the sources:
// no point of a triangle is farther than a corner's nearest source plus the
// way to the farthest other corner.
static inline void bound_cavity_triangles(cavity_work* w) {
  for (unsigned int i = 0; i < w->triangles; ++i) {
    double bound = (double)INFINITY;
    for (unsigned int k = 0; k < 3; ++k) {
      bound = smaller(bound, (double)w->s.nearest[w->s.corner_rows[3 * i + k]] + w->s.ways[3 * i + k]);
    }
    w->s.bounds[i] = bound;
  }
}

// The sources of gathered triangle i in `frame`: each source whose ball
// reaches all three corners; how many.
static inline unsigned int planar_sources(plane_frame frame, unsigned int i, cavity_work* w) {
  unsigned int count = 0;
  for (unsigned int k = 0; k < w->sources; ++k) {
    const GLOBAL_MEMORY float* column = w->s.table + k * w->rows;
    double d[3];
    int reached = 1;
    for (unsigned int c = 0; c < 3; ++c) {
      d[c] = (double)column[w->s.corner_rows[3 * i + c]];
      reached = reached && isfinite(d[c]);
    }
    if (reached) w->s.planar[count++] = planar_source_of(frame, d[0], d[1], d[2]);
  }
  return count;
}

// The distance of (x, y) from the nearest of the first `count` planar
// sources (all of them: `near` 0), or of the `count` that w->s.near lists.
static inline double nearest_planar(plane_frame frame, const cavity_work* w, unsigned int count, int near, double x,
                                    double y) {
  double nearest = (double)INFINITY;
  for (unsigned int k = 0; k < count; ++k) {
    const planar_source s = w->s.planar[near ? w->s.near[k] : k];
    nearest = smaller(nearest, planar_source_distance(frame, s, x, y));
  }
  return nearest;
}

// (x, y) of triangle `t`'s frame taken as the farthest point where it is
// in the triangle and farther from the near sources than the farthest yet.
static inline void consider_point(plane_frame frame, unsigned int t, const cavity_work* w, unsigned int near_count,
                                  double x, double y, cavity_found* widest) {
  if (!frame_holds(frame, x, y)) return;
  const double away = nearest_planar(frame, w, near_count, 1, x, y);
  if (!(away > widest->away)) return;
  widest->away = away;
  widest->triangle = t;
  frame_weights(frame, x, y, widest->weights);
  widest->at = frame_point(frame, x, y);
}

// The farthest point of gathered triangle i from its sources, where farther
// than `widest`: a corner, a point of an edge two sources are equally near,
// or the centre of the circle through three.
static inline void search_triangle(cavity_surface mesh, unsigned int i, cavity_work* w, cavity_found* widest) {
  const unsigned int t = w->s.triangles[i];
  const GLOBAL_MEMORY unsigned int* corner = mesh.triangles + 3 * t;
  const plane_frame f =
      frame_of_corners(mesh.positions[corner[0]], mesh.positions[corner[1]], mesh.positions[corner[2]]);
  if (frame_degenerate(f)) return;
  const unsigned int planar = planar_sources(f, i, w);
  if (planar == 0) return;
  // Only the sources within two longest edges of the nearest at the
  // centroid can be the nearest anywhere in the triangle.
  const double gx = (f.b + f.cx) / 3, gy = f.cy / 3;
  const double longest = larger(larger(f.b, planar_distance(f.cx, f.cy)), planar_distance(f.cx - f.b, f.cy));
  const double nearest = nearest_planar(f, w, planar, 0, gx, gy);
  unsigned int near = 0;
  for (unsigned int k = 0; k < planar; ++k) {
    if (planar_source_distance(f, w->s.planar[k], gx, gy) <= nearest + 2 * longest) w->s.near[near++] = k;
  }
  for (int c = 0; c < 3; ++c) consider_point(f, t, w, near, frame_corner_x(f, c), frame_corner_y(f, c), widest);
  for (unsigned int a = 0; a < near; ++a) {
    for (unsigned int b = a + 1; b < near; ++b) {
      // Where the line of points equally near a and b (straight lines:
      // the offsets are left out of where, not of how far) crosses an edge.
      const planar_source p = w->s.planar[w->s.near[a]], q = w->s.planar[w->s.near[b]];
      const double ex = q.x - p.x, ey = q.y - p.y;
      const double middle = (q.x * q.x + q.y * q.y - p.x * p.x - p.y * p.y) / 2;
      for (int e = 0; e < 3; ++e) {
        const double from_x = frame_corner_x(f, e), from_y = frame_corner_y(f, e);
        const double dx = frame_corner_x(f, (e + 1) % 3) - from_x, dy = frame_corner_y(f, (e + 1) % 3) - from_y;
        const double slope = dx * ex + dy * ey;
        if (slope == 0) continue;
        const double along = (middle - from_x * ex - from_y * ey) / slope;
        if (along > 0 && along < 1) consider_point(f, t, w, near, from_x + along * dx, from_y + along * dy, widest);
      }
      for (unsigned int c = b + 1; c < near; ++c) {
        // The centre of the circle through p, q and r, where they are not on a line.
        const planar_source r = w->s.planar[w->s.near[c]];
        const double d = 2 * (p.x * (q.y - r.y) + q.x * (r.y - p.y) + r.x * (p.y - q.y));
        if (fabs(d) < 1e-300) continue;
        const double p2 = p.x * p.x + p.y * p.y, q2 = q.x * q.x + q.y * q.y, r2 = r.x * r.x + r.y * r.y;
        const double x = (p2 * (q.y - r.y) + q2 * (r.y - p.y) + r2 * (p.y - q.y)) / d;
        const double y = (p2 * (r.x - q.x) + q2 * (p.x - r.x) + r2 * (q.x - p.x)) / d;
        consider_point(f, t, w, near, x, y, widest);
      }
    }
  }
}

// The point of the triangles around the cavity's region (and the
// particle's own triangle) farthest from the particles listed, each
// through its ball (a particle's distances beyond its ball: none, there
// others are nearer); away -inf where none is found. Ties go to the point
// found first: the triangles are searched by decreasing bound, then
// increasing index, until none left can hold a farther point.
// `scratch` holds `size`, cavity_scratch_sizes(mesh, c).
static inline cavity_found cavity_centre(cavity_surface mesh, cavity_particles particles, cavity c,
                                         cavity_scratch scratch, cavity_scratch_size size) {
  cavity_work w;
  w.s = scratch;
  gather_cavity(mesh, c, size, &w);
  for (unsigned int k = 0; k < c.near_size; ++k) add_cavity_source(particles, c.near[k], &w);
  // A particle further out is d >= its straight line >= that to `at` less
  // the farthest corner's from `at`. No point of the cavity is farther from
  // the near particles than the widest triangle's bound; one no nearer than
  // that to every point changes nothing, and is left out (the widest gap
  // found with the near particles alone, a second search, left out the
  // same particles and a few more: the same bytes on the 92 corpus runs).
  // (A triangle no near particle reaches at any corner holds no reading:
  // its bound, infinite, bounds nothing found.)
  bound_cavity_triangles(&w);
  double widest_bound = -(double)INFINITY;
  for (unsigned int i = 0; i < w.triangles; ++i) {
    if (isfinite(w.s.bounds[i])) widest_bound = larger(widest_bound, w.s.bounds[i]);
  }
  double reach = 0;
  for (unsigned int r = 0; r < w.rows; ++r) reach = larger(reach, vec3d_distance(c.at, mesh.positions[w.s.vertices[r]]));
  const unsigned int near_count = w.sources;
  for (unsigned int k = 0; k < c.further_size; ++k) {
    if (vec3d_distance(c.at, particles.points[c.further[k]]) - reach <= widest_bound) {
      add_cavity_source(particles, c.further[k], &w);
    }
  }
  if (w.sources > near_count) bound_cavity_triangles(&w);

  cavity_found widest;
  widest.triangle = c.triangle;
  widest.weights[0] = widest.weights[1] = widest.weights[2] = 0;
  widest.at.x = widest.at.y = widest.at.z = 0;
  widest.away = -(double)INFINITY;
  widest.here = (double)INFINITY;
  const unsigned int own = id_place_or(w.triangle_places, c.triangle, w.triangles);
  const GLOBAL_MEMORY unsigned int* corner = mesh.triangles + 3 * c.triangle;
  const plane_frame f =
      frame_of_corners(mesh.positions[corner[0]], mesh.positions[corner[1]], mesh.positions[corner[2]]);
  if (!frame_degenerate(f)) {
    widest.here = nearest_planar(f, &w, planar_sources(f, own, &w), 0, frame_x(f, c.at), frame_y(f, c.at));
  }
  // The triangle of widest bound not yet searched (ties: the lower
  // index); a searched one's bound is set to -inf (every other is at least 0).
  for (;;) {
    unsigned int next = 0;
    for (unsigned int i = 1; i < w.triangles; ++i) {
      if (w.s.bounds[i] > w.s.bounds[next] ||
          (w.s.bounds[i] == w.s.bounds[next] && w.s.triangles[i] < w.s.triangles[next])) {
        next = i;
      }
    }
    if (w.triangles == 0 || !(w.s.bounds[next] > widest.away)) break;
    w.s.bounds[next] = -(double)INFINITY;
    search_triangle(mesh, next, &w, &widest);
  }
  return widest;
}

#endif
