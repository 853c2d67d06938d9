// runCase: what frictionSolver does to a split case folder, for the command-line tool and the
// FreeFEM plug-in alike: read and check the whole case, prepare the outputs, assemble and
// factor once, run the time loop, print the summary, and turn every failure into a message
// and frictionSolver's exit code.
#pragma once

#include <exception>
#include <iosfwd>
#include <memory>
#include <string>

#include "friction/effect/GivenField.hpp"

namespace friction {

class FrictionCase;

struct RunCaseOptions {
  /// Remove an earlier run's outputs first (frictionSolver -overwrite).
  bool overwrite = false;
  /// The program that names itself in the log's first line and in error messages.
  std::string program = "frictionSolver";
  /// How the caller asks for `overwrite`, for the messages that suggest it.
  std::string overwriteHint = "frictionSolver -overwrite";
  /// Fields the caller hands to the case's effects (GivenField.hpp): the FreeFEM plug-in's
  /// pressure; frictionSolver gives none.
  GivenFields given;
};

/// Runs the case in caseDir; the log goes to `log`, errors to `err` as
/// "<program>: error: <file:line or key>: <what was expected>". The run holds the case's lock
/// (CaseLock.hpp; rank 0 does for all ranks) from after the case is read to its end, so
/// nothing is written or removed without it. Returns frictionSolver's exit code: 0 every step
/// converged; 1 bad input, or a case the run refuses to touch (locked by another run, time
/// folders of an earlier run or not the solver's); 3 some step did not converge, was inaccurate
/// or diverged; 4 the factorisation failed; 5 stopped by SIGINT/SIGTERM; 6 an output or system
/// error. If `kept` is given and the case was read, the FrictionCase is handed back there
/// (after its run, or after the failure), for the caller to read its results.
int runCase(const std::string& caseDir, const RunCaseOptions& options, std::ostream& log,
            std::ostream& err, std::unique_ptr<FrictionCase>* kept = nullptr);

/// The exit code runCase gives for a failure (an exception caught): 1 for bad input, 6 for an
/// output or system error. With several ranks, what they agree on (parallel::agree).
int exitStatusOf(const std::exception_ptr& error);

/// The largest resident set of this process so far [bytes]; 0 if unknown.
double peakMemoryBytes();

}  // namespace friction
