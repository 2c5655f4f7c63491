#include "platform/shared_library.hpp"

#include <dlfcn.h>
#include <elf.h>
#include <fcntl.h>
#include <link.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace fr {
namespace {

// The memfd's name: /proc/self/maps shows its mappings as "/memfd:fractalis-plugin (deleted)".
constexpr const char* kCopyName = "fractalis-plugin";

const char* machine_name(unsigned machine) {
  switch (machine) {
    case EM_X86_64:
      return "x86-64";
    case EM_386:
      return "i386";
    case EM_AARCH64:
      return "AArch64";
    case EM_ARM:
      return "ARM";
    case EM_RISCV:
      return "RISC-V";
    case EM_PPC64:
      return "PowerPC 64";
    case EM_S390:
      return "s390";
    case EM_MIPS:
      return "MIPS";
    case EM_LOONGARCH:
      return "LoongArch";
  }
  return nullptr;
}

std::string describe_machine(unsigned machine) {
  const char* name = machine_name(machine);
  return name ? name : "ELF machine " + std::to_string(machine);
}

// This process's own ELF identity: what a plugin must have been built for.
struct ElfTarget {
  unsigned char elf_class = 0, data = 0;
  unsigned machine = 0;
};
const ElfTarget& host_target() {
  static const ElfTarget target = [] {
    ElfTarget t;
    const int fd = open("/proc/self/exe", O_RDONLY | O_CLOEXEC);
    ElfW(Ehdr) eh{};
    if (fd >= 0 && pread(fd, &eh, sizeof eh, 0) == static_cast<ssize_t>(sizeof eh)) {
      t.elf_class = eh.e_ident[EI_CLASS];
      t.data = eh.e_ident[EI_DATA];
      t.machine = eh.e_machine;
    }
    if (fd >= 0) close(fd);
    return t;
  }();
  return target;
}

// Whether a loaded object already goes by `name` (glibc would hand back that one instead).
bool loaded_under_name(const std::string& name) {
  struct Query {
    const std::string* name;
    bool found;
  } q{&name, false};
  dl_iterate_phdr(
      [](dl_phdr_info* info, size_t, void* data) {
        auto* q = static_cast<Query*>(data);
        if (info->dlpi_name && *q->name == info->dlpi_name) q->found = true;
        return 0;
      },
      &q);
  return q.found;
}

void replace_all(std::string& text, const std::string& from, const std::string& to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
}

}  // namespace

std::string check_library_bytes(const std::string& bytes) {
  const uint64_t size = bytes.size();
  const auto read_at = [&](uint64_t at, void* out, size_t n) -> size_t {
    if (at >= size) return 0;
    const size_t got = static_cast<size_t>(std::min<uint64_t>(n, size - at));
    std::memcpy(out, bytes.data() + at, got);
    return got;
  };
  unsigned char ident[EI_NIDENT] = {};
  const size_t got = read_at(0, ident, sizeof ident);
  if (got < 4 || std::memcmp(ident, ELFMAG, SELFMAG) != 0) {
    char hex[32] = "fewer than 4 bytes";
    if (got >= 4)
      std::snprintf(hex, sizeof hex, "%02x %02x %02x %02x", ident[0], ident[1], ident[2], ident[3]);
    return std::string("not an ELF shared library (expected bytes 7f 45 4c 46, found ") + hex + ")";
  }
  const ElfTarget& host = host_target();
  if (got < EI_NIDENT) return "truncated: " + std::to_string(size) + " bytes";
  if (ident[EI_CLASS] != host.elf_class)
    return std::string("built as a ") + (ident[EI_CLASS] == ELFCLASS32 ? "32" : "64") +
           "-bit ELF library; this host is " + (host.elf_class == ELFCLASS32 ? "32" : "64") +
           "-bit";
  if (ident[EI_DATA] != host.data) return "built for the other byte order than this host's";
  ElfW(Ehdr) eh{};
  if (read_at(0, &eh, sizeof eh) != sizeof eh)
    return "truncated: " + std::to_string(size) + " bytes, shorter than an ELF header";
  if (eh.e_machine != host.machine)
    return "built for " + describe_machine(eh.e_machine) + "; this host is " +
           describe_machine(host.machine);
  if (eh.e_type != ET_DYN)
    return "not a shared library (ELF type " + std::to_string(eh.e_type) + ")";
  // dlopen maps a truncated library and then dies of SIGBUS touching the missing pages, so the
  // headers and every loadable segment must lie inside the file.
  const uint64_t ph_end = eh.e_phoff + uint64_t{eh.e_phnum} * eh.e_phentsize;
  const uint64_t sh_end = eh.e_shoff + uint64_t{eh.e_shnum} * eh.e_shentsize;
  if (eh.e_phentsize != sizeof(ElfW(Phdr)) || ph_end > size || sh_end > size)
    return "truncated: " + std::to_string(size) + " bytes, but its headers end at byte " +
           std::to_string(std::max(ph_end, sh_end));
  for (unsigned i = 0; i < eh.e_phnum; ++i) {
    ElfW(Phdr) ph{};
    if (read_at(eh.e_phoff + uint64_t{i} * sizeof ph, &ph, sizeof ph) != sizeof ph)
      return "truncated program header";
    if (ph.p_type == PT_LOAD && ph.p_offset + ph.p_filesz > size)
      return "truncated: " + std::to_string(size) + " bytes, but a loadable segment ends at byte " +
             std::to_string(ph.p_offset + ph.p_filesz);
  }
  return "";
}

