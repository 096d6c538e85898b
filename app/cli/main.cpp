// probecycle-cli: the probing-cycle model on the command line. The commands
// are registered by their groups (commands_*.cpp); CLI11 parses, checks the
// options and writes --help. Exit 0 on success, 2 with the message on stderr.

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <exception>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#ifdef _WIN32
#ifndef WIN32_LEAN_AND_MEAN
#define WIN32_LEAN_AND_MEAN
#endif
#include <windows.h>
// After windows.h, which it needs:
#include <fcntl.h>
#include <io.h>
#include <shellapi.h>
#else
#include <fcntl.h>
#include <unistd.h>
#endif

#include "app/cli/cli_options.h"
#include "app/cli/commands.h"
#include "core/cycle/scenario.h"

namespace {

using probecycle::cli::UsageError;

constexpr const char* kFooter =
    "Exit status: 0 on success, 2 on bad input or usage (the message is on stderr).\n"
    "'probecycle-cli COMMAND --help' describes a command and its options.";

// The words a command or command group allows after it, for a message that
// says what is allowed (CLI11 says only what was not expected).
std::vector<std::string> subcommand_names(const CLI::App& app) {
    std::vector<std::string> names;
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
        names.push_back(sub->get_name());
    }
    return names;
}

std::string joined(const std::vector<std::string>& words) {
    std::string out;
    for (const std::string& w : words) out += (out.empty() ? "" : ", ") + w;
    return out;
}

bool is_one_of(const std::string& word, const std::vector<std::string>& words) {
    return std::find(words.begin(), words.end(), word) != words.end();
}

// CLI11's messages, in this program's words where they differ.
std::string failure_text(const CLI::Error& e) {
    std::string text = e.what();
    const std::string required = " is required";
    if (dynamic_cast<const CLI::RequiredError*>(&e) != nullptr && text.size() > required.size() &&
        text.compare(text.size() - required.size(), required.size(), required) == 0) {
        const std::string name = text.substr(0, text.size() - required.size());
        return name.rfind("--", 0) == 0 ? "missing required option " + name
                                        : "missing the input file (" + name + ")";
    }
    return text;
}

// The words after the program's name, as UTF-8. On Windows argv is in the
// system's code page, where a Chinese or Russian path is lost: the words are
// taken from the wide command line instead (CommandLineToArgvW, Microsoft's
// Win32 reference), parsed by the same rules as the C runtime's argv.
std::vector<std::string> arguments(int argc, char** argv) {
#ifdef _WIN32
    int count = 0;
    wchar_t** wide = ::CommandLineToArgvW(::GetCommandLineW(), &count);
    if (wide != nullptr) {
        std::vector<std::string> words;
        for (int i = 1; i < count; ++i) {
            const int bytes =
                ::WideCharToMultiByte(CP_UTF8, 0, wide[i], -1, nullptr, 0, nullptr, nullptr);
            std::string word(static_cast<std::size_t>(bytes > 0 ? bytes - 1 : 0), '\0');
            if (bytes > 1) {
                ::WideCharToMultiByte(CP_UTF8, 0, wide[i], -1, word.data(), bytes, nullptr,
                                      nullptr);
            }
            words.push_back(std::move(word));
        }
        ::LocalFree(wide);
        return words;
    }
#endif
    return {argv + 1, argv + argc};
}

// On Windows: standard output and error carry the bytes as written, "\n"
// line ends as on Linux (text mode would make every one "\r\n", and a
// report piped to a file would differ from the one --out writes); the
// console shows UTF-8 as UTF-8.
void binary_standard_streams() {
#ifdef _WIN32
    _setmode(_fileno(stdout), _O_BINARY);
    _setmode(_fileno(stderr), _O_BINARY);
    ::SetConsoleOutputCP(CP_UTF8);
#endif
}

