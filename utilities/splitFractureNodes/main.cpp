// splitFractureNodes: duplicate the mesh nodes along the fractures of a case (docs/method.md)
// and write the split mesh, with n_Γ per fracture node (2D: also t_Γ and arclength; 3D: the
// oriented fault triangles), to <case>/constant/splitMesh for the solver.
//
// Sample run:
//   splitFractureNodes -case cases/paperBenchmark
// reads  cases/paperBenchmark/system/meshDict and the mesh file it names,
// writes cases/paperBenchmark/constant/splitMesh and prints a checkMesh-style summary.
//
// Exit codes: 0 done; 1 bad input (the message names file:line and what was expected);
// 2 bad command line; 6 an internal or system error (out of memory, …).
#include <boost/program_options.hpp>
#include <filesystem>
#include <iostream>

#include "friction/case/SplitCase.hpp"
#include "friction/core/CommandLine.hpp"
#include "friction/core/InputError.hpp"
#include "friction/core/Parallel.hpp"

namespace fs = std::filesystem;
namespace po = boost::program_options;
using namespace friction;

int main(int argc, char** argv) {
  // 1. Command line (OpenFOAM style: -case DIR, -overwrite, -help).
  po::options_description options("Options");
  options.add_options()("case", po::value<std::string>()->default_value("."),
                        "case folder (holds system/meshDict)")(
      "overwrite", "split again, replacing an existing constant/splitMesh")("help",
                                                                            "print this help");
  const auto parsed = parseCommandLine(argc, argv, options, "splitFractureNodes");
  if (!parsed) return 2;
  // Under mpirun every rank would split the same mesh into the same file: the splitter is one
  // process (it is cheap next to the solve); only frictionSolver runs on several ranks.
  if (const int ranks = parallel::launchedRanks(); ranks > 1) {
    std::cerr << "splitFractureNodes: error: started as one of " << ranks
              << " ranks (mpirun): it runs as one process; run it without mpirun, then "
                 "'mpirun -np "
              << ranks << " frictionSolver -parallel'\n";
    return 2;
  }
  const po::variables_map& args = *parsed;
  if (args.count("help")) {
    std::cout << "Usage: splitFractureNodes [-case DIR] [-overwrite]\n\n"
                 "Duplicates the mesh nodes along the fractures named in DIR/system/meshDict\n"
                 "and writes DIR/constant/splitMesh for the solver.\n\n"
              << options;
    return 0;
  }
  const std::string caseDir = args["case"].as<std::string>();

  try {
    std::cout << "splitFractureNodes\nCase: " << caseDir << "\n\n";
    // 2.–6. Read and check meshDict and the mesh, split, summarise, write (SplitCase.hpp).
    SplitCaseOptions how;
    how.overwrite = args.count("overwrite") > 0;
    splitCase(caseDir, how, std::cout);
    std::cout << "\nEnd\n";
    return 0;
  } catch (const InputError& e) {
    std::cout.flush();
    std::cerr << "\nsplitFractureNodes: error: " << e.what() << "\n";
    return 1;
  } catch (const fs::filesystem_error& e) {
    std::cerr << "\nsplitFractureNodes: error: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    // Last resort (out of memory, an internal error): a message and a documented code, no abort.
    std::cout.flush();
    std::cerr << "\nsplitFractureNodes: internal error: " << e.what() << "\n";
    return 6;
  }
}
