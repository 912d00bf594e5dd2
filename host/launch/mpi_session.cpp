#include "launch/mpi_session.hpp"

#include <mpi.h>

#include <stdexcept>

namespace meshparticles {

MpiSession::MpiSession(Calls calls) {
  const int needed = calls == Calls::main_thread ? MPI_THREAD_FUNNELED : MPI_THREAD_SERIALIZED;
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, needed, &provided);
  if (provided < needed) {
    MPI_Finalize();
    throw std::runtime_error(calls == Calls::main_thread
                                 ? "the MPI library does not allow threads beside MPI"
                                 : "the MPI library does not allow MPI calls from a second thread");
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  MPI_Comm node;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank, MPI_INFO_NULL, &node);
  MPI_Comm_rank(node, &node_rank);
  MPI_Comm_size(node, &node_size);
  MPI_Comm_free(&node);
}

MpiSession::~MpiSession() { MPI_Finalize(); }

}  // namespace meshparticles
