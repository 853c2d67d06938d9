// runCase: see RunCase.hpp. The log and the exit codes are frictionSolver's (README.md,
// "frictionSolver").
#include "friction/case/RunCase.hpp"

#include <sys/resource.h>

#include <exception>
#include <filesystem>
#include <iomanip>
#include <new>
#include <ostream>
#include <sstream>

#include "friction/case/CaseLock.hpp"
#include "friction/case/FrictionCase.hpp"
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
}  // namespace

int runCase(const std::string& caseDir, const RunCaseOptions& options, std::ostream& log,
            std::ostream& err, std::unique_ptr<FrictionCase>* kept) {
  try {
    // 2. Read and validate the whole case before any work.
    log << options.program;
    if (parallel::size() > 1) log << " (" << parallel::size() << " ranks)";
    log << "\n";
    auto owned = std::make_unique<FrictionCase>(caseDir);
    FrictionCase& c = *owned;
    Keep keep{kept, owned};
    // One run at a time writes a case: the lock before anything is written or removed. Rank 0
    // writes every file, so it holds it; the others hear whether it got it.
    std::unique_ptr<CaseLock> lock;
    std::exception_ptr lockError;
    int lockStatus = 0;
    if (parallel::isMaster()) try {
        lock = std::make_unique<CaseLock>(caseDir, options.program, log);
      } catch (const OutputError&) {
        lockStatus = 6;
        lockError = std::current_exception();
      } catch (const InputError&) {
        lockStatus = 1;
        lockError = std::current_exception();
      }
    parallel::broadcast(&lockStatus, 1);
    if (lockError) std::rethrow_exception(lockError);
    if (lockStatus != 0) return lockStatus;  // rank 0 said why
    // An earlier run's time folders are refused, continued (startFrom latestTime) or, with
    // -overwrite, removed: before any work.
    c.prepareOutput(options.overwrite, log, options.overwriteHint);
    parallel::barrier();  // rank 0 has removed what -overwrite removes

    // 3. Assemble and factor once.
    if (c.setup(log) != FactorStatus::ok) {
      log.flush();
      err << options.program << ": error: " << c.factorFailureDiagnosis() << "\n";
      return 4;
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
    if (!c.stoppedEarly().empty()) {
      log << "\nStopped early (" << c.stoppedEarly()
          << "); continue with startFrom latestTime\n\nEnd\n";
      return c.stoppedEarly().rfind("SIG", 0) == 0 ? 5 : 0;
    }
    if (notConverged) {
      log << "\nWarning: " << notConverged << " of " << results.size()
          << " steps did not converge (see the status column)\n\nEnd\n";
      return 3;
    }
    log << "\nEnd\n";
    return 0;
  } catch (const OutputError& e) {
    // Not the user's input (OutputError is an InputError, so it comes first): exit 6. Here and
    // below the stack is unwound on the way, so TimeFolder's destructor has removed the step's
    // partial folder.
    log.flush();
    err << "\n" << options.program << ": error: " << e.what() << "\n";
    return 6;
  } catch (const InputError& e) {
    log.flush();
    err << "\n" << options.program << ": error: " << e.what() << "\n";
    return 1;
  } catch (const std::filesystem::filesystem_error& e) {
    log.flush();
    err << "\n"
        << options.program << ": error: " << e.path1().string() << ": " << e.code().message()
        << " (" << e.what() << ")\n";
    return 6;
  } catch (const std::bad_alloc&) {
    log.flush();
    err << "\n" << options.program << ": error: out of memory\n";
    return 6;
  } catch (const std::exception& e) {
    log.flush();
    err << "\n" << options.program << ": internal error: " << e.what() << "\n";
    return 6;
  } catch (...) {
    log.flush();
    err << "\n" << options.program << ": internal error: an unknown exception\n";
    return 6;
  }
}

}  // namespace friction
