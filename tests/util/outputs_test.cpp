// Outputs: all or nothing, with files written at once (write_now) or at commit alike.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <vector>

#include "engine/util/error.h"
#include "engine/util/file.h"

namespace p3d {
namespace {

class OutputsFixture : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("p3d-outputs-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& entry : std::filesystem::directory_iterator(dir_)) out.push_back(entry.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
  }
  std::filesystem::path dir_;
};

const std::vector<uint8_t> kBytes = {1, 2, 3};

TEST_F(OutputsFixture, WrittenNowAppearOnlyAtCommit) {
  {
    Outputs outputs;
    outputs.write_now(dir_ / "a.png", kBytes);
    outputs.add(dir_ / "b.csv", std::string("x\n"));
    EXPECT_EQ(names().size(), 1u) << "a's temporary only";
    outputs.commit();
  }
  EXPECT_EQ(names(), (std::vector<std::string>{"a.png", "b.csv"}));
  EXPECT_EQ(std::filesystem::file_size(dir_ / "a.png"), kBytes.size());
}

TEST_F(OutputsFixture, NothingIsLeftWithoutCommit) {
  {
    Outputs outputs;
    outputs.write_now(dir_ / "a.png", kBytes);
    outputs.write_now(dir_ / "b.png", kBytes);
  }  // an error before commit: the command's outputs go with it
  EXPECT_TRUE(names().empty());
}

TEST_F(OutputsFixture, AFailedCommitLeavesNothing) {
  std::filesystem::create_directory(dir_ / "taken.json");
  {
    Outputs outputs;
    outputs.write_now(dir_ / "a.png", kBytes);
    outputs.add(dir_ / "taken.json", std::string("{}"));
    EXPECT_THROW(outputs.commit(), Error);
  }
  EXPECT_EQ(names(), (std::vector<std::string>{"taken.json"}));
  EXPECT_TRUE(std::filesystem::is_directory(dir_ / "taken.json"));
}

}  // namespace
}  // namespace p3d
