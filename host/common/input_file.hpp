#pragma once
// Every file the program reads is opened here, so each refuses the same
// things in the same words: anything but a regular file (a FIFO could block
// for ever, /dev/urandom never ends), a missing or unreadable file, and a
// file over the size its kind may have. Errors are UserError("LABEL: why").
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace meshparticles {

// 1 GiB: far above any particle file, list, tuning file or report.
inline constexpr std::size_t kMaxTextFileBytes = std::size_t(1) << 30;

// An open, regular, readable file; closed when it goes.
class InputFile {
 public:
  // `what` names the kind in "is a directory, not a WHAT".
  InputFile(const std::filesystem::path& file, const std::string& label, const std::string& what = "file");
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  // Its size when opened.
  std::uint64_t size() const { return size_; }
  // Up to `count` bytes; 0 at the end.
  std::size_t read(char* into, std::size_t count);
  // The rest of the file (it may have shrunk since it was opened).
  std::vector<char> read_all();

 private:
  int descriptor_ = -1;
  std::uint64_t size_ = 0;
  std::string label_;
};

// The whole file, refused beyond `max_bytes`.
std::vector<char> read_input_file(const std::filesystem::path& file, const std::string& label, std::size_t max_bytes,
                                  const std::string& what = "file");
std::string read_input_text(const std::filesystem::path& file, const std::string& label,
                            const std::string& what = "file", std::size_t max_bytes = kMaxTextFileBytes);

}  // namespace meshparticles
