#include "render/scene_source_guard.hpp"

#include "render/cl_runtime.hpp"

#include <cctype>

namespace fr {
namespace {

// What one pass over a source file finds: OpenCL C's comments, strings, character literals,
// preprocessor lines (with their continuations) and nesting, without a real parser. Enough to
// name what a file defines at file scope and what it leaves open.
struct SourceScan {
  struct Named {
    int line;
    std::string word;  // the directive ("define", "undef"), or "function", "type"
    std::string name;
  };
  std::vector<Named> names;
  int open_comment_line = 0;  // 0: none
  std::vector<int> open_if_lines;
  int stray_endif_line = 0;
  int open_brace_line = 0, open_paren_line = 0;
};

bool ident_start(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}
bool ident_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

// A position in the text, with its line.
struct Cursor {
  std::string_view s;
  size_t i = 0;
  int line = 1;
  bool at_end() const { return i >= s.size(); }
  bool starts(const char* two) const {
    return i + 1 < s.size() && s[i] == two[0] && s[i + 1] == two[1];
  }
};

// At "/*": past its "*/"; false (and the comment's line noted) when it never closes.
bool skip_block_comment(Cursor& c, SourceScan& out) {
  const int start = c.line;
  c.i += 2;
  while (c.i + 1 < c.s.size() && !c.starts("*/")) c.line += c.s[c.i++] == '\n';
  if (c.i + 1 >= c.s.size()) {
    out.open_comment_line = start;
    c.i = c.s.size();
    return false;
  }
  c.i += 2;
  return true;
}

// Past a comment or a line continuation at the cursor; false when there is none there. (A block
// comment that never closes ends the text.)
bool skip_comment_or_continuation(Cursor& c, SourceScan& out) {
  if (c.starts("\\\n")) {
    c.i += 2;
    ++c.line;
  } else if (c.starts("/*")) {
    skip_block_comment(c, out);
  } else if (c.starts("//")) {
    while (!c.at_end() && c.s[c.i] != '\n') ++c.i;
  } else {
    return false;
  }
  return true;
}

// At a quote: past the string or character literal (or to the end of its line).
void skip_quoted(Cursor& c) {
  const char q = c.s[c.i++];
  while (!c.at_end() && c.s[c.i] != q && c.s[c.i] != '\n')
    c.i += (c.s[c.i] == '\\' && c.i + 1 < c.s.size()) ? 2 : 1;
  if (!c.at_end() && c.s[c.i] == q) ++c.i;
}

std::string read_identifier(Cursor& c) {
  std::string word;
  while (!c.at_end() && ident_char(c.s[c.i])) word += c.s[c.i++];
  return word;
}

// At a line's "#": the directive's word and first name, then the rest of its logical line
// (continuations, comments and quotes in it).
void scan_directive(Cursor& c, SourceScan& out) {
  const int line = c.line;
  auto blanks = [&] {
    while (!c.at_end() && (c.s[c.i] == ' ' || c.s[c.i] == '\t')) ++c.i;
  };
  ++c.i;
  blanks();
  const std::string word = read_identifier(c);
  blanks();
  const std::string name = read_identifier(c);
  while (!c.at_end() && c.s[c.i] != '\n') {
    if (skip_comment_or_continuation(c, out)) continue;
    if (c.s[c.i] == '"' || c.s[c.i] == '\'')
      skip_quoted(c);
    else
      ++c.i;
  }
  if (word == "if" || word == "ifdef" || word == "ifndef") {
    out.open_if_lines.push_back(line);
  } else if (word == "endif") {
    if (!out.open_if_lines.empty())
      out.open_if_lines.pop_back();
    else if (!out.stray_endif_line)
      out.stray_endif_line = line;
  } else if ((word == "define" || word == "undef") && !name.empty()) {
    out.names.push_back({line, word, name});
  }
}

// What code at file scope defines: a function is a name, "(...)" and then "{"; a type follows
// "struct", "union" or "enum", or ends a typedef.
struct FileScope {
  int brace = 0, paren = 0;
  int brace_line = 0, paren_line = 0;  // of the outermost open one
  std::string last_ident, candidate;   // candidate: the name before a file-scope '('
  bool after_params = false;           // a file-scope ')' just closed the candidate's parameters
  bool in_typedef = false, after_struct = false;
  std::string statement_last;  // last identifier of the file-scope statement (typedef's name)

  void identifier(const std::string& word, int line, SourceScan& out) {
    if (brace == 0 && paren == 0) {
      if (word == "typedef") in_typedef = true;
      if (after_struct) out.names.push_back({line, "type", word});
      after_struct = word == "struct" || word == "union" || word == "enum";
      statement_last = word;
    }
    last_ident = word;
    after_params = false;
  }

