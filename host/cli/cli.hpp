// cli.hpp — the `fractalis` command line. main() only forwards to run_cli, so tests drive the
// whole CLI in-process.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace fr {

// args excludes the program name. Returns the exit code: 0 ok, 1 failed while working, 2 usage.
int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace fr
