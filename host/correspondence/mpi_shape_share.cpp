// ShapeShare under mpirun: rank r owns the r-th block of shapes, and the
// gathers are MPI all-gathers (every rank receives every block, in shape
// order). Only the main thread calls MPI: the threads of a rank work on its
// own shapes between the calls.
#include <mpi.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <thread>

#include "correspondence/shape_share.hpp"

namespace meshparticles {

namespace {

struct Launch {
  int rank = 0, processes = 1;
  unsigned threads = 1;  // the node's cores divided among its ranks
};

Launch start_mpi() {
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  if (provided < MPI_THREAD_FUNNELED) {
    MPI_Finalize();
    throw std::runtime_error("the MPI library does not allow threads beside MPI");
  }
  Launch launch;
  MPI_Comm_rank(MPI_COMM_WORLD, &launch.rank);
  MPI_Comm_size(MPI_COMM_WORLD, &launch.processes);
  MPI_Comm node;
  int node_size = 1;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, launch.rank, MPI_INFO_NULL, &node);
  MPI_Comm_size(node, &node_size);
  MPI_Comm_free(&node);
  launch.threads = std::max(1u, std::thread::hardware_concurrency() / unsigned(std::max(node_size, 1)));
  return launch;
}

class MpiShapeShare : public ShapeShare {
 public:
  MpiShapeShare(std::size_t shapes, const Launch& launch)
      : ShapeShare(shapes, launch.rank, launch.processes, launch.threads) {}
  ~MpiShapeShare() override { MPI_Finalize(); }

  void gather(std::vector<std::vector<double>>& values) override { gather_blocks(values, MPI_DOUBLE); }
  void gather(std::vector<std::string>& texts) override { gather_blocks(texts, MPI_CHAR); }
  void broadcast(std::vector<double>& values) override { broadcast_block(values, MPI_DOUBLE); }
  void broadcast(std::string& text) override { broadcast_block(text, MPI_CHAR); }
  [[noreturn]] void abort(int exit_code) override {
    MPI_Abort(MPI_COMM_WORLD, exit_code);
    std::abort();  // MPI_Abort does not return
  }

 private:
  // Rank r's first shape, and one past its last (as ShapeShare's blocks).
  std::size_t block_start(int r) const { return shapes() * std::size_t(r) / std::size_t(processes()); }

  template <typename Block>
  void gather_blocks(std::vector<Block>& blocks, MPI_Datatype type) {
    blocks.resize(shapes());
    const int ranks = processes();
    // First every shape's length, then every shape's values, each rank's block at its place.
    std::vector<int> counts(static_cast<std::size_t>(ranks)), starts(static_cast<std::size_t>(ranks));
    for (int r = 0; r < ranks; ++r) {
      starts[std::size_t(r)] = int(block_start(r));
      counts[std::size_t(r)] = int(block_start(r + 1) - block_start(r));
    }
    std::vector<int> lengths(shapes());
    std::vector<int> own_lengths;
    for (const std::size_t k : owned()) own_lengths.push_back(int(blocks[k].size()));
    MPI_Allgatherv(own_lengths.data(), int(own_lengths.size()), MPI_INT, lengths.data(), counts.data(), starts.data(),
                   MPI_INT, MPI_COMM_WORLD);
    std::vector<int> value_counts(static_cast<std::size_t>(ranks), 0), value_starts(static_cast<std::size_t>(ranks), 0);
    std::size_t total = 0;
    for (int r = 0; r < ranks; ++r) {
      value_starts[std::size_t(r)] = int(total);
      for (std::size_t k = block_start(r); k < block_start(r + 1); ++k) value_counts[std::size_t(r)] += lengths[k];
      total += std::size_t(value_counts[std::size_t(r)]);
    }
    Block own;
    for (const std::size_t k : owned()) own.insert(own.end(), blocks[k].begin(), blocks[k].end());
    Block all;
    all.resize(total);
    MPI_Allgatherv(own.data(), int(own.size()), type, all.data(), value_counts.data(), value_starts.data(), type,
                   MPI_COMM_WORLD);
    std::size_t at = 0;
    for (std::size_t k = 0; k < shapes(); ++k) {
      blocks[k].assign(all.begin() + std::ptrdiff_t(at), all.begin() + std::ptrdiff_t(at + std::size_t(lengths[k])));
      at += std::size_t(lengths[k]);
    }
  }

  template <typename Block>
  void broadcast_block(Block& block, MPI_Datatype type) {
    unsigned long long length = block.size();
    MPI_Bcast(&length, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
    block.resize(std::size_t(length));
    MPI_Bcast(block.data(), int(length), type, 0, MPI_COMM_WORLD);
  }
};

}  // namespace

std::unique_ptr<ShapeShare> share_shapes_across_ranks(std::size_t shapes, unsigned threads) {
  Launch launch = start_mpi();
  if (threads) launch.threads = threads;
  return std::make_unique<MpiShapeShare>(shapes, launch);
}

}  // namespace meshparticles
