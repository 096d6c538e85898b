#include "core/common/file_io.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace probecycle {
namespace {

namespace fs = std::filesystem;

class FileIoTest : public ::testing::Test {
  protected:
    void SetUp() override {
        char pattern[] = "/tmp/probecycle-file-io-XXXXXX";
        ASSERT_NE(::mkdtemp(pattern), nullptr);
        dir_ = pattern;
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

TEST_F(FileIoTest, AFifoIsRefusedAndStaysAFifo) {
    const std::string fifo = path("report.csv");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_EQ(reason_code([&] { write_file_atomically(fifo, "a,b\n"); }), "not_a_regular_file");
    EXPECT_TRUE(fs::is_fifo(fifo));
}

TEST_F(FileIoTest, ALinkToADeviceIsRefusedAndTheDeviceKept) {
    const std::string link = path("out.csv");
    fs::create_symlink("/dev/null", link);
    EXPECT_EQ(reason_code([&] { write_file_atomically(link, "x"); }), "not_a_regular_file");
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

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

TEST_F(FileIoTest, ADanglingLinkIsWrittenThroughWhenItsFolderExists) {
    const std::string link = path("link.csv");
    fs::create_symlink("target.csv", link);
    write_file_atomically(link, "new\n");
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(read(path("target.csv")), "new\n");
}

TEST_F(FileIoTest, ALinkIntoAMissingFolderIsRefusedAndKept) {
    const std::string link = path("link.csv");
    fs::create_symlink("/nonexistent-probecycle/x.csv", link);
    EXPECT_EQ(reason_code([&] { write_file_atomically(link, "x"); }), "dangling_link");
    EXPECT_TRUE(fs::is_symlink(link));
}

TEST_F(FileIoTest, StaleTemporaryFilesOfOurNamingAreRemovedAfterAWrite) {
    const std::string target = path("out.csv");
    const std::string stale = path(".out.csv.tmp-Ab12Z9");
    const std::string fresh = path(".out.csv.tmp-Cd34Y8");
    const std::string other = path(".out.csv.tmp-short");       // not six characters
    const std::string foreign = path(".other.csv.tmp-Ef56X7");  // another target's
    for (const std::string& p : {stale, fresh, other, foreign}) std::ofstream(p) << "half";
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
    std::ofstream(big) << std::string(2000, 'x');
    EXPECT_EQ(read_text_file(big, 2000).size(), 2000u);
    EXPECT_EQ(reason_code([&] { (void)read_text_file(big, 1999); }), "file_too_large");
    // A device that never ends is read only to the limit.
    EXPECT_EQ(reason_code([&] { (void)read_text_file("/dev/zero", 4096); }), "file_too_large");
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

}  // namespace
}  // namespace probecycle
