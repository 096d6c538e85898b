#include "core/common/file_io.h"

#include <gtest/gtest.h>

#ifndef _WIN32
#include <sys/stat.h>
#endif

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

namespace probecycle {
namespace {

namespace fs = std::filesystem;

class FileIoTest : public ::testing::Test {
  protected:
    void SetUp() override {
        std::random_device seed;
        dir_ = fs::temp_directory_path() / ("probecycle-file-io-" + std::to_string(seed()));
        ASSERT_TRUE(fs::create_directory(dir_)) << dir_;
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    static std::string read(const std::string& p) {
        std::ifstream in(p, std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        return text.str();
    }
    // The code of the reason of the FileError that `f` throws; "" when none.
    template <typename F>
    static std::string reason_code(F&& f) {
        try {
            f();
        } catch (const FileError& e) {
            return e.reason().code;
        }
        return "";
    }
    fs::path dir_;
};

#ifndef _WIN32  // FIFOs, devices and symbolic links: POSIX
TEST_F(FileIoTest, AFifoIsRefusedAndStaysAFifo) {
    const std::string fifo = path("report.csv");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_EQ(reason_code([&] { write_file_atomically(fifo, "a,b\n"); }), "not_a_regular_file");
    EXPECT_TRUE(fs::is_fifo(fifo));
}
#endif

#ifndef _WIN32  // FIFOs, devices and symbolic links: POSIX
TEST_F(FileIoTest, ALinkToADeviceIsRefusedAndTheDeviceKept) {
    const std::string link = path("out.csv");
    fs::create_symlink("/dev/null", link);
    EXPECT_EQ(reason_code([&] { write_file_atomically(link, "x"); }), "not_a_regular_file");
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_TRUE(fs::is_character_file("/dev/null"));
}
#endif

TEST_F(FileIoTest, ADirectoryIsRefusedForWritingAndReading) {
    const std::string folder = path("folder");
    fs::create_directory(folder);
    EXPECT_EQ(reason_code([&] { write_file_atomically(folder, "x"); }), "is_a_directory");
    EXPECT_EQ(reason_code([&] { (void)read_text_file(folder); }), "is_a_directory");
    EXPECT_TRUE(fs::is_directory(folder));
    try {
        (void)read_text_file(folder);
    } catch (const FileError& e) {
        EXPECT_NE(std::string(e.what()).find(folder), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("directory"), std::string::npos) << e.what();
    }
}

#ifndef _WIN32  // FIFOs, devices and symbolic links: POSIX
TEST_F(FileIoTest, ADanglingLinkIsWrittenThroughWhenItsFolderExists) {
    const std::string link = path("link.csv");
    fs::create_symlink("target.csv", link);
    write_file_atomically(link, "new\n");
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(read(path("target.csv")), "new\n");
}
#endif

#ifndef _WIN32  // FIFOs, devices and symbolic links: POSIX
TEST_F(FileIoTest, ALinkIntoAMissingFolderIsRefusedAndKept) {
    const std::string link = path("link.csv");
    fs::create_symlink("/nonexistent-probecycle/x.csv", link);
    EXPECT_EQ(reason_code([&] { write_file_atomically(link, "x"); }), "dangling_link");
    EXPECT_TRUE(fs::is_symlink(link));
}
#endif

TEST_F(FileIoTest, StaleTemporaryFilesOfOurNamingAreRemovedAfterAWrite) {
    const std::string target = path("out.csv");
    const std::string stale = path(".out.csv.tmp-Ab12Z9");
    const std::string fresh = path(".out.csv.tmp-Cd34Y8");
    const std::string other = path(".out.csv.tmp-short");       // not six characters
    const std::string foreign = path(".other.csv.tmp-Ef56X7");  // another target's
    for (const std::string& p : {stale, fresh, other, foreign})
        std::ofstream(p, std::ios::binary) << "half";
    const auto old = fs::file_time_type::clock::now() - std::chrono::hours(1);
    for (const std::string& p : {stale, other, foreign}) fs::last_write_time(p, old);

    write_file_atomically(target, "whole\n");
    EXPECT_EQ(read(target), "whole\n");
    EXPECT_FALSE(fs::exists(stale));
    EXPECT_TRUE(fs::exists(fresh)) << "a concurrent write's file is kept";
    EXPECT_TRUE(fs::exists(other));
    EXPECT_TRUE(fs::exists(foreign));
}

TEST_F(FileIoTest, AFileOverTheLimitIsRefusedNamingTheLimit) {
    const std::string big = path("big.csv");
    std::ofstream(big, std::ios::binary) << std::string(2000, 'x');
    EXPECT_EQ(read_text_file(big, 2000).size(), 2000u);
    EXPECT_EQ(reason_code([&] { (void)read_text_file(big, 1999); }), "file_too_large");
#ifndef _WIN32
    // A device that never ends is read only to the limit.
    EXPECT_EQ(reason_code([&] { (void)read_text_file("/dev/zero", 4096); }), "file_too_large");
#endif
    try {
        (void)read_text_file(big, std::size_t{1} << 10);
    } catch (const FileError& e) {
        EXPECT_NE(std::string(e.what()).find("MiB"), std::string::npos) << e.what();
    }
}

TEST_F(FileIoTest, AMissingFileNamesThePathAndTheSystemReason) {
    const std::string missing = path("missing.json");
    try {
        (void)read_text_file(missing);
        FAIL() << "no FileError";
    } catch (const FileError& e) {
        EXPECT_EQ(e.path(), missing);
        EXPECT_EQ(e.reason().code, "system_error");
        EXPECT_NE(std::string(e.what()).find("No such file"), std::string::npos) << e.what();
    }
}

#ifndef _WIN32  // FIFOs, devices and symbolic links: POSIX
TEST_F(FileIoTest, AChainOfLinksToANewFileIsWrittenAtItsEndAndEveryLinkKept) {
    // l1 -> l2 -> new.csv: before, l2 was replaced by the file.
    fs::create_symlink("l2", path("l1"));
    fs::create_symlink("new.csv", path("l2"));
    write_file_atomically(path("l1"), "new\n");
    EXPECT_TRUE(fs::is_symlink(path("l1")));
    EXPECT_TRUE(fs::is_symlink(path("l2")));
    EXPECT_EQ(read(path("new.csv")), "new\n");
    // A loop of links is refused and kept.
    fs::create_symlink("loop_b", path("loop_a"));
    fs::create_symlink("loop_a", path("loop_b"));
    EXPECT_NE(reason_code([&] { write_file_atomically(path("loop_a"), "x"); }), "");
    EXPECT_TRUE(fs::is_symlink(path("loop_a")));
}
#endif

TEST_F(FileIoTest, TheLongestFileNameIsWritten) {
    // Before, names of 244 to 255 bytes failed: the temporary name was longer.
    for (const std::size_t length : {std::size_t{243}, std::size_t{244}, std::size_t{255}}) {
        const std::string name = std::string(length - 4, 'n') + ".csv";
        write_file_atomically(path(name), "whole\n");
        EXPECT_EQ(read(path(name)), "whole\n") << length;
        write_file_atomically(path(name), "again\n");  // and replaced
        EXPECT_EQ(read(path(name)), "again\n") << length;
    }
}

TEST_F(FileIoTest, AReadOnlyFileIsRefusedAndKept) {
    const std::string target = path("protected.csv");
    std::ofstream(target, std::ios::binary) << "old\n";
    fs::permissions(target, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
    EXPECT_EQ(reason_code([&] { write_file_atomically(target, "new\n"); }), "read_only");
    EXPECT_EQ(read(target), "old\n");
}

#ifndef _WIN32  // FIFOs, devices and symbolic links: POSIX
TEST_F(FileIoTest, AHardLinkedFileIsReplacedUnderItsNameOnly) {
    // As documented: the rename makes a new file; the other name keeps the old text.
    const std::string target = path("a.csv");
    std::ofstream(target, std::ios::binary) << "old\n";
    fs::create_hard_link(target, path("b.csv"));
    write_file_atomically(target, "new\n");
    EXPECT_EQ(read(target), "new\n");
    EXPECT_EQ(read(path("b.csv")), "old\n");
}
#endif

#ifndef _WIN32  // FIFOs, devices and symbolic links: POSIX
TEST_F(FileIoTest, AFolderThatCannotBeWrittenIsNamed) {
    // sysfs refuses new files even to root.
    if (!fs::is_directory("/sys/kernel")) GTEST_SKIP() << "no /sys";
    try {
        write_file_atomically("/sys/kernel/probecycle.csv", "x");
        FAIL() << "no FileError";
    } catch (const FileError& e) {
        EXPECT_EQ(e.reason().code, "folder_not_writable");
        EXPECT_NE(std::string(e.what()).find("the folder /sys/kernel cannot be written to"),
                  std::string::npos)
            << e.what();
    }
}
#endif

TEST_F(FileIoTest, TheSizeOfAFileOverTheLimitIsSaidInBytes) {
    const std::string big = path("big.json");
    std::ofstream(big, std::ios::binary) << std::string(1025, 'x');
    try {
        (void)read_text_file(big, 1024);
        FAIL() << "no FileError";
    } catch (const FileError& e) {
        EXPECT_NE(std::string(e.what()).find("it has 1025 bytes; the limit for an input file is "
                                             "1024 bytes"),
                  std::string::npos)
            << e.what();
    }
}

TEST_F(FileIoTest, SeveralFilesAreWrittenAllOrNothing) {
    const std::string program = path("probe.ngc");
    const std::string plan = path("probe.plan.json");
    std::ofstream(program, std::ios::binary) << "old program\n";
    std::ofstream(plan, std::ios::binary) << "old plan\n";
    write_files_atomically({{program, "new program\n"}, {plan, "new plan\n"}});
    EXPECT_EQ(read(program), "new program\n");
    EXPECT_EQ(read(plan), "new plan\n");

    // The second refused: the first is not written either, and no temporary is left.
    const std::string folder = path("folder");
    fs::create_directory(folder);
    EXPECT_EQ(reason_code([&] {
                  write_files_atomically({{program, "third\n"}, {folder, "x"}});
              }),
              "is_a_directory");
    EXPECT_EQ(read(program), "new program\n");
    std::size_t entries = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir_)) ++entries;
    EXPECT_EQ(entries, 3u);
}

TEST_F(FileIoTest, TwoOutputsToOneFileAreRefused) {
    const std::string scenario = path("scenario.json");
    std::ofstream(scenario, std::ios::binary) << "{}\n";
#ifndef _WIN32
    fs::create_symlink("scenario.json", path("link.json"));
    EXPECT_EQ(reason_code([&] {
                  write_files_atomically({{path("link.json"), "report"}, {scenario, "x"}});
              }),
              "same_file_twice");
#endif
    EXPECT_EQ(reason_code([&] {
                  write_files_atomically({{scenario, "report"}, {path("./scenario.json"), "x"}});
              }),
              "same_file_twice");
    EXPECT_EQ(read(scenario), "{}\n");
}

TEST_F(FileIoTest, AFolderOfFilesIsWrittenAsOneAndReplacesOnlyAnEarlierSet) {
    const std::string folder = path("set");
    write_folder_atomically(folder, {{"a.csv", "a1\n"}, {"b.csv", "b1\n"}});
    EXPECT_EQ(read(path("set/a.csv")), "a1\n");
    EXPECT_EQ(read(path("set/b.csv")), "b1\n");
    // An earlier set is replaced whole.
    write_folder_atomically(folder, {{"a.csv", "a2\n"}, {"b.csv", "b2\n"}});
    EXPECT_EQ(read(path("set/a.csv")), "a2\n");
    EXPECT_EQ(read(path("set/b.csv")), "b2\n");
    // A folder with the user's own files is refused and kept.
    std::ofstream(path("set/notes.txt"), std::ios::binary) << "mine\n";
    try {
        write_folder_atomically(folder, {{"a.csv", "a3\n"}, {"b.csv", "b3\n"}});
        FAIL() << "no FileError";
    } catch (const FileError& e) {
        EXPECT_EQ(e.reason().code, "folder_holds_other_files");
        EXPECT_NE(std::string(e.what()).find("notes.txt"), std::string::npos) << e.what();
    }
    EXPECT_EQ(read(path("set/a.csv")), "a2\n");
    EXPECT_EQ(read(path("set/notes.txt")), "mine\n");
    // A file where the folder should be is refused; nothing is left beside it.
    std::ofstream(path("plain"), std::ios::binary) << "x";
    EXPECT_EQ(reason_code([&] {
                  write_folder_atomically(path("plain"), {{"a.csv", "a"}});
              }),
              "not_a_folder");
    fs::remove(path("set/notes.txt"));
#ifndef _WIN32
    // A file of the set that cannot be written (a FIFO of that name) leaves the old set.
    ASSERT_EQ(::mkfifo(path("set/c.csv").c_str(), 0600), 0);
    EXPECT_EQ(reason_code([&] {
                  write_folder_atomically(folder, {{"a.csv", "a4\n"}, {"c.csv", "c\n"}});
              }),
              "folder_holds_other_files");
    EXPECT_EQ(read(path("set/a.csv")), "a2\n");
#endif
    std::size_t entries = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir_)) ++entries;
    EXPECT_EQ(entries, 2u);  // set and plain: no temporary folder left
}

// A Chinese or Russian user's folders: every path is UTF-8 text, on Windows
// too (where std::string paths would be taken in the system's code page).
TEST_F(FileIoTest, FoldersAndFilesWithChineseAndRussianNamesAreWrittenAndRead) {
    const std::string folder =
        utf8_from_path(dir_) +
        "/\u6d4b\u91cf \u0418\u0437\u043c\u0435\u0440\u0435\u043d\u0438\u044f";
    ASSERT_TRUE(fs::create_directory(path_from_utf8(folder)));
    const std::string file = folder + "/\u73af\u89c4_\u043a\u043e\u043b\u044c\u0446\u043e.csv";
    write_file_atomically(file, "old\n");
    write_file_atomically(file, "\u65b0 new\n");  // replaced
    EXPECT_EQ(read_text_file(file), "\u65b0 new\n");
    write_folder_atomically(folder + "/\u7ed3\u679c", {{"\u0430.csv", "a\n"}});
    write_folder_atomically(folder + "/\u7ed3\u679c", {{"\u0430.csv", "b\n"}});  // swapped
    EXPECT_EQ(read_text_file(folder + "/\u7ed3\u679c/\u0430.csv"), "b\n");
    std::size_t entries = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(path_from_utf8(folder)))
        ++entries;
    EXPECT_EQ(entries, 2u) << "no temporary file or folder left";
    // The path round-trips as the same UTF-8 text.
    EXPECT_EQ(utf8_from_path(path_from_utf8(file)), file);
}