std::unique_ptr<SharedLibrary> SharedLibrary::load_private_copy(
    const std::string& bytes, const std::filesystem::path& named_as, std::string* error) {
  if (std::string problem = check_library_bytes(bytes); !problem.empty()) {
    *error = problem;
    return nullptr;
  }
  const int memfd = memfd_create(kCopyName, MFD_CLOEXEC | MFD_ALLOW_SEALING);
  if (memfd < 0) {
    *error = std::string("cannot make a private copy (memfd_create): ") + std::strerror(errno);
    return nullptr;
  }
  auto fail = [&](std::string why) {
    close(memfd);
    *error = std::move(why);
    return nullptr;
  };
  // Copy, then seal: the bytes checked above are the bytes dlopen maps.
  for (size_t done = 0; done < bytes.size();) {
    const ssize_t w = write(memfd, bytes.data() + done, bytes.size() - done);
    if (w < 0 && errno == EINTR) continue;
    if (w < 0) return fail(std::string("cannot copy: ") + std::strerror(errno));
    done += static_cast<size_t>(w);
  }
  fcntl(memfd, F_ADD_SEALS, F_SEAL_SHRINK | F_SEAL_GROW | F_SEAL_WRITE | F_SEAL_SEAL);

  // glibc hands back an already loaded object that has the same name, so the fd number must not
  // be one an earlier (still resident) library was loaded under.
  int load_fd = memfd;
  std::vector<int> spare;
  while (loaded_under_name("/proc/self/fd/" + std::to_string(load_fd))) {
    spare.push_back(load_fd);
    load_fd = fcntl(memfd, F_DUPFD_CLOEXEC, load_fd + 1);
    if (load_fd < 0) {
      for (int f : spare)
        if (f != memfd) close(f);
      return fail("cannot find a free descriptor for the private copy");
    }
  }
  for (int f : spare)
    if (f != memfd) close(f);
  if (load_fd != memfd) close(memfd);
  const std::string copy_name = "/proc/self/fd/" + std::to_string(load_fd);
  void* handle = dlopen(copy_name.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* dl_error = dlerror();
    std::string message = std::string("dlopen failed: ") + (dl_error ? dl_error : "unknown error");
    replace_all(message, copy_name, named_as.string());
    close(load_fd);
    *error = message;
    return nullptr;
  }
  std::unique_ptr<SharedLibrary> library(new SharedLibrary());
  library->handle_ = handle;
  library->copy_ = load_fd;  // kept open while loaded: its /proc/self/fd name must not be reused
  return library;
}

SharedLibrary::~SharedLibrary() {
  dlclose(handle_);
  close(static_cast<int>(copy_));
}

const void* SharedLibrary::symbol(const char* name) const {
  dlerror();
  return dlsym(handle_, name);
}

size_t private_copy_mappings() {
  std::ifstream maps("/proc/self/maps");
  std::string line;
  size_t n = 0;
  while (std::getline(maps, line))
    if (line.find(kCopyName) != std::string::npos) ++n;
  return n;
}

std::string library_file_name(const std::string& name) {
  return name + ".so";
}

bool is_library_file_name(const std::filesystem::path& file) {
  return file.extension() == ".so" && !file.stem().empty();
}

}  // namespace fr
