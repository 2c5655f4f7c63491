// options.hpp — command-line options: a small declarative parser and the value parsers that
// turn text into checked values. Every failure is a UsageError whose message names the option
// and the value, and what was expected; the CLI prints it on one line and exits with code 2.
#pragma once

#include "io/dd_text.hpp"

#include <array>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace fr {

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct OptionSpec {
  const char* name;        // without the leading "--"
  const char* value_name;  // null: a flag without a value
  bool repeatable;
  const char* help;
};

struct ParsedOptions {
  std::map<std::string, std::vector<std::string>> values;  // flags map to {""}
  bool has(const std::string& name) const { return values.count(name) != 0; }
  // The last value given for `name`, or nullopt.
  std::optional<std::string> get(const std::string& name) const;
};

// Parses `--name value`, `--name=value` and flags; anything else is a UsageError naming it.
ParsedOptions parse_options(const std::string& command, const std::vector<std::string>& args,
                            const std::vector<OptionSpec>& specs);

// Help text: one line per option.
std::string format_options(const std::vector<OptionSpec>& specs);

// Value parsers; `what` names the option in messages ("--size").
// "WxH", each side in [1, max_side].
std::array<int, 2> parse_size(const std::string& what, const std::string& text,
                              int max_side = 16384);
std::array<double, 3> parse_vec3(const std::string& what, const std::string& text);  // "x,y,z"
// "x,y,z" to double-double (io/dd_text.hpp): each number's nearest pair, for a deep view's eye
// and target. *most_digits, when given, receives the most significant digits a number had.
std::array<DoubleDouble, 3> parse_vec3_pairs(const std::string& what, const std::string& text,
                                             int* most_digits = nullptr);
double parse_finite(const std::string& what, const std::string& text);
long long parse_integer(const std::string& what, const std::string& text, long long lo,
                        long long hi);

// A file an option will write at the end of the command, checked before any work: its folder
// exists and the path is something io/atomic_file.hpp writes (a new or regular file, a symlink to
// one, a character device or FIFO). A UsageError names the option, the path and why otherwise.
void check_output_file(const std::string& what, const std::string& path);

// Largest image side rendered in one piece, in pixels (a 16384 x 16384 float image is already
// 4 GiB): the explorer, bench, sweep.
constexpr int kMaxImageSide = 16384;
// Largest side `render` takes: larger images are rendered in bands (image/poster.hpp).
constexpr int kMaxPosterSide = 65535;

}  // namespace fr
