#include "io/atomic_file.hpp"

#include "platform/interrupt.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstring>

namespace fr {
namespace {

// Temporary files being written now, for the signal handler: fixed slots, since the handler may
// only touch memory that is always valid and call async-signal-safe functions (remove_file_now).
constexpr int kTempSlots = 16;
constexpr size_t kTempPathMax = 4096;
char g_temp_paths[kTempSlots][kTempPathMax];
// 0: free, 1: being filled, 2: holds a path the handler may remove.
std::atomic<int> g_temp_state[kTempSlots];

// A slot holding `path`, or -1 when all are taken (then a signal may leave this one file).
int register_temp(const std::string& path) {
  if (path.size() >= kTempPathMax) return -1;
  for (int i = 0; i < kTempSlots; ++i) {
    int expected = 0;
    if (!g_temp_state[i].compare_exchange_strong(expected, 1)) continue;
    std::memcpy(g_temp_paths[i], path.c_str(), path.size() + 1);
    g_temp_state[i] = 2;
    return i;
  }
  return -1;
}

void unregister_temp(int slot) {
  if (slot >= 0) g_temp_state[slot] = 0;
}

// The line the handler writes before the process ends (set_signal_note): two buffers, so that a
// note being written never is the one the handler reads.
constexpr size_t kNoteMax = 1024;
char g_notes[2][kNoteMax];
std::atomic<int> g_note_current{-1};

// The last words before an interrupt ends the process (platform/interrupt.hpp): the note, then
// no temporary file left.
void say_note_and_remove_temps() {
  const int note = g_note_current.load();
  if (note >= 0) write_stderr_now(g_notes[note]);
  remove_temp_files();
}

// Bits for temporary file names: not secret, only unlikely to repeat.
uint32_t random_bits() {
  static std::atomic<uint32_t> counter{0};
  const auto now = std::chrono::steady_clock::now().time_since_epoch().count();
  return static_cast<uint32_t>(now) * 2654435761u + counter.fetch_add(0x9e3779b9u);
}

const char* kind_name(PathKind kind) {
  switch (kind) {
    case PathKind::Folder:
      return "is a folder, not a file";
    case PathKind::BlockDevice:
      return "is a block device (a disk), which fractalis never writes to";
    case PathKind::Socket:
      return "is a socket";
    default:
      return nullptr;
  }
}

}  // namespace

std::string output_problem(const std::filesystem::path& path) {
  const PathInfo info = examine_path(path);
  if (info.kind == PathKind::Missing && info.error.empty()) return "";  // a new file
  if (info.kind == PathKind::Missing)
    return info.is_link ? "is a symlink to nothing (" + info.error + ")" : info.error;
  if (const char* problem = kind_name(info.kind))
    return info.is_link ? std::string("is a symlink to what ") + problem : problem;
  return "";
}

bool is_standard_output(const std::filesystem::path& path) {
  return is_standard_output_path(path);
}

std::unique_ptr<OutputFile> OutputFile::open(const std::filesystem::path& path,
                                             std::string* error) {
  if (const std::string problem = output_problem(path); !problem.empty()) {
    *error = "cannot write " + path.string() + ": it " + problem;
    return nullptr;
  }
  std::unique_ptr<OutputFile> out(new OutputFile());
  out->path_ = out->real_ = path;
  const PathInfo info = examine_path(path);
  if (info.kind != PathKind::Missing) {
    if (info.kind == PathKind::CharacterDevice || info.kind == PathKind::Pipe) {
      // Written through: no temporary file, nothing replaced.
      std::string why;
      out->file_ = WritableFile::open_existing(path, &why);
      if (!out->file_.valid()) {
        *error = "cannot write " + path.string() + ": " + why;
        return nullptr;
      }
      return out;
    }
    out->mode_ = info.mode;
    if (info.is_link) {
      std::error_code ec;
      out->real_ = std::filesystem::canonical(path, ec);  // the link's target is replaced
      if (ec) {
        *error = "cannot write " + path.string() + ": " + ec.message();
        return nullptr;
      }
    }
  } else {
    out->mode_ = new_file_mode();
  }
  const std::filesystem::path dir = out->real_.has_parent_path() ? out->real_.parent_path() : ".";
  // The temporary file's name is registered for the signal handler before the file exists: a
  // signal may be delivered to any thread, so blocking it in this one would not close the gap
  // between creating the file and registering it. (Removing a name not yet created is harmless;
  // the process id in the name keeps it from being another process's file.)
  std::string create_error;
  for (int attempt = 0; attempt < 100 && !out->file_.valid(); ++attempt) {
    char suffix[48];
    std::snprintf(suffix, sizeof suffix, ".%llu.%08x",
                  static_cast<unsigned long long>(current_process_id()),
                  static_cast<unsigned>(random_bits()));
    std::string hidden = out->real_.filename().string();  // appended: GCC 12's -Wrestrict
    hidden.insert(hidden.begin(), '.');                   // misfires on "." + string
    hidden += suffix;
    out->temp_ = (dir / hidden).string();
    out->slot_ = register_temp(out->temp_);
    bool exists = false;
    out->file_ = WritableFile::create_new(out->temp_, &exists, &create_error);
    if (!out->file_.valid()) {
      unregister_temp(out->slot_);
      out->slot_ = -1;
      if (!exists) break;
    }
  }
  if (!out->file_.valid()) {
    *error = "cannot write " + path.string() + ": cannot create a temporary file in " +
             dir.string() + ": " + create_error;
    out->temp_.clear();
    return nullptr;
  }
  return out;
}

bool OutputFile::write(std::string_view bytes, std::string* error) {
  std::string why;
  if (file_.write_all(bytes, &why)) {
    position_ += bytes.size();
    return true;
  }
  *error = "cannot write " + path_.string() + ": write failed: " + why;
  return false;
}

bool OutputFile::seek(uint64_t offset, std::string* error) {
  std::string why = "this format must seek, and a pipe or device cannot";
  if (seekable() && file_.seek(offset, &why)) {
    position_ = offset;
    return true;
  }
  *error = "cannot write " + path_.string() + ": " + (seekable() ? "seek failed: " + why : why);
  return false;
}

bool OutputFile::commit(std::string* error) {
  std::string why;
  auto fail = [&](const char* what) {
    *error = "cannot write " + path_.string() + ": " + what + ": " + why;
    return false;
  };
  if (temp_.empty()) {  // written through
    done_ = true;
    return file_.close(&why) || fail("close failed");
  }
  if (!file_.set_mode(mode_, &why)) return fail("chmod failed");
  if (!file_.flush_to_disk(&why)) return fail("fsync failed");
  if (!file_.close(&why)) return fail("close failed");
  if (!replace_file(temp_, real_, &why)) return fail("rename failed");
  unregister_temp(slot_);
  done_ = true;
  return true;
}

OutputFile::~OutputFile() {
  file_ = WritableFile();  // closed before it is removed (Windows cannot remove an open file)
  if (!done_ && !temp_.empty()) {
    remove_file_now(temp_.c_str());
    unregister_temp(slot_);
  }
}

bool write_file_atomic(const std::filesystem::path& path, std::string_view bytes,
                       std::string* error) {
  auto out = OutputFile::open(path, error);
  return out && out->write(bytes, error) && out->commit(error);
}

void remove_temp_files() {
  for (int i = 0; i < kTempSlots; ++i)
    if (g_temp_state[i].load() == 2) remove_file_now(g_temp_paths[i]);
}

void set_signal_note(std::string_view note) {
  if (note.empty()) {
    g_note_current = -1;
    return;
  }
  const int next = g_note_current.load() == 0 ? 1 : 0;
  const size_t n = std::min(note.size(), kNoteMax - 2);
  std::memcpy(g_notes[next], note.data(), n);
  g_notes[next][n] = '\n';
  g_notes[next][n + 1] = '\0';
  g_note_current = next;
}

void install_temp_file_cleanup() {
  on_termination_request(say_note_and_remove_temps);
}

}  // namespace fr
