// frictionSolver: quasi-static Coulomb friction on the fractures of an elastic body, by the
// control-problem method of Cerroni, Formaggia and Scotti (docs/method.md). Orchestration
// only: the numerics live in the library.
//
// Sample run (after splitFractureNodes):
//   frictionSolver -case cases/paperBenchmark
//   mpirun -np 2 frictionSolver -parallel -case cases/paperBenchmark   (linearSolver mumps)
// prints the settings, one line per time step (iterations, back-substitutions, J,
// |D|/|Sigma|, max(ST − μ_f, 0), status) and End; writes time folders <t>/D,
// <t>/fractures/<name>.dat, <t>/solverStatus and postProcessing/convergence.dat.
//
// Exit codes: 0 every step converged; 1 bad input (file:line and what was expected);
// 2 bad command line; 3 some step did not converge, was inaccurate or diverged (see the log);
// 4 the factorisation failed (the log says why); 5 stopped by SIGINT/SIGTERM (after writing
// the current step, or at once on a second signal, without writing it); 6 an output or system
// error (cannot write, disk full, a file vanished, internal error).
#include <sys/resource.h>

#include <boost/program_options.hpp>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <new>
#include <sstream>

#include "friction/case/FrictionCase.hpp"
#include "friction/control/Optimizer.hpp"
#include "friction/core/CommandLine.hpp"
#include "friction/core/OutputError.hpp"
#include "friction/core/Parallel.hpp"
#include "friction/core/Suggest.hpp"
#include "friction/effect/Effect.hpp"
#include "friction/law/FrictionLaw.hpp"
#include "friction/linalg/SparseFactor.hpp"

namespace po = boost::program_options;
using namespace friction;

namespace {
// The largest resident set of the run so far [GB] (Linux reports ru_maxrss in KiB), with 3
// digits: at 10⁶ unknowns in 3D the factor takes most of the machine, and the user should
// see it.
// The largest resident set of this process so far [bytes]; 0 if unknown.
double peakMemoryBytes() {
  rusage usage{};
  return getrusage(RUSAGE_SELF, &usage) == 0 ? static_cast<double>(usage.ru_maxrss) * 1024 : 0.0;
}

std::string peakMemoryGb() {
  const double bytes = peakMemoryBytes();
  if (bytes <= 0) return "unknown";
  std::ostringstream s;
  s << std::setprecision(3) << bytes / 1e9;
  return s.str();
}

// A stream buffer that drops what it is given: the log of ranks other than 0.
class NullBuffer : public std::streambuf {
 protected:
  int overflow(int c) override { return c == EOF ? 0 : c; }
  std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
};

int solve(const po::variables_map& args);
}  // namespace

int main(int argc, char** argv) {
  // 1. Command line (OpenFOAM style).
  po::options_description options("Options");
  options.add_options()("case", po::value<std::string>()->default_value("."), "case folder")(
      "listModels", "list the friction laws, optimizers and linear solvers")(
      "overwrite",
      "remove an earlier run's outputs (time folders after startTime, VTK files, "
      "postProcessing/convergence.dat) before running")(
      "parallel",
      "run on the ranks mpirun started (mpirun -np N frictionSolver -parallel ...; needs "
      "linearSolver mumps)")("help", "print this help");
  const auto parsed = parseCommandLine(argc, argv, options, "frictionSolver");
  if (!parsed) return 2;
  const po::variables_map& args = *parsed;
  if (args.count("help")) {
    std::cout << "Usage: frictionSolver [-case DIR] [-overwrite] [-parallel] [-listModels]\n\n"
                 "Runs the case in DIR (split by splitFractureNodes) through quasi-static time.\n\n"
              << options;
    return 0;
  }
  if (args.count("listModels")) {
    std::cout << "friction laws (constant/fractureProperties, key 'law'): "
              << joinWords(FrictionLaw::names()) << "\n"
              << "friction fields (constant/fractureProperties, frictionCoefficient, cohesion or "
                 "threshold { type ...; }): "
              << joinWords(FrictionField::typeNames()) << "\n"
              << "optimizers (system/frictionSolution, control/optimizer/type): "
              << joinWords(Optimizer::names()) << "\n"
              << "linear solvers (system/frictionSolution, linearSolver): "
              << joinWords(SparseFactor::backendNames()) << "\n"
              << "effects (constant/effects, key 'type'): " << joinWords(Effect::names()) << "\n";
    return 0;
  }

  // Several ranks (mpirun): MPI first. Without -parallel every rank would run the whole case
  // and write the same files: refused.
  const int launched = parallel::launchedRanks();
  if (!args.count("parallel") && launched > 1) {
    std::cerr << "frictionSolver: error: started as one of " << launched
              << " ranks (mpirun) without -parallel: each would run the whole case and write "
                 "the same files; run 'mpirun -np "
              << launched << " frictionSolver -parallel ...' (with linearSolver mumps)\n";
    return 2;
  }
  if (args.count("parallel") && !parallel::initialize(argc, argv)) {
    std::cerr << "frictionSolver: error: -parallel: this build has no MPI (configure with "
                 "-DFRICTION_MUMPS=ON, with libmumps-dev and mpi-default-dev installed)\n";
    return 2;
  }
  // Rank 0 writes the log; the others keep quiet (their errors still reach stderr).
  NullBuffer quiet;
  std::streambuf* const logBuffer = std::cout.rdbuf();
  if (!parallel::isMaster()) std::cout.rdbuf(&quiet);
  const int status = solve(args);
  std::cout.flush();
  std::cout.rdbuf(logBuffer);
  // An output or system error may strike one rank only (rank 0 writes; memory runs out on
  // one): the others would wait in a shared solve forever, so stop them all with its status.
  // Input errors are found by every rank alike while reading, before any shared work.
  if (status == 6 && parallel::size() > 1) parallel::abort(status);
  parallel::finalize();
  return status;
}

