// Parallel: the ranks of a distributed run (README "Running in parallel"; docs/method.md §4
// "The distributed engine"). Every rank reads the case and runs the control loop on the
// fracture (small, dense, identical on every rank); the sparse factorisation and its solves
// are shared by the ranks (linalg/MumpsBackend.cpp), and only the master rank writes files
// and the log. A build without MPI (FRICTION_MUMPS off) has one rank and these calls do
// nothing.
#pragma once

#include <exception>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace friction {
namespace parallel {

/// Whether this build has MPI (and the mumps linear solver).
bool available();

/// Start MPI for a run with -parallel (mpirun -np N frictionSolver -parallel ...). Call once,
/// first thing in main; finalize() at the end. Without MPI in the build it returns false.
bool initialize(int& argc, char**& argv);
/// Start MPI if nobody has (a serial run or a test that selects the mumps solver: one rank);
/// MPI is then finalized at exit.
void ensureInitialized();
/// MPI_Finalize if this module started MPI.
void finalize();
/// Whether initialize() or ensureInitialized() started MPI in this process.
bool initialized();
/// Whether MPI is running (initialised and not yet finalised).
bool running();

/// This process's rank and the number of ranks (0 and 1 without MPI).
int rank();
int size();
/// Rank 0: the one that writes files and the log.
inline bool isMaster() { return rank() == 0; }

/// The number of ranks mpirun started this process with, read from its environment before MPI
/// is initialised (OpenMPI's OMPI_COMM_WORLD_SIZE, MPICH's PMI_SIZE); 1 when not under mpirun.
int launchedRanks();

/// Collective operations over all ranks (no-ops with one rank).
void barrier();
/// root's values overwrite everyone's.
void broadcast(double* data, long count, int root = 0);
void broadcast(int* data, long count, int root = 0);
/// The maximum of value over the ranks.
int maxOverRanks(int value);
/// data[i] becomes the maximum over the ranks of their data[i], on every rank.
void maxOverRanks(int* data, long count);
/// The sum of value over the ranks.
double sumOverRanks(double value);
/// data[i] becomes the sum over the ranks of their data[i], on every rank.
void sumOverRanks(double* data, long count);
/// Rank 0 receives every rank's values, in rank order; the others an empty vector.
std::vector<int> gatherOnMaster(const std::vector<int>& mine);
/// The maximum of value over the ranks.
double maxOverRanks(double value);

/// Stop every rank with exit status `code` (MPI_Abort); with one rank, std::exit(code). Safe to
/// call from two threads at once (the stop watchdog, StopRequest.cpp): the first call ends the
/// run, a later one waits for that.
[[noreturn]] void abort(int code);

/// Thrown on every rank when agree() found that its step failed on some rank. On the first rank
/// where it failed (the lowest), cause() is the exception, to be reported once, as a serial run
/// reports it; elsewhere it is empty. status() is the exit status every rank ends with (the
/// largest over the ranks that failed).
class RankFailure : public std::runtime_error {
 public:
  RankFailure(int status, std::exception_ptr cause);
  int status() const { return status_; }
  const std::exception_ptr& cause() const { return cause_; }

 private:
  int status_;
  std::exception_ptr cause_;
};

/// Runs `step` on this rank, then every rank learns whether it threw on any rank, so that they
/// all go on, or all stop, together: a step that only rank 0 does (writing) cannot fail there
/// while the others wait for it in a shared solve. Collective: every rank calls agree() at the
/// same point, and `step` itself makes no collective call. If `step` threw anywhere, every rank
/// throws RankFailure with the largest statusOf(exception) over the ranks where it threw. With
/// one rank the exception passes unchanged.
void agree(const std::function<void()>& step, int (*statusOf)(const std::exception_ptr&));

/// The Fortran handle of the ranks' communicator, as MUMPS takes it.
int fortranCommunicator();

}  // namespace parallel
}  // namespace friction
