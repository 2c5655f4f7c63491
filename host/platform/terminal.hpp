// terminal.hpp — whether a person is watching this process's error stream.
#pragma once

namespace fr {

// stderr is a terminal (a console on Windows): progress bars redraw in place there, and are
// plain lines in a file or a pipe.
bool stderr_is_terminal();

}  // namespace fr
