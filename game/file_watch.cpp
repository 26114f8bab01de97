#include "game/file_watch.h"

#include <sys/stat.h>

namespace p3d::game {

FileWatch::FileWatch(std::vector<std::filesystem::path> files) : files_(std::move(files)) { rebase(); }

void FileWatch::rebase() {
  baseline_ = look();
  has_pending_ = false;
}

// stat() rather than std::filesystem: an editor's rename over the file changes the
// inode and not always the time or size, and one call gives all three.
std::vector<FileWatch::Signature> FileWatch::look() const {
  std::vector<Signature> out(files_.size());
  for (size_t i = 0; i < files_.size(); ++i) {
    struct stat st {};
    if (::stat(files_[i].c_str(), &st) != 0) continue;
    out[i] = {true, int64_t(st.st_mtim.tv_sec) * 1000000000 + st.st_mtim.tv_nsec, uintmax_t(st.st_size),
              uintmax_t(st.st_ino)};
  }
  return out;
}

bool FileWatch::changed(double now) {
  if (now - last_poll_ < kPollSeconds) return false;
  last_poll_ = now;
  std::vector<Signature> seen = look();
  if (!has_pending_ || seen != pending_) {  // a first change, or still being written
    has_pending_ = seen != baseline_;
    pending_ = std::move(seen);
    pending_since_ = now;
    return false;
  }
  for (const Signature& s : pending_)
    if (!s.exists) return false;  // renamed away for the moment: wait for it to come back
  if (now - pending_since_ < kSettleSeconds) return false;
  baseline_ = pending_;
  has_pending_ = false;
  return true;
}

}  // namespace p3d::game