namespace {
int solve(const po::variables_map& args) {
  try {
    // 2. Read and validate the whole case before any work.
    std::cout << "frictionSolver";
    if (parallel::size() > 1) std::cout << " (" << parallel::size() << " ranks)";
    std::cout << "\n";
    FrictionCase c(args["case"].as<std::string>());
    // An earlier run's time folders are refused, continued (startFrom latestTime) or, with
    // -overwrite, removed: before any work.
    c.prepareOutput(args.count("overwrite") > 0, std::cout);
    parallel::barrier();  // rank 0 has removed what -overwrite removes

    // 3. Assemble and factor once.
    if (c.setup(std::cout) != FactorStatus::ok) {
      std::cout.flush();
      std::cerr << "frictionSolver: error: " << c.factorFailureDiagnosis() << "\n";
      return 4;
    }

    // 4. The time loop.
    const auto results = c.run(std::cout);
    int notConverged = 0;
    for (const auto& r : results) notConverged += r.report.status != OptimizerStatus::converged;
    const auto& f = c.system().factorization();
    std::cout << "\nFactorisations " << f.numFactorizations() << " (" << f.factorSeconds()
              << " s), back-substitutions " << f.numSolves() << " (" << f.solveSeconds()
              << " s), peak memory " << peakMemoryGb() << " GB";
    if (parallel::size() > 1) {
      // Every rank's, as a user sizing a cluster job needs it (collective: every rank is here).
      const double mine = peakMemoryBytes();
      std::cout << " on rank 0, " << std::setprecision(3) << parallel::maxOverRanks(mine) / 1e9
                << " GB on the largest rank, " << parallel::sumOverRanks(mine) / 1e9
                << " GB on all " << parallel::size();
    }
    std::cout << "\n";
    if (!c.stoppedEarly().empty()) {
      std::cout << "\nStopped early (" << c.stoppedEarly()
                << "); continue with startFrom latestTime\n\nEnd\n";
      return c.stoppedEarly().rfind("SIG", 0) == 0 ? 5 : 0;
    }
    if (notConverged) {
      std::cout << "\nWarning: " << notConverged << " of " << results.size()
                << " steps did not converge (see the status column)\n\nEnd\n";
      return 3;
    }
    std::cout << "\nEnd\n";
    return 0;
  } catch (const OutputError& e) {
    // Not the user's input (OutputError is an InputError, so it comes first): exit 6. Here and
    // below the stack is unwound on the way, so TimeFolder's destructor has removed the step's
    // partial folder.
    std::cout.flush();
    std::cerr << "\nfrictionSolver: error: " << e.what() << "\n";
    return 6;
  } catch (const InputError& e) {
    std::cout.flush();
    std::cerr << "\nfrictionSolver: error: " << e.what() << "\n";
    return 1;
  } catch (const std::filesystem::filesystem_error& e) {
    std::cout.flush();
    std::cerr << "\nfrictionSolver: error: " << e.path1().string() << ": " << e.code().message()
              << " (" << e.what() << ")\n";
    return 6;
  } catch (const std::bad_alloc&) {
    std::cout.flush();
    std::cerr << "\nfrictionSolver: error: out of memory\n";
    return 6;
  } catch (const std::exception& e) {
    std::cout.flush();
    std::cerr << "\nfrictionSolver: internal error: " << e.what() << "\n";
    return 6;
  } catch (...) {
    std::cout.flush();
    std::cerr << "\nfrictionSolver: internal error: an unknown exception\n";
    return 6;
  }
}
}  // namespace
