#pragma once

// Running probecycle-cli as a user runs it, for the CLI's tests: a
// subprocess, its stdout, stderr and exit status, in a folder of its own.
// Every CLI test runs it through run() below.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

extern char** environ;  // the test's environment, passed on to the CLI

namespace probecycle::cli_test {

namespace fs = std::filesystem;

struct CliRun {
    bool exited{false};  // ended by exit(), not by a signal
    int exit_code{-1};
    int signal{0};
    std::string out;
    std::string err;
};

inline std::ostream& operator<<(std::ostream& os, const CliRun& run) {
    return os << "exit " << run.exit_code << " signal " << run.signal << "\n--- stdout\n"
              << run.out << "--- stderr\n"
              << run.err;
}

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

// probecycle-cli with `arguments` (already quoted where needed), through the
// shell: for redirections and pipes of the test's own.
inline CliRun run(const std::string& arguments) {
    const TempDir capture;
    const fs::path out = capture / "stdout";
    const fs::path err = capture / "stderr";
    const std::string command = quote(PROBECYCLE_CLI_PATH) + " " + arguments + " >" +
                                quote(out.string()) + " 2>" + quote(err.string());
    const int status = std::system(command.c_str());
    CliRun result;
    result.exited = WIFEXITED(status);
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
    result.out = read(out);
    result.err = read(err);
    return result;
}

// probecycle-cli with `args` as its words, no shell, stdin from /dev/null.
inline CliRun run(const std::vector<std::string>& args) {
    const TempDir capture;
    const std::string out_path = (capture / "stdout").string();
    const std::string err_path = (capture / "stderr").string();
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
    posix_spawn_file_actions_addopen(&actions, 2, err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
    const std::string cli = PROBECYCLE_CLI_PATH;
    std::vector<std::string> argv_storage = {cli};
    argv_storage.insert(argv_storage.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& arg : argv_storage) argv.push_back(arg.data());
    argv.push_back(nullptr);
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, cli.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    CliRun result;
    if (spawned != 0) {
        ADD_FAILURE() << "cannot start " << cli;
        return result;
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0) {
    }
    if (WIFEXITED(status)) {
        result.exited = true;
        result.exit_code = WEXITSTATUS(status);
    } else if (WIFSIGNALED(status)) {
        result.signal = WTERMSIG(status);
    }
    result.out = read(out_path);
    result.err = read(err_path);
    return result;
}

}  // namespace probecycle::cli_test