int run(int argc, char** argv) {
    using namespace probecycle;
    CLI::App app(
        "probecycle-cli: cycle time, overtravel and uncertainty of touch-trigger probing "
        "cycles on CNC machine tools, and the calibration and latency lab.",
        "probecycle-cli");
    // On Windows CLI11 takes a word starting with '/' as an option ("/o";
    // allow_windows_style_options_ is true there, CLI11 2.1's App.hpp); a
    // path such as "/data/ring.csv" is a path there too.
    app.allow_windows_style_options(false);
    app.get_formatter()->label("Usage", "usage");
    app.get_formatter()->column_width(34);
    app.footer(kFooter);
    // The window's and the package's version string (CMakeLists.txt's project()).
    app.set_version_flag("--version", "ProbeCycle " PROBECYCLE_VERSION,
                         "Print the version (the package's) and exit");
    app.require_subcommand(1);
    cli::add_cycle_commands(app);
    cli::add_optimise_commands(app);
    cli::add_calibrate_commands(app);
    cli::add_latency_commands(app);
    cli::add_compare_commands(app);
    cli::add_program_commands(app);
    cli::add_machine_commands(app);

    std::vector<std::string> args = arguments(argc, argv);
    if (args.empty()) {
        std::cerr << app.help();
        return 2;
    }
    // "help" as a command word asks for the help of what stands before it.
    for (std::size_t i = 0; i < args.size() && i < 2; ++i) {
        if (args[i] == "help") args[i] = "--help";
    }
    // An unknown command or verb: say which are allowed.
    const std::string command = args[0];  // a copy: CLI11 consumes args
    const std::vector<std::string> commands = subcommand_names(app);
    if (command.rfind('-', 0) != 0 && !is_one_of(command, commands)) {
        std::cerr << "probecycle-cli: unknown command '" << command
                  << "'; allowed: " << joined(commands) << '\n';
        return 2;
    }
    if (command == "calibrate" || command == "latency" || command == "compare" ||
        command == "program" || command == "machine") {
        const std::vector<std::string> verbs = subcommand_names(*app.get_subcommand(command));
        if (args.size() == 1) {
            std::cerr << "probecycle-cli " << command
                      << ": missing what to do; allowed: " << joined(verbs) << '\n';
            return 2;
        }
        if (args[1].rfind('-', 0) != 0 && !is_one_of(args[1], verbs)) {
            std::cerr << "probecycle-cli " << command << ": unknown "
                      << (command == "calibrate" ? "calibration"
                          : command == "latency" ? "latency command"
                          : command == "program" ? "program"
                          : command == "machine" ? "control"
                                                 : "comparison command")
                      << " '" << args[1] << "'; allowed: " << joined(verbs) << '\n';
            return 2;
        }
    }
    std::reverse(args.begin(), args.end());  // CLI11 takes them last first
    try {
        app.parse(args);
        return 0;
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);  // the help on stdout, exit 0
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);  // the version on stdout, exit 0
    } catch (const CLI::ParseError& e) {
        std::cerr << "probecycle-cli " << command << ": " << failure_text(e) << '\n';
    } catch (const ScenarioError& e) {
        std::cerr << "probecycle-cli: invalid scenario:\n" << e.what() << '\n';
    } catch (const std::exception& e) {
        std::cerr << "probecycle-cli " << command << ": " << e.what() << '\n';
    }
    return 2;
}

// A standard stream the caller closed (`>&-`) stays closed: /dev/null opened
// read-only takes its number, so writing to it fails and reports an error
// instead of a file this program opens later taking the number and
// receiving the output.
void hold_closed_standard_streams() {
#ifndef _WIN32
    for (const int fd : {STDIN_FILENO, STDOUT_FILENO, STDERR_FILENO}) {
        if (fcntl(fd, F_GETFD) == -1 && errno == EBADF) {
            const int held = open("/dev/null", O_RDONLY);
            if (held != -1 && held != fd) close(held);  // a lower number was free: not ours
        }
    }
#endif
}

// The output is complete only once standard output took all of it: print()
// reports a failed write at once; flushing catches what was still buffered.
// False after saying so on stderr.
bool standard_output_written() {
    try {
        probecycle::cli::flush_output();
    } catch (const std::exception& e) {
        std::cerr << "probecycle-cli: " << e.what() << '\n';
        return false;
    }
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    hold_closed_standard_streams();
    binary_standard_streams();
    int status = 2;
    try {
        status = run(argc, argv);
    } catch (const std::exception& e) {  // e.g. out of memory while setting up
        std::cerr << "probecycle-cli: " << e.what() << '\n';
    } catch (...) {
        std::cerr << "probecycle-cli: an unexpected error\n";
    }
    // Once: a failed print() was reported by its command's message.
    if (status == 0 && !standard_output_written()) status = 2;
    return status;
}
