// Whole iterations of the colored and monotone schemes in one launch of one
// work-group: every colour's decisions, commit and field update, the energy
// check and the monotone scheme's undo and retry, with barriers between them
// instead of launches and host reads between them (docs/ALGORITHM.md,
// "One-launch iterations"). The same helpers as the per-colour kernels make
// the same moves: field_decide (field.h), commit_claimed_move (claims.h) and
// apply_color_moves (field_rows.h).
//
// One work-group is the whole launch, so barrier() orders every phase: OpenCL
// 1.2 has no barrier across work-groups. Every loop that holds a barrier runs
// the same trips on every work-item: its bounds are arguments, or values
// read after a barrier.
#include "field_rows.h"

#ifndef WORK_GROUP_SIZE
#define WORK_GROUP_SIZE 64
#endif

// history: [0] the iterations run, [1] the energy before the first, then per
// iteration HISTORY_WORDS words: particles moved, energy after (field units,
// every pair counted from both ends), attempts, and the kept attempt's
// colours (KEPT_SEQUENTIAL, KEPT_NONE: no attempt lowered the energy).
#define HISTORY_WORDS 4
#define KEPT_SEQUENTIAL 0
#define KEPT_NONE 0xffffffffUL

// The host's schemes compare energies as doubles (the serial twin sums the
// same units exactly and rounds once): x rounded to 53 significant bits,
// ties to even, compares as that double does. Sums of n < 4096 particles'
// energies stay below 2^64 (the host checks n).
static inline ulong rounded_as_double(ulong x) {
  if (x < (1UL << 53)) return x;
  const uint dropped = 11 - (uint)clz(x);
  const ulong unit = 1UL << dropped, rest = x & (unit - 1), kept = x - rest, halfway = unit >> 1;
  return rest > halfway || (rest == halfway && (kept & unit)) ? kept + unit : kept;
}

// Every particle's energy where it is, summed by the whole work-group.
static inline ulong energy_units(__global const long* field, __global const weight_t* weights, uint vertex_count,
                                 __global const uint* positions, uint particle_count, __local ulong* partial) {
  const uint item = (uint)get_local_id(0);
  ulong sum = 0;
  for (uint c = item; c < particle_count; c += WORK_GROUP_SIZE) {
    sum += (ulong)particle_energy_units(c, field, weights, vertex_count, positions);
  }
  partial[item] = sum;
  barrier(CLK_LOCAL_MEM_FENCE);
  if (item == 0) {
    for (uint i = 1; i < WORK_GROUP_SIZE; ++i) sum += partial[i];
    partial[0] = sum;
  }
  barrier(CLK_LOCAL_MEM_FENCE);
  const ulong total = partial[0];
  barrier(CLK_LOCAL_MEM_FENCE);  // before partial is written again
  return total;
}

// One attempt: `groups` sub-steps (colours), each deciding from the same
// snapshot, committing, then updating F, as the per-colour launches do.
// rank_stacks 0 is the sequential rule. Returns the particles moved.
static inline uint run_attempt(uint groups, uint rank_stacks, __global long* field,
                               __global const weight_t* weights, uint vertex_count,
                               __global const uint* ring_offsets, __global const uint* ring_neighbors,
                               __global uint* occupancy, __global uint* positions, uint particle_count,
                               __global uint* chosen, __global uint* claims, __global uint* move_counts,
                               __global uint2* moves) {
  const uint item = (uint)get_local_id(0);
  const uint counted = min(groups, particle_count);  // colours that hold a particle
  for (uint k = item; k < counted; k += WORK_GROUP_SIZE) move_counts[k] = 0;
  barrier(CLK_GLOBAL_MEM_FENCE);
  uint moved = 0;
  for (uint color = 0; color < counted; ++color) {
    const uint first_particle = color + item * groups, stride = WORK_GROUP_SIZE * groups;
    for (uint c = first_particle; c < particle_count; c += stride) {
      field_decide(c, field, weights, vertex_count, ring_offsets, ring_neighbors, occupancy, positions, rank_stacks,
                   chosen, claims);
    }
    barrier(CLK_GLOBAL_MEM_FENCE);  // every choice made from the same snapshot
    for (uint c = first_particle; c < particle_count; c += stride) {
      commit_claimed_move(c, color, groups, particle_count, positions, chosen, claims, move_counts, moves);
    }
    barrier(CLK_GLOBAL_MEM_FENCE);  // the colour's moves listed and counted
    const uint count = move_counts[color];
    if (count > 0) {
      for (uint first = item * VERTICES_PER_ITEM; first < vertex_count; first += WORK_GROUP_SIZE * VERTICES_PER_ITEM) {
        apply_color_moves(weights, vertex_count, positions, particle_count, color, groups, count, moves, first, field,
                          occupancy);
      }
      barrier(CLK_GLOBAL_MEM_FENCE);  // F follows before the next colour decides
    }
    moved += count;
  }
  return moved;
}

