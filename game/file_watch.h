// Watches the files a level is read from and says when an editor has finished
// saving them. Editors write in place or rename a new file over the old one, and a
// file may be missing or half written for a moment: a change counts once every file
// exists and has looked the same (time, size, inode) for a settling period.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace p3d::game {

class FileWatch {
 public:
  static constexpr double kPollSeconds = 0.25;   // how often the files are looked at
  static constexpr double kSettleSeconds = 0.4;  // how long a change must stay put

  FileWatch() = default;
  explicit FileWatch(std::vector<std::filesystem::path> files);

  // Called as often as wanted with a monotonic clock; true once per finished save.
  bool changed(double now_seconds);
  // The files as they are now become the baseline (after a reload read them).
  void rebase();

 private:
  struct Signature {
    bool exists = false;
    int64_t time = 0;
    uintmax_t size = 0, inode = 0;
    bool operator==(const Signature&) const = default;
  };
  std::vector<Signature> look() const;

  std::vector<std::filesystem::path> files_;
  std::vector<Signature> baseline_, pending_;
  double last_poll_ = -1e300, pending_since_ = 0;
  bool has_pending_ = false;
};

}  // namespace p3d::game
