// The fixture of the CLI tests: runs the built hedge tool as a user would, with stdout and stderr
// captured, in a temporary folder of its own per test.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace cli_test {

namespace fs = std::filesystem;
using nlohmann::json;

inline const std::string kData = HEDGE_DATA_DIR;

inline std::string data(const std::string& name) { return kData + "/" + name; }

struct Result {
  int code = -1;
  std::string out;
  std::string err;
};

inline std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline void write_text(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

inline std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) {
    if (c == '\'') {
      q += "'\\''";
    } else {
      q += c;
    }
  }
  return q + "'";
}

inline std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> result;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) result.push_back(line);
  return result;
}

class HedgeCli : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("hedge_cli_test_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path tmp(const std::string& name) const { return dir_ / name; }

  //! Runs hedge with `args`; stdout and stderr are captured separately, stdin is empty.
  Result run(const std::vector<std::string>& args) const {
    std::string command = shell_quote(HEDGE_CLI_PATH);
    for (const std::string& a : args) command += " " + shell_quote(a);
    const fs::path out = tmp("stdout.txt"), err = tmp("stderr.txt");
    command += " </dev/null >" + shell_quote(out.string()) + " 2>" + shell_quote(err.string());
    const int status = std::system(command.c_str());
    Result r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = read_text(out);
    r.err = read_text(err);
    return r;
  }

  json run_json(const std::vector<std::string>& args) const {
    const Result r = run(args);
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(json::accept(r.out)) << r.out;
    return json::accept(r.out) ? json::parse(r.out) : json::object();
  }

  //! A data error: exit 1 and exactly one "hedge: error: ..." line on stderr that names `file`.
  void expect_data_error(const std::vector<std::string>& args, const std::string& file) const {
    const Result r = run(args);
    EXPECT_EQ(r.code, 1);
    const auto err = lines(r.err);
    ASSERT_EQ(err.size(), 1u) << r.err;
    EXPECT_EQ(err[0].rfind("hedge: error: ", 0), 0u) << err[0];
    EXPECT_NE(err[0].find(file), std::string::npos) << err[0];
  }

  //! A usage error: exit 2 and exactly one "hedge: error: ..." line on stderr.
  void expect_usage_error(const std::vector<std::string>& args) const {
    const Result r = run(args);
    EXPECT_EQ(r.code, 2);
    const auto err = lines(r.err);
    ASSERT_EQ(err.size(), 1u) << r.err;
    EXPECT_EQ(err[0].rfind("hedge: error: ", 0), 0u) << err[0];
  }

  fs::path dir_;
};

}  // namespace cli_test
