// Parallel: MPI when the build has it (FRICTION_WITH_MPI), one rank otherwise.
#include "friction/core/Parallel.hpp"

#include <dlfcn.h>

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>

#ifdef FRICTION_WITH_MPI
#include <mpi.h>
#endif

namespace friction {
namespace parallel {

namespace {
bool startedHere = false;

#ifdef FRICTION_WITH_MPI
bool mpiRunning() {
  int init = 0, fin = 0;
  MPI_Initialized(&init);
  MPI_Finalized(&fin);
  return init && !fin;
}

// Several ranks on one machine: one BLAS thread each. OpenBLAS's threads would otherwise
// compete for the same cores (and busy-wait) under every rank's dense kernels.
void oneBlasThreadPerRank() {
  using Set = void (*)(int);
  if (size() > 1)
    if (const auto set = reinterpret_cast<Set>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads")))
      set(1);
}
#endif
}  // namespace

#ifdef FRICTION_WITH_MPI
bool available() { return true; }

bool initialize(int& argc, char**& argv) {
  if (!mpiRunning()) {
    MPI_Init(&argc, &argv);
    startedHere = true;
  }
  oneBlasThreadPerRank();
  return true;
}

void ensureInitialized() {
  if (mpiRunning()) return;
  int fin = 0;
  MPI_Finalized(&fin);
  if (fin) return;  // MPI cannot start twice in one process
  MPI_Init(nullptr, nullptr);
  startedHere = true;
  std::atexit(finalize);
}

void finalize() {
  if (startedHere && mpiRunning()) MPI_Finalize();
}

bool initialized() { return startedHere; }
bool running() { return mpiRunning(); }

int rank() {
  if (!mpiRunning()) return 0;
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

int size() {
  if (!mpiRunning()) return 1;
  int s = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &s);
  return s;
}

void barrier() {
  if (size() > 1) MPI_Barrier(MPI_COMM_WORLD);
}

void broadcast(double* data, long count, int root) {
  if (size() > 1 && count > 0) {
    // MPI counts are int: large blocks go in pieces.
    const long chunk = 1L << 30;
    for (long first = 0; first < count; first += chunk)
      MPI_Bcast(data + first, static_cast<int>(std::min(chunk, count - first)), MPI_DOUBLE, root,
                MPI_COMM_WORLD);
  }
}

void broadcast(int* data, long count, int root) {
  if (size() > 1 && count > 0)
    MPI_Bcast(data, static_cast<int>(count), MPI_INT, root, MPI_COMM_WORLD);
}

int maxOverRanks(int value) {
  if (size() > 1) MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  return value;
}

void maxOverRanks(int* data, long count) {
  if (size() > 1 && count > 0)
    MPI_Allreduce(MPI_IN_PLACE, data, static_cast<int>(count), MPI_INT, MPI_MAX, MPI_COMM_WORLD);
}

double sumOverRanks(double value) {
  if (size() > 1) MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  return value;
}

double maxOverRanks(double value) {
  if (size() > 1) MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return value;
}

void sumOverRanks(double* data, long count) {
  if (size() <= 1 || count <= 0) return;
  const long chunk = 1L << 30;  // MPI counts are int
  for (long first = 0; first < count; first += chunk)
    MPI_Allreduce(MPI_IN_PLACE, data + first, static_cast<int>(std::min(chunk, count - first)),
                  MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
}

std::vector<int> gatherOnMaster(const std::vector<int>& mine) {
  if (size() <= 1) return mine;
  const int count = static_cast<int>(mine.size());
  std::vector<int> counts(static_cast<std::size_t>(size())), offsets(counts.size() + 1, 0);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::vector<int> all;
  if (isMaster()) {
    for (std::size_t r = 0; r < counts.size(); ++r) offsets[r + 1] = offsets[r] + counts[r];
    all.resize(static_cast<std::size_t>(offsets.back()));
  }
  MPI_Gatherv(mine.data(), count, MPI_INT, all.data(), counts.data(), offsets.data(), MPI_INT, 0,
              MPI_COMM_WORLD);
  return all;
}

void abort(int code) {
  static std::atomic_flag once = ATOMIC_FLAG_INIT;
  if (once.test_and_set())
    for (;;) pause();  // another thread is ending the run
  if (size() > 1) MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);
}

int fortranCommunicator() {
  ensureInitialized();
  return static_cast<int>(MPI_Comm_c2f(MPI_COMM_WORLD));
}
#else
bool available() { return false; }
bool initialize(int&, char**&) { return false; }
void ensureInitialized() {}
void finalize() {}
bool initialized() { return false; }
bool running() { return false; }
int rank() { return 0; }
int size() { return 1; }
void barrier() {}
void broadcast(double*, long, int) {}
void broadcast(int*, long, int) {}
int maxOverRanks(int value) { return value; }
void maxOverRanks(int*, long) {}
double sumOverRanks(double value) { return value; }
double maxOverRanks(double value) { return value; }
void sumOverRanks(double*, long) {}
std::vector<int> gatherOnMaster(const std::vector<int>& mine) { return mine; }
void abort(int code) { std::exit(code); }
int fortranCommunicator() { return 0; }
#endif

RankFailure::RankFailure(int status, std::exception_ptr cause)
    : std::runtime_error("a rank failed (exit status " + std::to_string(status) + ")"),
      status_(status),
      cause_(std::move(cause)) {}

void agree(const std::function<void()>& step, int (*statusOf)(const std::exception_ptr&)) {
  if (size() <= 1) {
    step();
    return;
  }
  std::exception_ptr error;
  try {
    step();
  } catch (...) {
    error = std::current_exception();
  }
  // Exit statuses are positive: 0 says "no failure here". The second number finds the lowest
  // rank that failed (the largest of −rank), the one that reports it.
  int shared[2] = {error ? std::max(statusOf(error), 1) : 0, error ? -rank() : -size()};
  maxOverRanks(shared, 2);
  if (shared[0] > 0) throw RankFailure(shared[0], -shared[1] == rank() ? error : nullptr);
}

int launchedRanks() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"})
    if (const char* value = std::getenv(name)) {
      const int n = std::atoi(value);
      if (n > 0) return n;
    }
  return 1;
}

}  // namespace parallel
}  // namespace friction