// Puts the particles back where the attempt started and F with them: the
// attempt's listed moves reversed, or all n rows summed again when it moved
// more than half the particles. Integer sums: the same bits either way.
static inline void undo_attempt(uint groups, uint moved, __global long* field, __global const weight_t* weights,
                                uint vertex_count, __global uint* occupancy, __global uint* positions,
                                __global const uint* start_positions, uint particle_count,
                                __global const uint* move_counts, __global const uint2* moves) {
  const uint item = (uint)get_local_id(0);
  for (uint c = item; c < particle_count; c += WORK_GROUP_SIZE) positions[c] = start_positions[c];
  barrier(CLK_GLOBAL_MEM_FENCE);
  const uint counted = min(groups, particle_count), capacity = moves_capacity(particle_count, groups);
  for (uint first = item * VERTICES_PER_ITEM; first < vertex_count; first += WORK_GROUP_SIZE * VERTICES_PER_ITEM) {
    if (2 * moved > particle_count) {
      sum_rows(weights, vertex_count, positions, particle_count, first, field, occupancy);
    } else {
      for (uint color = 0; color < counted; ++color) {
        add_listed_moves(weights, vertex_count, first, moves + color * capacity, move_counts[color], 1, field,
                         occupancy);
      }
    }
  }
  barrier(CLK_GLOBAL_MEM_FENCE);
}

// Up to `iterations` iterations of colored K = `colors`, or of monotone
// (`monotone` 1: an attempt that moved particles without lowering the
// energy is undone and tried with twice the colours, then as the sequential
// loop, then nothing moves: host/particles/scheme_step.cpp). Stops after an
// iteration that moved nothing. Launch exactly one work-group.
__kernel __attribute__((reqd_work_group_size(WORK_GROUP_SIZE, 1, 1)))
void field_iterations(__global long* field, __global const weight_t* weights, uint vertex_count,
                      __global const uint* ring_offsets, __global const uint* ring_neighbors,
                      __global uint* occupancy, __global uint* positions, uint particle_count, uint colors,
                      uint monotone, uint iterations, __global uint* chosen, __global uint* claims,
                      __global uint* move_counts, __global uint2* moves, __global uint* start_positions,
                      __global ulong* history) {
  __local ulong partial[WORK_GROUP_SIZE];
  const uint item = (uint)get_local_id(0);
  ulong before = energy_units(field, weights, vertex_count, positions, particle_count, partial);
  if (item == 0) history[1] = before;
  uint run = 0;
  while (run < iterations) {
    for (uint c = item; c < particle_count; c += WORK_GROUP_SIZE) start_positions[c] = positions[c];
    uint groups = colors, rank_stacks = 1;
    if (monotone && groups >= particle_count) groups = particle_count, rank_stacks = 0;
    uint attempts = 0, moved = 0;
    ulong after = before, kept = 0;
    for (;;) {
      moved = run_attempt(groups, rank_stacks, field, weights, vertex_count, ring_offsets, ring_neighbors,
                          occupancy, positions, particle_count, chosen, claims, move_counts, moves);
      ++attempts;
      after = energy_units(field, weights, vertex_count, positions, particle_count, partial);
      if (!monotone || moved == 0 || rounded_as_double(after) < rounded_as_double(before)) {
        kept = rank_stacks ? groups : KEPT_SEQUENTIAL;
        break;
      }
      undo_attempt(groups, moved, field, weights, vertex_count, occupancy, positions, start_positions,
                   particle_count, move_counts, moves);
      if (!rank_stacks) {  // not even the sequential loop lowered it
        moved = 0, after = before, kept = KEPT_NONE;
        break;
      }
      groups *= 2;
      if (groups >= particle_count) groups = particle_count, rank_stacks = 0;
    }
    if (item == 0) {
      __global ulong* record = history + 2 + HISTORY_WORDS * run;
      record[0] = moved, record[1] = after, record[2] = attempts, record[3] = kept;
    }
    before = after;
    ++run;
    if (moved == 0) break;
  }
  if (item == 0) history[0] = run;
}
