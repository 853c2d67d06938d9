// frictionSolver: quasi-static Coulomb friction on the fractures of an elastic body, by the
// control-problem method of Cerroni, Formaggia and Scotti (docs/method.md). Orchestration
// only: the numerics live in the library.
//
// Sample run (after splitFractureNodes):
//   frictionSolver -case cases/paperBenchmark
//   mpirun -np 2 frictionSolver -parallel -case cases/paperBenchmark   (linearSolver mumps)
// prints the date, each setup phase with its wall time as it ends, the settings, one line per
// time step (iterations, back-substitutions, J, |D|/|Sigma|, max(ST − μ_f, 0), status,
// progress and time left, largest slip, the loads' scale, time since start) and End, each
// line flushed as it is written; writes time folders <t>/D,
// <t>/fractures/<name>.dat, <t>/solverStatus and postProcessing/convergence.dat.
//
// Exit codes: 0 every step converged; 1 bad input (file:line and what was expected), or a
// case it refuses to touch (locked by another run, folders it did not write; nothing written);
// 2 bad command line; 3 some step did not converge, was inaccurate or diverged (see the log);
// 4 the factorisation failed (the log says why); 5 stopped by SIGINT/SIGTERM (after writing
// the current step, or at once on a second signal, without writing it); 6 an output or system
// error (cannot write, disk full, a file vanished, internal error).
#include <boost/program_options.hpp>
#include <iostream>

#include "friction/case/RunCase.hpp"
#include "friction/control/Optimizer.hpp"
#include "friction/core/CommandLine.hpp"
#include "friction/core/Parallel.hpp"
#include "friction/core/Suggest.hpp"
#include "friction/effect/Effect.hpp"
#include "friction/law/FrictionLaw.hpp"
#include "friction/linalg/SparseFactor.hpp"
#include "friction/time/TimeIntegrator.hpp"

namespace po = boost::program_options;
using namespace friction;

namespace {
// A stream buffer that drops what it is given: the log of ranks other than 0.
class NullBuffer : public std::streambuf {
 protected:
  int overflow(int c) override { return c == EOF ? 0 : c; }
  std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
};

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
    std::cout
        << "Usage: frictionSolver [-case DIR] [-overwrite] [-parallel] [-listModels]\n\n"
           "Runs the case in DIR (split by splitFractureNodes) through its times: quasi-static\n"
           "stepping, or rate-and-state faults integrated quasi-dynamically\n"
           "(system/frictionSolution, timeIntegration).\n\n"
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
              << "linear solvers (system/frictionSolution, linearSolver): auto (the default: "
                 "chosen by the predicted factor's size), "
              << joinWords(SparseFactor::backendNames()) << "\n"
              << "time integrators (system/frictionSolution, timeIntegration): "
              << joinWords(TimeIntegrator::names()) << "\n"
              << "effects (constant/effects, key 'type'): " << joinWords(Effect::names()) << "\n";
    return 0;
  }

  // Several ranks (mpirun): MPI first. Without -parallel every rank would run the whole case
  // and write the same files: refused.
  const int launched = parallel::launchedRanks();
  if (!args.count("parallel") && launched > 1) {
    // One write per message (every rank prints it: pieces of several would interleave).
    std::cerr << ("frictionSolver: error: started as one of " + std::to_string(launched) +
                  " ranks (mpirun) without -parallel: each would run the whole case and write "
                  "the same files; run 'mpirun -np " +
                  std::to_string(launched) +
                  " frictionSolver -parallel ...' (with linearSolver mumps)\n")
              << std::flush;
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
  RunCaseOptions run;
  run.overwrite = args.count("overwrite") > 0;
  const int status = runCase(args["case"].as<std::string>(), run, std::cout, std::cerr);
  std::cout.flush();
  std::cout.rdbuf(logBuffer);
  // A failure on any rank has reached every rank (runCase: they agree after what may fail on
  // one alone, and end every rank at once where they cannot): each returns the same status.
  parallel::finalize();
  return status;
}