  void punctuation(char ch, int line, SourceScan& out) {
    bool keep_after_params = false;
    switch (ch) {
      case '(':
        if (brace == 0 && paren == 0) candidate = last_ident, paren_line = line;
        ++paren;
        break;
      case ')':
        if (paren > 0 && --paren == 0 && brace == 0) keep_after_params = true;
        break;
      case '{':
        if (brace == 0) {
          if (after_params && paren == 0 && !candidate.empty())
            out.names.push_back({line, "function", candidate});
          brace_line = line;
        }
        ++brace;
        break;
      case '}':
        if (brace > 0) --brace;
        break;
      case ';':
        if (brace == 0 && paren == 0) {
          if (in_typedef && !statement_last.empty())
            out.names.push_back({line, "type", statement_last});
          in_typedef = false;
          statement_last.clear();
        }
        break;
      default:
        break;
    }
    after_params = keep_after_params;
    after_struct = false;
    last_ident.clear();
  }
};

SourceScan scan_source(std::string_view text) {
  SourceScan out;
  Cursor c{text};
  FileScope scope;
  bool line_start = true;
  while (!c.at_end()) {
    if (skip_comment_or_continuation(c, out)) continue;
    const char ch = c.s[c.i];
    if (ch == '\n') {
      ++c.line;
      line_start = true;
      ++c.i;
    } else if (ch == ' ' || ch == '\t' || ch == '\r' || ch == '\f' || ch == '\v') {
      ++c.i;
    } else if (line_start && ch == '#') {
      scan_directive(c, out);
    } else {
      line_start = false;
      if (ch == '"' || ch == '\'') {
        skip_quoted(c);
        scope.after_params = false;
      } else if (ident_start(ch)) {
        scope.identifier(read_identifier(c), c.line, out);
      } else {
        ++c.i;
        scope.punctuation(ch, c.line, out);
      }
    }
  }
  if (scope.brace > 0) out.open_brace_line = scope.brace_line;
  if (scope.paren > 0) out.open_paren_line = scope.paren_line;
  return out;
}

bool reserved(const std::string& name) {
  return name.rfind("FR_", 0) == 0 || name.rfind("fr_", 0) == 0;
}

}  // namespace

HostKernelNames collect_host_names(const std::vector<std::string_view>& before,
                                   const std::vector<std::string_view>& after) {
  HostKernelNames host;
  // The assembler's own generated names (kernel_assembly.cpp) that do not begin with FR_.
  host.defined = {"PARAM", "scene_params_t"};
  for (const auto* files : {&before, &after})
    for (std::string_view text : *files)
      for (const auto& named : scan_source(text).names) {
        if (named.word == "undef") continue;
        host.defined.insert(named.name);
        if (files == &after && named.word == "function") host.functions_after.insert(named.name);
      }
  return host;
}

bool source_defines_function(std::string_view text, std::string_view name) {
  for (const auto& named : scan_source(text).names)
    if (named.word == "function" && named.name == name) return true;
  return false;
}

std::vector<std::string> guard_scene_source(const std::string& scene_id, std::string_view file_name,
                                            std::string_view text, const HostKernelNames& host) {
  const SourceScan scan = scan_source(text);
  auto refuse = [&](int line, const std::string& why) {
    throw KernelBuildError("scene '" + scene_id + "': " + std::string(file_name) + ":" +
                           std::to_string(line) + ": " + why);
  };
  std::vector<std::string> macros;
  for (const auto& named : scan.names) {
    if (named.word == "define" || named.word == "undef") {
      const std::string what = "`#" + named.word + " " + named.name + "`";
      if (reserved(named.name))
        refuse(named.line, what +
                               ": names beginning FR_ or fr_ are the host's (its switches "
                               "and hooks); choose another name");
      if (host.defined.count(named.name))
        refuse(named.line, what + " would change the host's own " + named.name +
                               " for all of its code after the scene's; choose another name");
      bool known = false;
      for (const auto& m : macros) known |= m == named.name;
      if (!known) macros.push_back(named.name);
    } else if (named.word == "function" && host.functions_after.count(named.name)) {
      refuse(named.line, "function " + named.name +
                             "() has the name of one of the host's render stages; choose "
                             "another name");
    }
  }
  if (scan.open_comment_line)
    refuse(scan.open_comment_line,
           "a comment opened here is never closed (it would hide the host's code after it)");
  if (!scan.open_if_lines.empty())
    refuse(scan.open_if_lines.back(), "this #if has no #endif in the file");
  if (scan.stray_endif_line) refuse(scan.stray_endif_line, "#endif without #if");
  if (scan.open_paren_line) refuse(scan.open_paren_line, "a '(' opened here is never closed");
  if (scan.open_brace_line) refuse(scan.open_brace_line, "a '{' opened here is never closed");
  return macros;
}

}  // namespace fr
