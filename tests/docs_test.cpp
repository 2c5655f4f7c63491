// README.md and docs/: every link resolves (a file that exists, a heading that exists), and every
// `fractalis` command shown in a shell block is one the CLI accepts — its command and options
// are known, each with its value, each `--set KEY=VALUE` names a setting and passes its check,
// and each `--scene` names an in-tree scene (plugins/ID/). The options are checked by the CLI itself
// (`fractalis COMMAND ... --help` parses every option and then only prints the help), so this
// test holds no list of options of its own.
#include "cli_run.hpp"
#include "settings/settings.hpp"
#include "test_paths.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fr {
namespace {

namespace fs = std::filesystem;

const fs::path kRoot = SOURCE_DIR;

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// README.md and every page under docs/.
std::vector<fs::path> documents() {
  std::vector<fs::path> files = {kRoot / "README.md"};
  for (const auto& entry : fs::recursive_directory_iterator(kRoot / "docs"))
    if (entry.path().extension() == ".md") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// The anchor GitHub gives a heading: lower case, spaces to '-', punctuation other than '-' and
// '_' dropped (non-ASCII letters kept).
std::string heading_anchor(const std::string& heading) {
  std::string anchor;
  for (unsigned char c : heading) {
    if (std::isalnum(c) || c == '-' || c == '_' || c >= 0x80)
      anchor += static_cast<char>(std::tolower(c));
    else if (c == ' ')
      anchor += '-';
  }
  return anchor;
}

// The anchors of a Markdown file's headings (outside code blocks).
std::set<std::string> anchors_of(const fs::path& file) {
  std::set<std::string> anchors;
  bool in_code = false;
  for (const std::string& line : lines_of(read_text(file))) {
    if (line.rfind("```", 0) == 0) in_code = !in_code;
    if (in_code || line.empty() || line[0] != '#') continue;
    const size_t text = line.find_first_not_of('#');
    if (text == std::string::npos || line[text] != ' ') continue;
    anchors.insert(heading_anchor(line.substr(text + 1)));
  }
  return anchors;
}

// The targets of the Markdown links [text](target) and images ![alt](target) on a line: a "]("
// after a "[", up to the ")" (a target with a space is not a link). Parsed by hand: std::regex
// trips GCC 12's -Wmaybe-uninitialized in the sanitizer build, where warnings are errors.
std::vector<std::string> link_targets(const std::string& line) {
  std::vector<std::string> targets;
  size_t opened = std::string::npos;
  for (size_t i = 0; i + 1 < line.size(); ++i) {
    if (line[i] == '[') {
      opened = i;
    } else if (line[i] == ']' && line[i + 1] == '(' && opened != std::string::npos) {
      const size_t close = line.find(')', i + 2);
      if (close == std::string::npos) break;
      const std::string target = line.substr(i + 2, close - i - 2);
      if (!target.empty() && target.find_first_of(" \t") == std::string::npos)
        targets.push_back(target);
      opened = std::string::npos;
      i = close;
    }
  }
  return targets;
}

TEST(Docs, LinksAreFoundAsMarkdownHasThem) {
  EXPECT_EQ(link_targets("see [a](x.md#y), ![b](img.png) and [c] (not) [d](has space)"),
            (std::vector<std::string>{"x.md#y", "img.png"}));
}

TEST(Docs, HeadingAnchorsFollowGitHub) {
  EXPECT_EQ(heading_anchor("What would reach the targets"), "what-would-reach-the-targets");
  EXPECT_EQ(heading_anchor("Many machines (MPI)"), "many-machines-mpi");
  EXPECT_EQ(heading_anchor("CI"), "ci");
  EXPECT_EQ(heading_anchor("`soak`: the long loops"), "soak-the-long-loops");
}

// Every [text](target) and ![alt](target) outside code: a relative target names a file or
// folder that exists, and its #anchor a heading of that Markdown file.
TEST(Docs, EveryLinkResolves) {
  size_t checked = 0;
  for (const fs::path& file : documents()) {
    bool in_code = false;
    int line_number = 0;
    for (const std::string& line : lines_of(read_text(file))) {
      ++line_number;
      if (line.rfind("```", 0) == 0) in_code = !in_code;
      if (in_code) continue;
      // Inline code spans are not links.
      std::string prose;
      bool in_span = false;
      for (char c : line) {
        if (c == '`') in_span = !in_span;
        prose += in_span ? ' ' : c;
      }
      for (const std::string& target : link_targets(prose)) {
        const std::string where = fs::relative(file, kRoot).string() + ":" +
                                  std::to_string(line_number) + ": " + target;
        if (target.rfind("http://", 0) == 0 || target.rfind("https://", 0) == 0 ||
            target.rfind("mailto:", 0) == 0)
          continue;
        const size_t hash = target.find('#');
        const std::string path_part = target.substr(0, hash);
        const fs::path resolved = path_part.empty() ? file : file.parent_path() / path_part;
        ++checked;
        if (!fs::exists(resolved)) {
          ADD_FAILURE() << where << ": no such file";
          continue;
        }
        if (hash == std::string::npos) continue;
        if (resolved.extension() != ".md") {
          ADD_FAILURE() << where << ": an anchor into a file that is not Markdown";
          continue;
        }
        EXPECT_EQ(anchors_of(resolved).count(target.substr(hash + 1)), 1u)
            << where << ": no such heading in " << fs::relative(resolved, kRoot).string();
      }
    }
  }
  EXPECT_GT(checked, 20u) << "the pages link to each other";
}

// Splits a shell line into words: quotes group, a backslash escapes, '#' starts a comment.
std::vector<std::string> shell_words(const std::string& line) {
  std::vector<std::string> words;
  std::string word;
  bool in_word = false;
  char quote = 0;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quote) {
      if (c == quote)
        quote = 0;
      else
        word += c;
    } else if (c == '\'' || c == '"') {
      quote = c;
      in_word = true;
    } else if (c == '\\' && i + 1 < line.size()) {
      word += line[++i];
      in_word = true;
    } else if (c == '#' && !in_word) {
      break;
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      if (in_word) words.push_back(word);
      word.clear();
      in_word = false;
    } else {
      word += c;
      in_word = true;
    }
  }
  if (in_word) words.push_back(word);
  return words;
}

