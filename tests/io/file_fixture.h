// The fixture of the file tests (file_test.cpp, file_posix_test.cpp): a fresh folder per test.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "hedge/io/io.h"

namespace hedge::test {

// A fresh folder per test, removed afterwards.
class FileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::random_device rd;
    dir_ = std::filesystem::temp_directory_path() /
           ("hedge_io_test_" + std::to_string(rd()) + std::to_string(rd()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    std::filesystem::permissions(dir_, std::filesystem::perms::owner_all, std::filesystem::perm_options::add,
                                 ec);
    std::filesystem::remove_all(dir_, ec);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::vector<std::string> listing() const {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(dir_))
      names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
  static void put(const std::string& p, const std::string& bytes) {
    std::ofstream(p, std::ios::binary) << bytes;
  }
  //! Writing over a file `name` that has the permissions `perms` replaces its bytes and keeps them.
  void expect_replaced_keeping(const std::string& name, std::filesystem::perms perms) const {
    put(path(name), "old");
    std::filesystem::permissions(path(name), perms);
    write_file_atomic(path(name), "new");
    EXPECT_EQ(read_file(path(name)), "new");
    EXPECT_EQ(std::filesystem::status(path(name)).permissions() & std::filesystem::perms::all, perms);
  }

  std::filesystem::path dir_;
};

}  // namespace hedge::test
