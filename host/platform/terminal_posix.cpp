#include "platform/terminal.hpp"

#include <unistd.h>

namespace fr {

bool stderr_is_terminal() {
  return isatty(STDERR_FILENO) != 0;
}

}  // namespace fr
