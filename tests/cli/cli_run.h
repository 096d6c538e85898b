#pragma once

// Running probecycle-cli as a user runs it, for the CLI's tests: a
// subprocess, its stdout, stderr and exit status, in a folder of its own.
// Every CLI test runs it through run() below.

#include <gtest/gtest.h>

#ifdef _WIN32
#ifndef WIN32_LEAN_AND_MEAN
#define WIN32_LEAN_AND_MEAN
#endif
#include <windows.h>
#else
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>
#endif

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#ifndef _WIN32
extern char** environ;  // the test's environment, passed on to the CLI
#endif

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

// Sets an environment variable of the test, which the CLI inherits, or
// removes it for nullptr.
inline void set_env(const char* name, const char* value) {
#ifdef _WIN32
    _putenv_s(name, value != nullptr ? value : "");  // "" removes it
#else
    if (value != nullptr) {
        ::setenv(name, value, 1);
    } else {
        ::unsetenv(name);
    }
#endif
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

#ifdef _WIN32
// Windows: no POSIX shell. The words of `arguments` are split as a POSIX
// shell splits them ('...' and "..." quoting; quote() above), and the CLI
// started with them as run(args) starts it. A redirection other than the
// "</dev/null" that run(args) gives anyway is refused: such a test is POSIX's.
inline std::vector<std::string> shell_words(const std::string& text) {
    std::vector<std::string> words;
    std::string word;
    bool in_word = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == ' ' || c == '\t' || c == '\n') {
            if (in_word) words.push_back(word);
            word.clear();
            in_word = false;
        } else if (c == '\'') {
            const std::size_t end = std::min(text.find('\'', i + 1), text.size());
            word += text.substr(i + 1, end - i - 1);
            i = end;
            in_word = true;
        } else if (c == '"') {
            for (++i; i < text.size() && text[i] != '"'; ++i) {
                if (text[i] == '\\' && i + 1 < text.size() && text[i + 1] == '"') ++i;
                word += text[i];
            }
            in_word = true;
        } else {
            word += c;
            in_word = true;
        }
    }
    if (in_word) words.push_back(word);
    return words;
}

inline std::wstring wide(const std::string& utf8) {
    if (utf8.empty()) return {};
    const int n =
        ::MultiByteToWideChar(CP_UTF8, 0, utf8.data(), static_cast<int>(utf8.size()), nullptr, 0);
    std::wstring text(static_cast<std::size_t>(n), L'\0');
    ::MultiByteToWideChar(CP_UTF8, 0, utf8.data(), static_cast<int>(utf8.size()), text.data(), n);
    return text;
}

// One word of a Windows command line, as CommandLineToArgvW and the C
// runtime read it back: quoted, a quote escaped, and the backslashes before a
// quote doubled.
inline std::wstring command_line_word(const std::wstring& word) {
    std::wstring quoted = L"\"";
    std::size_t backslashes = 0;
    for (const wchar_t c : word) {
        if (c == L'\\') {
            ++backslashes;
            continue;
        }
        quoted.append(c == L'"' ? 2 * backslashes + 1 : backslashes, L'\\');
        backslashes = 0;
        quoted += c;
    }
    quoted.append(2 * backslashes, L'\\');
    return quoted + L"\"";
}

inline CliRun run(const std::vector<std::string>& args) {
    const TempDir capture;
    SECURITY_ATTRIBUTES inherit{sizeof(SECURITY_ATTRIBUTES), nullptr, TRUE};
    const auto open = [&](const fs::path& path, DWORD access, DWORD disposition) {
        return ::CreateFileW(path.c_str(), access, FILE_SHARE_READ | FILE_SHARE_WRITE, &inherit,
                             disposition, FILE_ATTRIBUTE_NORMAL, nullptr);
    };
    HANDLE in = open(L"NUL", GENERIC_READ, OPEN_EXISTING);
    HANDLE out = open(capture / "stdout", GENERIC_WRITE, CREATE_ALWAYS);
    HANDLE err = open(capture / "stderr", GENERIC_WRITE, CREATE_ALWAYS);
    const std::wstring cli = wide(PROBECYCLE_CLI_PATH);
    std::wstring line = command_line_word(cli);
    for (const std::string& arg : args) line += L" " + command_line_word(wide(arg));
    STARTUPINFOW startup{};
    startup.cb = sizeof startup;
    startup.dwFlags = STARTF_USESTDHANDLES;
    startup.hStdInput = in;
    startup.hStdOutput = out;
    startup.hStdError = err;
    PROCESS_INFORMATION process{};
    const BOOL started = ::CreateProcessW(cli.c_str(), line.data(), nullptr, nullptr, TRUE, 0,
                                          nullptr, nullptr, &startup, &process);
    CliRun result;
    if (started != 0) {
        ::WaitForSingleObject(process.hProcess, INFINITE);
        DWORD code = 0;
        ::GetExitCodeProcess(process.hProcess, &code);
        result.exited = true;
        result.exit_code = static_cast<int>(code);
        ::CloseHandle(process.hProcess);
        ::CloseHandle(process.hThread);
    } else {
        ADD_FAILURE() << "cannot start " << PROBECYCLE_CLI_PATH;
    }
    for (HANDLE h : {in, out, err}) ::CloseHandle(h);
    result.out = read(capture / "stdout");
    result.err = read(capture / "stderr");
    return result;
}

inline CliRun run(const std::string& arguments) {
    std::vector<std::string> words = shell_words(arguments);
    for (std::size_t i = 0; i < words.size(); ++i) {
        if (words[i] == "</dev/null" ||
            (words[i] == "<" && i + 1 < words.size() && words[i + 1] == "/dev/null")) {
            words.erase(
                words.begin() + static_cast<std::ptrdiff_t>(i),
                words.begin() + static_cast<std::ptrdiff_t>(words[i] == "<" ? i + 2 : i + 1));
            --i;
        } else if (words[i].find_first_of("<>|") == 0) {
            ADD_FAILURE() << "a POSIX shell's redirection in a test run on Windows: " << arguments;
            return {};
        }
    }
    return run(words);
}
#else
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

#endif

}  // namespace probecycle::cli_test