TEST_F(FileIoTest, ALongNameInRussianIsWrittenWhenItsTemporaryNameIsCut) {
    // 125 Cyrillic letters, 250 bytes: the temporary name is cut between
    // letters, never inside one (Windows takes only whole UTF-8 as a name).
    std::string name;
    for (int i = 0; i < 125; ++i) name += "\u0436";
    name = name.substr(0, 246) + ".csv";
    const std::string file = utf8_from_path(dir_) + "/" + name;
    write_file_atomically(file, "whole\n");
    write_file_atomically(file, "again\n");
    EXPECT_EQ(read_text_file(file), "again\n");
    std::size_t entries = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir_)) ++entries;
    EXPECT_EQ(entries, 1u) << "no temporary file left";
}

TEST(WindowsDeviceName, TheReservedNamesInAnyCaseWithAnyExtension) {
    for (const char* name : {"CON", "con", "Nul.csv", "PRN.txt", "aux", "COM1", "com9.json", "LPT1",
                             "lpt9.ngc", "CON .csv", "nul."}) {
        EXPECT_TRUE(is_windows_device_name(name)) << name;
    }
    for (const char* name : {"CONSOLE.csv", "COM0", "COM10", "LPT", "null.csv", "icon.svg",
                             "report.csv", "", "x.CON", "\u0441\u043e\u043d.csv"}) {
        EXPECT_FALSE(is_windows_device_name(name)) << name;
    }
}

#ifdef _WIN32
TEST_F(FileIoTest, OnWindowsADeviceNameIsRefusedNamingTheRule) {
    try {
        write_file_atomically(path("nul.csv"), "x");
        FAIL() << "no FileError";
    } catch (const FileError& e) {
        EXPECT_EQ(e.reason().code, "device_name");
        EXPECT_NE(std::string(e.what()).find("Windows device"), std::string::npos) << e.what();
    }
}
#endif

}  // namespace
}  // namespace probecycle
