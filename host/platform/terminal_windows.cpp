#include "platform/terminal.hpp"

#include <windows.h>

namespace fr {

bool stderr_is_terminal() {
  // A console handle has a console mode; a file or a pipe (MSYS terminals included) has none.
  DWORD mode = 0;
  return GetConsoleMode(GetStdHandle(STD_ERROR_HANDLE), &mode) != 0;
}

}  // namespace fr
