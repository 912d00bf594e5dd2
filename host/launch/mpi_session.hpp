#pragma once
// MPI for the life of one command under mpirun or srun: initialized at the
// thread level the caller needs, finalized when destroyed, with this rank's
// place in the world and on its node (the ranks that share its cores and
// GPUs). The program's one MPI start-up, for batch's work queue and
// correspond's shape share; only in a build with MPI (CMakeLists.txt), and
// the header needs no MPI.
namespace meshparticles {

class MpiSession {
 public:
  // Which threads call MPI.
  enum class Calls {
    main_thread,    // the main thread alone (MPI_THREAD_FUNNELED)
    one_at_a_time,  // any thread, never two at once (MPI_THREAD_SERIALIZED)
  };
  // Throws std::runtime_error when the MPI library does not allow `calls`.
  explicit MpiSession(Calls calls);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  int rank = 0, size = 1;            // in MPI_COMM_WORLD
  int node_rank = 0, node_size = 1;  // among the ranks on this rank's node
};

}  // namespace meshparticles
