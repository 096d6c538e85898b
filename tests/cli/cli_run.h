#pragma once

// Running probecycle-cli as a user runs it, for the CLI's tests: a
// subprocess, its stdout, stderr and exit status, in a folder of its own.
// (cli_test.cpp and lab_cli_test.cpp still carry their own copies.)

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

namespace probecycle::cli_test {

namespace fs = std::filesystem;

struct CliRun {
    int exit_code{-1};
    std::string out;
    std::string err;
};

inline std::string quote(const std::string& text) {
    std::string quoted = "'";
    for (const char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

inline std::string read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

inline void write(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

inline std::string data(const std::string& name) {
    return std::string(PROBECYCLE_TEST_DATA_DIR) + "/" + name;
}

// A folder of its own per test, removed afterwards: ctest runs in parallel.
class TempDir {
  public:
    TempDir() {
        std::random_device seed;
        std::string name = testing::UnitTest::GetInstance()->current_test_info()->name();
        std::replace(name.begin(), name.end(), '/', '_');
        path_ =
            fs::temp_directory_path() / ("probecycle_cli_" + name + "_" + std::to_string(seed()));
        fs::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ignored;
        fs::remove_all(path_, ignored);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const fs::path& path() const { return path_; }
    fs::path operator/(const std::string& name) const { return path_ / name; }

  private:
    fs::path path_;
};

// probecycle-cli with `arguments` (already quoted where needed).
inline CliRun run(const std::string& arguments) {
    const TempDir capture;
    const fs::path out = capture / "stdout";
    const fs::path err = capture / "stderr";
    const std::string command = quote(PROBECYCLE_CLI_PATH) + " " + arguments + " >" +
                                quote(out.string()) + " 2>" + quote(err.string());
    const int status = std::system(command.c_str());
    CliRun result;
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = read(out);
    result.err = read(err);
    return result;
}

}  // namespace probecycle::cli_test
