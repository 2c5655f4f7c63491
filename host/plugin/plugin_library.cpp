#include "plugin/plugin_library.hpp"

#include <dlfcn.h>
#include <elf.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cstdio>
#include <fstream>
#include <memory>
#include <system_error>

namespace fr {
namespace {

std::filesystem::path private_copy_dir() {
  return std::filesystem::temp_directory_path() /
         ("fractalis-" + std::to_string(getuid()) + "-" + std::to_string(getpid()));
}

// ELF files start with 0x7f 'E' 'L' 'F'; anything else gets a clearer message than dlerror's.
bool starts_like_elf(const std::filesystem::path& file, std::string* first_bytes) {
  std::ifstream in(file, std::ios::binary);
  std::array<char, 4> magic{};
  in.read(magic.data(), magic.size());
  if (in.gcount() < 4) {
    *first_bytes = "fewer than 4 bytes";
    return false;
  }
  if (magic[0] == 0x7f && magic[1] == 'E' && magic[2] == 'L' && magic[3] == 'F') return true;
  char hex[32];
  std::snprintf(hex, sizeof hex, "%02x %02x %02x %02x", static_cast<unsigned char>(magic[0]),
                static_cast<unsigned char>(magic[1]), static_cast<unsigned char>(magic[2]),
                static_cast<unsigned char>(magic[3]));
  *first_bytes = hex;
  return false;
}

// dlopen maps a truncated library and then dies of SIGBUS touching the missing pages, so check
// first that the headers and every loadable segment lie inside the file. "" when it does.
std::string check_elf_complete(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  in.seekg(0, std::ios::end);
  const auto size = static_cast<uint64_t>(in.tellg());
  in.seekg(0);
  Elf64_Ehdr eh{};
  if (!in.read(reinterpret_cast<char*>(&eh), sizeof eh))
    return "truncated: " + std::to_string(size) + " bytes, shorter than an ELF header";
  if (eh.e_ident[EI_CLASS] != ELFCLASS64 || eh.e_machine != EM_X86_64)
    return "not a 64-bit x86-64 ELF library";
  if (eh.e_type != ET_DYN)
    return "not a shared library (ELF type " + std::to_string(eh.e_type) + ")";
  const uint64_t ph_end = eh.e_phoff + uint64_t{eh.e_phnum} * eh.e_phentsize;
  const uint64_t sh_end = eh.e_shoff + uint64_t{eh.e_shnum} * eh.e_shentsize;
  if (eh.e_phentsize != sizeof(Elf64_Phdr) || ph_end > size || sh_end > size)
    return "truncated: " + std::to_string(size) + " bytes, but its headers end at byte " +
           std::to_string(std::max(ph_end, sh_end));
  for (unsigned i = 0; i < eh.e_phnum; ++i) {
    Elf64_Phdr ph{};
    in.seekg(static_cast<std::streamoff>(eh.e_phoff + uint64_t{i} * sizeof ph));
    in.read(reinterpret_cast<char*>(&ph), sizeof ph);
    if (ph.p_type == PT_LOAD && ph.p_offset + ph.p_filesz > size)
      return "truncated: " + std::to_string(size) + " bytes, but a loadable segment ends at byte " +
             std::to_string(ph.p_offset + ph.p_filesz);
  }
  return "";
}

}  // namespace

std::shared_ptr<PluginLibrary> PluginLibrary::open(const std::filesystem::path& file,
                                                   std::string* error) {
  std::string first_bytes;
  if (!starts_like_elf(file, &first_bytes)) {
    *error = "not an ELF shared library (expected bytes 7f 45 4c 46, found " + first_bytes + ")";
    return nullptr;
  }
  if (std::string problem = check_elf_complete(file); !problem.empty()) {
    *error = problem;
    return nullptr;
  }
  static std::atomic<unsigned> copy_counter{0};
  std::error_code ec;
  const auto dir = private_copy_dir();
  std::filesystem::create_directories(dir, ec);
  const auto copy = dir / (std::to_string(copy_counter++) + "-" + file.filename().string());
  if (ec || !std::filesystem::copy_file(file, copy,
                                        std::filesystem::copy_options::overwrite_existing, ec)) {
    *error = "cannot make a private copy in " + dir.string() + ": " + ec.message();
    return nullptr;
  }
  void* handle = dlopen(copy.c_str(), RTLD_NOW | RTLD_LOCAL);
  const char* dl_error = handle ? nullptr : dlerror();
  std::filesystem::remove(copy, ec);  // the mapping stays valid without the file
  if (!handle) {
    *error = std::string("dlopen failed: ") + (dl_error ? dl_error : "unknown error");
    return nullptr;
  }
  return std::shared_ptr<PluginLibrary>(new PluginLibrary(handle));
}

PluginLibrary::~PluginLibrary() {
  dlclose(handle_);
}

const void* PluginLibrary::symbol(const char* name) const {
  dlerror();
  return dlsym(handle_, name);
}

}  // namespace fr
