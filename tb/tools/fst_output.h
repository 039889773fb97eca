// An FST waveform being written for the user (the RTL's, the model's):
// written as "<path>.part" and renamed to <path> only when it is whole, so a
// full disk or a file-size limit leaves no truncated waveform behind and is
// reported as one line naming the flag. The GTKWave writer maps temporary
// files into memory: a write that fails there raises SIGBUS, which is caught
// while an FST is open (the partial files are removed, exit 2).
#pragma once

#include <cstdint>
#include <string>

namespace sc {

// Clocks an FST records when no --fst-to is given: 200,000 clocks (10 ms at
// 20 MHz, about 16 MB for sc_axis_core). A whole paper group would be tens
// of GB.
inline constexpr uint64_t kDefaultFstWindow = 200'000;

class FstOutput {
 public:
  // `param` names the flag in messages ("fst"). Checks the path
  // (input::output_path) and throws input::Error when it cannot be written.
  FstOutput(std::string param, std::string path);
  ~FstOutput();  // removes the .part file unless committed
  FstOutput(const FstOutput&) = delete;
  FstOutput& operator=(const FstOutput&) = delete;

  const std::string& part_path() const { return part_; }
  // The writer could not create the .part file: throws input::Error.
  void creation_failed() const;
  // After the writer closed the .part file: checks it is a whole FST file
  // and renames it to the path; throws input::Error (and removes the .part)
  // when it is not.
  void commit();

 private:
  std::string param_, path_, part_;
  int slot_ = -1;
  bool committed_ = false;
};

// Why the file at `path` is not a whole FST file (its blocks must tile the
// file and include the geometry and hierarchy written at close), or "".
std::string fst_incomplete_reason(const std::string& path);

}  // namespace sc
