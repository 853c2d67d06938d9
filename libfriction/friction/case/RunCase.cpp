// runCase: see RunCase.hpp. The log and the exit codes are frictionSolver's (README.md,
// "frictionSolver").
#include "friction/case/RunCase.hpp"

#include <chrono>
#include <thread>

#include <sys/resource.h>

#include <exception>
#include <filesystem>
#include <iomanip>
#include <new>
#include <ostream>
#include <sstream>

#include "friction/case/CaseLock.hpp"
#include "friction/case/FrictionCase.hpp"
#include "friction/core/LogLines.hpp"
#include "friction/core/OutputError.hpp"
#include "friction/core/Parallel.hpp"
#include "friction/linalg/SparseFactor.hpp"

namespace friction {

double peakMemoryBytes() {
  // Linux reports ru_maxrss in KiB.
  rusage usage{};
  return getrusage(RUSAGE_SELF, &usage) == 0 ? static_cast<double>(usage.ru_maxrss) * 1024 : 0.0;
}

namespace {
// The peak [GB] with 3 digits: at 10⁶ unknowns in 3D the factor takes most of the machine,
// and the user should see it.
std::string peakMemoryGb() {
  const double bytes = peakMemoryBytes();
  if (bytes <= 0) return "unknown";
  std::ostringstream s;
  s << std::setprecision(3) << bytes / 1e9;
  return s.str();
}

// Hands the case over to the caller when runCase returns, however it returns.
struct Keep {
  std::unique_ptr<FrictionCase>* to;
  std::unique_ptr<FrictionCase>& from;
  ~Keep() {
    if (to) *to = std::move(from);
  }
};

// The exit status of a failure and its message (without the leading newline), as frictionSolver
// reports it.
int describeFailure(const std::exception_ptr& error, const std::string& program,
                    std::string& message) {
  try {
    std::rethrow_exception(error);
  } catch (const OutputError& e) {
    // Not the user's input (OutputError is an InputError, so it comes first): exit 6.
    message = program + ": error: " + e.what();
    return 6;
  } catch (const InputError& e) {
    message = program + ": error: " + e.what();
    return 1;
  } catch (const std::filesystem::filesystem_error& e) {
    message = program + ": error: " + e.path1().string() + ": " + e.code().message() + " (" +
              e.what() + ")";
    return 6;
  } catch (const std::bad_alloc&) {
    message = program + ": error: out of memory";
    return 6;
  } catch (const std::exception& e) {
    message = program + ": internal error: " + e.what();
    return 6;
  } catch (...) {
    message = program + ": internal error: an unknown exception";
    return 6;
  }
}
}  // namespace

int exitStatusOf(const std::exception_ptr& error) {
  std::string message;
  return describeFailure(error, "", message);
}

namespace {

/// Several ranks ending with a failure status: mpirun ends the whole job at the first non-zero
/// exit it sees, and a rank ended that way may lose what it wrote last (measured: the rigid-body
/// diagnosis of rank 0 missing in 1 of 5 runs on 2 ranks). So rank 0 says why first, every rank
/// waits for that (a barrier), and the others leave a moment after rank 0.
int endTogether(int status, std::ostream& err) {
  if (parallel::size() == 1 || status == 0) return status;
  err.flush();
  parallel::barrier();
  if (!parallel::isMaster()) std::this_thread::sleep_for(std::chrono::milliseconds(200));
  return status;
}

}  // namespace

int runCase(const std::string& caseDir, const RunCaseOptions& options, std::ostream& log,
            std::ostream& err, std::unique_ptr<FrictionCase>* kept) {
  // Outside the try block: a failure on one rank alone must end every rank while the case, and
  // with it the factor MUMPS shares between the ranks, still lives (its release is collective
  // and would wait for the other ranks forever).
  std::unique_ptr<FrictionCase> owned;
  Keep keep{kept, owned};
  // Each line of the log reaches the file or pipe when it ends: a long setup is seen phase by
  // phase, not all at once when the C library's buffer fills.
  const FlushEachLine flushLines(log);
  const auto report = [&](const std::exception_ptr& error) {
    std::string message;
    const int status = describeFailure(error, options.program, message);
    // The stack is unwound on the way, so TimeFolder's destructor has removed the step's
    // partial folder.
    log.flush();
    // One write: stderr is unbuffered, and under mpirun its pieces and the log's lines (stdout,
    // flushed line by line) reach the terminal or file through separate channels, so a message
    // written in pieces can be cut by a log line.
    err << ("\n" + message + "\n") << std::flush;
    return status;
  };
  try {
    // 2. Read and validate the whole case before any work. Every rank reads it; they agree
    // (parallel::agree) after each part that may fail on one rank alone, before the next shared
    // call.
    log << options.program;
    if (parallel::size() > 1) log << " (" << parallel::size() << " ranks)";
    log << ", started " << localDateTime() << "\n";
    parallel::agree([&] { owned = std::make_unique<FrictionCase>(caseDir, options.given); },
                    exitStatusOf);
    FrictionCase& c = *owned;
    {
      const Mesh& m = c.splitMesh().mesh;
      c.logPhase(log,
                 "case and split mesh read (" + std::to_string(m.numPoints()) + " points, " +
                     std::to_string(m.numCells()) +
                     (m.dim == 3 ? " tetrahedra, " : " triangles, ") +
                     std::to_string(c.splitMesh().fractures.size()) + " fracture(s))",
                 c.secondsSinceStart());
    }
    // One run at a time writes a case: the lock before anything is written or removed. Rank 0
    // writes every file, so it holds it; the agreement tells the others whether it got it.
    std::unique_ptr<CaseLock> lock;
    parallel::agree(
        [&] {
          if (parallel::isMaster())
            lock = std::make_unique<CaseLock>(caseDir, options.program, log);
        },
        exitStatusOf);
    // An earlier run's time folders are refused, continued (startFrom latestTime) or, with
    // -overwrite, removed: before any work (rank 0 removes; the agreement waits for it).
    parallel::agree([&] { c.prepareOutput(options.overwrite, log, options.overwriteHint); },
                    exitStatusOf);

    // 3. Assemble and factor once.
    if (c.setup(log) != FactorStatus::ok) {
      log.flush();
      // Every rank has the same verdict (setup()): rank 0 says it, as for the log.
      if (parallel::isMaster())
        err << (options.program + ": error: " + c.factorFailureDiagnosis() + "\n") << std::flush;
      return endTogether(4, err);
    }

    // 4. The time loop.
    const auto results = c.run(log);
    int notConverged = 0;
    for (const auto& r : results) notConverged += r.report.status != OptimizerStatus::converged;
    const auto& f = c.system().factorization();
    log << "\nFactorisations " << f.numFactorizations() << " (" << f.factorSeconds()
        << " s), back-substitutions " << f.numSolves() << " (" << f.solveSeconds()
        << " s), peak memory " << peakMemoryGb() << " GB";
    if (parallel::size() > 1) {
      // Every rank's, as a user sizing a cluster job needs it (collective: every rank is here).
      const double mine = peakMemoryBytes();
      log << " on rank 0, " << std::setprecision(3) << parallel::maxOverRanks(mine) / 1e9
          << " GB on the largest rank, " << parallel::sumOverRanks(mine) / 1e9 << " GB on all "
          << parallel::size();
    }
    log << "\n";
    // An iterative solver: what its solves took and how close they came.
    if (f.iterative()) {
      const FactorAnalysis a = f.currentAnalysis();
      log << "Linear solver amg: " << a.iterativeSolves << " solves (the check included), "
          << a.iterativeIterations << " CG iterations ("
          << (a.iterativeSolves > 0 ? a.iterativeIterations / a.iterativeSolves : 0)
          << " per solve), the largest relative residual at a stop " << std::setprecision(3)
          << a.iterativeWorstResidual << "; "
          << (a.iterativeUnconverged == 0
                  ? std::string("every solve reached its tolerance")
                  : std::to_string(a.iterativeUnconverged) +
                        " solve(s) stopped short of the tolerance at the iteration limit")
          << "\n";
    }
    if (!c.stoppedEarly().empty()) {
      log << "\nStopped early (" << c.stoppedEarly() << "); " << c.continuation() << "\n\nEnd\n";
      return c.stoppedEarly().rfind("SIG", 0) == 0 ? 5 : 0;
    }
    if (notConverged) {
      log << "\nWarning: " << notConverged << " of " << results.size()
          << " steps did not converge (see the status column)\n\nEnd\n";
      return 3;
    }
    log << "\nEnd\n";
    return 0;
  } catch (const parallel::RankFailure& e) {
    // Every rank knows: each ends with the same status, the first where it failed says why.
    if (e.cause()) report(e.cause());
    return endTogether(e.status(), err);
  } catch (...) {
    const int status = report(std::current_exception());
    // This rank alone may have failed, in the middle of work the ranks share: the others
    // would wait for it forever. End them all, with the status a serial run gives.
    if (parallel::size() > 1) parallel::abort(status);
    return status;
  }
}

}  // namespace friction
