#include "friction/core/CommandLine.hpp"

#include <iostream>

namespace friction {

namespace po = boost::program_options;

std::optional<po::variables_map> parseCommandLine(int argc, char** argv,
                                                  const po::options_description& options,
                                                  const std::string& application) {
  po::variables_map args;
  try {
    po::store(po::command_line_parser(argc, argv)
                  .options(options)
                  .style(po::command_line_style::default_style |
                         po::command_line_style::allow_long_disguise)
                  .run(),
              args);
    po::notify(args);
  } catch (const po::error& e) {
    std::cerr << application << ": " << e.what() << "\n(run with -help for usage)\n";
    return std::nullopt;
  }
  return args;
}

}  // namespace friction
