// ShapeShare under mpirun: rank r owns the r-th block of shapes, and the
// gathers are MPI all-gathers (every rank receives every block, in shape
// order). Only the main thread calls MPI: the threads of a rank work on its
// own shapes between the calls.
#include <mpi.h>

#include <cstdlib>
#include <memory>
#include <utility>

#include "correspondence/shape_share.hpp"
#include "launch/launch_environment.hpp"
#include "launch/mpi_session.hpp"

namespace meshparticles {

namespace {

class MpiShapeShare : public ShapeShare {
 public:
  // `mpi` lives as long as the share: MPI ends with it.
  MpiShapeShare(std::size_t shapes, std::unique_ptr<MpiSession> mpi, unsigned threads)
      : ShapeShare(shapes, mpi->rank, mpi->size, threads), mpi_(std::move(mpi)) {}

  void gather(std::vector<std::vector<double>>& values) override { gather_blocks(values, MPI_DOUBLE); }
  void gather(std::vector<std::string>& texts) override { gather_blocks(texts, MPI_CHAR); }
  void broadcast(std::vector<double>& values) override { broadcast_block(values, MPI_DOUBLE); }
  void broadcast(std::string& text) override { broadcast_block(text, MPI_CHAR); }
  [[noreturn]] void abort(int exit_code) override {
    MPI_Abort(MPI_COMM_WORLD, exit_code);
    std::abort();  // MPI_Abort does not return
  }

 private:
  std::unique_ptr<MpiSession> mpi_;

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
  // Only the main thread calls MPI: the threads of a rank work on its own shapes between the calls.
  auto mpi = std::make_unique<MpiSession>(MpiSession::Calls::main_thread);
  if (threads == 0) threads = cores_per_rank(mpi->node_size);
  return std::make_unique<MpiShapeShare>(shapes, std::move(mpi), threads);
}

}  // namespace meshparticles