struct ShownCommand {
  std::string where;               // file:line
  std::vector<std::string> args;   // after `fractalis`
};

// The `fractalis` commands of a page's shell blocks (```sh, ```bash, ```console; in a console
// block only lines after a "$ " prompt), continued lines joined, each cut at a pipe, `&&` or
// `;`. A command is what follows a word that is `fractalis` (or ends in /fractalis) or
// scripts/run.sh, where the run script names a command.
std::vector<ShownCommand> shown_commands(const fs::path& file) {
  std::vector<ShownCommand> commands;
  const std::vector<std::string> lines = lines_of(read_text(file));
  std::string block;  // the open block's language, "" outside one
  bool in_code = false;
  for (size_t i = 0; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    if (line.rfind("```", 0) == 0) {
      in_code = !in_code;
      block = in_code ? line.substr(3) : "";
      continue;
    }
    if (!in_code || (block != "sh" && block != "bash" && block != "console")) continue;
    std::string text = line;
    if (block == "console") {
      if (text.rfind("$ ", 0) != 0) continue;
      text = text.substr(2);
    }
    const size_t first = i;
    while (!text.empty() && text.back() == '\\' && i + 1 < lines.size()) {
      text.pop_back();
      text += " " + lines[++i];
    }
    const std::vector<std::string> words = shell_words(text);
    for (size_t w = 0; w < words.size(); ++w) {
      const std::string& word = words[w];
      const bool is_fractalis = word == "fractalis" || (word.size() > 10 &&
                                                        word.compare(word.size() - 10, 10,
                                                                     "/fractalis") == 0);
      const bool is_run_script = word == "./scripts/run.sh" || word == "scripts/run.sh";
      if (!is_fractalis && !is_run_script) continue;
      ShownCommand command{fs::relative(file, kRoot).string() + ":" + std::to_string(first + 1),
                           {}};
      for (size_t a = w + 1; a < words.size(); ++a) {
        if (words[a] == "|" || words[a] == "&&" || words[a] == ";" || words[a] == "||") break;
        command.args.push_back(words[a]);
      }
      // The run script alone opens the explorer; with arguments it is fractalis's command line.
      if (is_run_script && command.args.empty()) break;
      commands.push_back(command);
      break;
    }
  }
  return commands;
}

TEST(Docs, ShellWordsSplitAsAShellDoes) {
  EXPECT_EQ(shell_words("fractalis render --param 'c=1, 2' --out a\\ b.png  # note"),
            (std::vector<std::string>{"fractalis", "render", "--param", "c=1, 2", "--out",
                                      "a b.png"}));
  EXPECT_EQ(shell_words("a \"#not a comment\" b#c"),
            (std::vector<std::string>{"a", "#not a comment", "b#c"}));
}

// Every `fractalis` command shown is accepted: the CLI parses it with --help added (unknown
// options, missing values and repeats are usage errors, exit 2), its settings are known keys
// with valid values, and its scene exists.
TEST(Docs, EveryShownCommandParses) {
  size_t checked = 0;
  for (const fs::path& file : documents()) {
    std::vector<std::string> made;  // scenes a `fractalis new NAME` on the page made
    for (const ShownCommand& command : shown_commands(file)) {
      if (command.args.size() >= 2 && command.args[0] == "new") made.push_back(command.args[1]);
      ++checked;
      std::vector<std::string> args = command.args;
      const bool help_given =
          std::find(args.begin(), args.end(), "--help") != args.end() ||
          std::find(args.begin(), args.end(), "--version") != args.end();
      if (!help_given) args.push_back("--help");
      const test::CliRun r = test::run(args);
      EXPECT_EQ(r.code, 0) << command.where << ": fractalis rejects what the page shows:\n"
                           << r.err;
      for (size_t a = 0; a + 1 < command.args.size(); ++a) {
        const std::string& option = command.args[a];
        const std::string& value = command.args[a + 1];
        if (option == "--set") {
          Settings settings;
          for (const SettingsProblem& problem : apply_setting_override(value, settings))
            ADD_FAILURE() << command.where << ": --set " << value << ": "
                          << problem.to_string();
        } else if (option == "--scene") {
          // In-tree scenes live in plugins/ID/; or the page made it with `fractalis new` above.
          EXPECT_TRUE(fs::is_directory(kRoot / "plugins" / value) ||
                      std::find(made.begin(), made.end(), value) != made.end())
              << command.where << ": no scene '" << value << "'";
        }
      }
    }
  }
  EXPECT_GT(checked, 20u) << "the pages show commands";
}

// A page that shows a command the CLI does not know fails: the check above is not vacuous.
TEST(Docs, AMistypedCommandIsCaught) {
  const fs::path page = fs::path(TEST_OUTPUT_DIR) / "docs_test_page.md";
  {
    std::ofstream out(page);
    out << "```sh\nfractalis render --scene mandelbulb --sampels 4 --out x.png\n```\n";
  }
  const std::vector<ShownCommand> commands = shown_commands(page);
  ASSERT_EQ(commands.size(), 1u);
  std::vector<std::string> args = commands[0].args;
  args.push_back("--help");
  const test::CliRun r = test::run(args);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("unknown option '--sampels'"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace fr
