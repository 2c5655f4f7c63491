#include "cli/options.hpp"

#include "io/atomic_file.hpp"
#include "io/echo.hpp"

#include <algorithm>
#include <filesystem>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace fr {

std::optional<std::string> ParsedOptions::get(const std::string& name) const {
  auto it = values.find(name);
  if (it == values.end() || it->second.empty()) return std::nullopt;
  return it->second.back();
}

ParsedOptions parse_options(const std::string& command, const std::vector<std::string>& args,
                            const std::vector<OptionSpec>& specs) {
  ParsedOptions out;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg.rfind("--", 0) != 0 || arg.size() == 2)
      throw UsageError("unexpected argument '" + arg + "' for '" + command + "' (see fractalis " +
                       command + " --help)");
    std::string name = arg.substr(2), value;
    bool inline_value = false;
    if (auto eq = name.find('='); eq != std::string::npos) {
      value = name.substr(eq + 1);
      name = name.substr(0, eq);
      inline_value = true;
    }
    const OptionSpec* spec = nullptr;
    for (const auto& s : specs)
      if (name == s.name) spec = &s;
    if (!spec)
      throw UsageError("unknown option '--" + echo(name) + "' for '" + command +
                       "' (see fractalis " + command + " --help)");
    if (spec->value_name) {
      if (!inline_value) {
        if (i + 1 >= args.size())
          throw UsageError("option '--" + name + "' needs a value (" + spec->value_name + ")");
        value = args[++i];
      }
    } else if (inline_value) {
      throw UsageError("option '--" + name + "' takes no value");
    }
    auto& slot = out.values[name];
    if (!slot.empty() && !spec->repeatable)
      throw UsageError("option '--" + name + "' given more than once");
    slot.push_back(value);
  }
  return out;
}

std::string format_options(const std::vector<OptionSpec>& specs) {
  std::ostringstream out;
  for (const auto& s : specs) {
    std::string left =
        std::string("  --") + s.name + (s.value_name ? std::string(" ") + s.value_name : "");
    out << left;
    for (size_t n = left.size(); n < 30; ++n) out << ' ';
    out << " " << s.help << "\n";
  }
  return out.str();
}

double parse_finite(const std::string& what, const std::string& text) {
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  double v = std::strtod(begin, &end);
  if (text.empty() || end != begin + text.size())
    throw UsageError(what + ": '" + echo(text) + "' is not a number");
  if (!std::isfinite(v) || errno == ERANGE)
    throw UsageError(what + ": '" + echo(text) + "' is not a finite number");
  return v;
}

long long parse_integer(const std::string& what, const std::string& text, long long lo,
                        long long hi) {
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  long long v = std::strtoll(begin, &end, 10);
  if (text.empty() || end != begin + text.size() || errno == ERANGE)
    throw UsageError(what + ": '" + echo(text) + "' is not a whole number");
  if (v < lo || v > hi)
    throw UsageError(what + ": " + echo(text) + " is outside [" + std::to_string(lo) + ", " +
                     std::to_string(hi) + "]");
  return v;
}

std::array<int, 2> parse_size(const std::string& what, const std::string& text, int max_side) {
  auto x = text.find_first_of("xX");
  if (x == std::string::npos)
    throw UsageError(what + ": '" + echo(text) + "' is not WIDTHxHEIGHT (for example 1280x720)");
  std::array<int, 2> size{};
  for (int i = 0; i < 2; ++i) {
    const std::string part = i == 0 ? text.substr(0, x) : text.substr(x + 1);
    size[i] =
        static_cast<int>(parse_integer(what + (i == 0 ? " width" : " height"), part, 1, max_side));
  }
  return size;
}

std::array<double, 3> parse_vec3(const std::string& what, const std::string& text) {
  std::array<double, 3> v{};
  size_t start = 0;
  for (int i = 0; i < 3; ++i) {
    size_t comma = text.find(',', start);
    if ((i < 2) != (comma != std::string::npos))
      throw UsageError(what + ": '" + echo(text) + "' is not three comma-separated numbers x,y,z");
    v[i] = parse_finite(what, text.substr(start, i < 2 ? comma - start : std::string::npos));
    start = comma + 1;
  }
  return v;
}

std::array<DoubleDouble, 3> parse_vec3_pairs(const std::string& what, const std::string& text,
                                             int* most_digits) {
  const std::array<double, 3> rounded = parse_vec3(what, text);  // its errors, its rules
  std::array<DoubleDouble, 3> v{};
  size_t start = 0;
  if (most_digits) *most_digits = 0;
  for (int i = 0; i < 3; ++i) {
    const size_t comma = text.find(',', start);
    std::string part = text.substr(start, i < 2 ? comma - start : std::string::npos);
    part.erase(0, part.find_first_not_of(" \t"));
    part.erase(part.find_last_not_of(" \t") + 1);
    int digits = 0;
    // What parse_vec3 takes and a pair cannot hold (a value below 1e-290) keeps its double.
    v[i] = parse_double_double(part, &digits).value_or(DoubleDouble{rounded[i], 0});
    if (most_digits) *most_digits = std::max(*most_digits, digits);
    start = comma + 1;
  }
  return v;
}

void check_output_file(const std::string& what, const std::string& path) {
  if (path.empty()) throw UsageError(what + ": empty file name");
  std::error_code ec;
  const std::filesystem::path file(path);
  const std::filesystem::path folder = file.parent_path();
  if (!folder.empty() && !std::filesystem::is_directory(folder, ec))
    throw UsageError(what + ": folder '" + echo(folder.string()) + "' does not exist");
  if (const std::string problem = output_problem(file); !problem.empty())
    throw UsageError(what + ": '" + echo(path) + "' " + problem);
}

}  // namespace fr
