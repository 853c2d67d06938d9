// OpenFOAM-style command lines (-case DIR, -help, -listModels) for the applications and
// utilities, on Boost.ProgramOptions (single-dash long options are accepted).
#pragma once

#include <optional>
#include <string>

#include <boost/program_options.hpp>

namespace friction {

/// Parse argv against options. On a bad command line prints "<application>: <problem>" and a
/// hint to stderr and returns nothing (the caller exits with status 2).
std::optional<boost::program_options::variables_map> parseCommandLine(
    int argc, char** argv, const boost::program_options::options_description& options,
    const std::string& application);

}  // namespace friction
