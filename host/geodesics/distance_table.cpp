#include "geodesics/distance_table.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <thread>

#include "common/progress.hpp"
#include "common/worker_threads.hpp"
#include "geodesics/memory_guard.hpp"
#include "geodesics/solver_factory.hpp"

namespace meshparticles {

void DistanceTable::distances_from(VertexId u, std::span<const VertexId> targets, std::span<float> out) const {
  const auto from_u = row(u);
  for (std::size_t k = 0; k < targets.size(); ++k) out[k] = from_u[targets[k]];
}

void DistanceTable::for_each_marked_within(VertexId u, float radius, std::span<const std::uint8_t> marked,
                                           VertexId first, const std::function<void(VertexId, float)>& visit) const {
  const auto from_u = row(u);
  for (std::size_t v = first; v < vertex_count_; ++v) {
    if (marked[v] && from_u[v] <= radius) visit(VertexId(v), from_u[v]);
  }
}

void symmetrize_by_averaging(DistanceTable& table) {
  constexpr std::size_t kBlock = 64;
  const std::size_t n = table.vertex_count();
  auto values = table.values();
  for (std::size_t bi = 0; bi < n; bi += kBlock) {
    for (std::size_t bj = bi; bj < n; bj += kBlock) {
      for (std::size_t i = bi; i < std::min(bi + kBlock, n); ++i) {
        for (std::size_t j = std::max(bj, i + 1); j < std::min(bj + kBlock, n); ++j) {
          // inf + inf stays inf (different components); no NaN can arise.
          const float mean = 0.5f * (values[i * n + j] + values[j * n + i]);
          values[i * n + j] = values[j * n + i] = mean;
        }
      }
    }
  }
}

DistanceTable compute_all_pairs(const SurfaceMesh& mesh, GeodesicMethod method, unsigned threads, bool quiet) {
  const std::size_t n = mesh.vertex_count();
  check_table_fits(n, sizeof(float), usable_host_memory_bytes(), "distance table", usable_host_memory_name());
  DistanceTable table(n);
  const auto solver = make_geodesic_solver(mesh, method, cores_or(threads));

  std::atomic<std::size_t> next_source{0}, done{0};
  // A worker that fails (out of memory) hands its exception to this thread,
  // which rethrows it after joining: a clean error, not std::terminate.
  std::exception_ptr failure;
  std::mutex failure_mutex;
  const auto work = [&] {
    try {
      SolverScratch scratch;
      std::vector<double> distances(n);
      for (std::size_t source = next_source++; source < n; source = next_source++) {
        solver->solve(VertexId(source), distances, scratch);
        auto row = table.row(VertexId(source));
        std::transform(distances.begin(), distances.end(), row.begin(), [](double d) { return float(d); });
        row[source] = 0.0f;
        ++done;
      }
    } catch (...) {
      const std::lock_guard lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      next_source = n;  // the other workers stop too
      done = n;
    }
  };
  threads = cores_or(threads);
  threads = unsigned(std::min<std::size_t>(threads, std::max<std::size_t>(n, 1)));

  ProgressLine progress("geodesics (" + method_name(method) + ", " + std::to_string(threads) + " threads)", n, quiet);
  WorkerThreads workers(threads, [&](unsigned) { work(); });
  if (workers.started() == 0) work();  // no thread could start: this one does it all
  try {
    while (done < n) {
      progress.update(done);
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  } catch (...) {  // interrupted: the workers stop at their next source
    next_source = n;
    throw;  // WorkerThreads joins them
  }
  workers.join();
  if (failure) std::rethrow_exception(failure);
  symmetrize_by_averaging(table);
  progress.update(n);
  progress.finish();
  return table;
}

}  // namespace meshparticles
