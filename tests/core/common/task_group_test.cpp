// TaskGroup: every task runs once, its results are seen after wait(), a
// task's exception comes back from wait(), and the caller runs what the
// workers have not taken.

#include "core/common/task_group.h"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

namespace probecycle {
namespace {

TEST(TaskGroup, EveryTaskRunsOnceAndItsResultIsSeenAfterWait) {
    std::vector<int> results(64, 0);
    std::atomic<int> runs{0};
    TaskGroup group;
    for (int i = 0; i < 64; ++i) {
        group.run([&results, &runs, i] {
            results[static_cast<std::size_t>(i)] = i * i;
            ++runs;
        });
    }
    group.wait();
    EXPECT_EQ(runs.load(), 64);
    for (int i = 0; i < 64; ++i) EXPECT_EQ(results[static_cast<std::size_t>(i)], i * i);
    EXPECT_GE(TaskGroup::workers(), 1);
}

TEST(TaskGroup, AGroupWithoutTasksWaitsForNothing) {
    TaskGroup group;
    group.wait();
    group.wait();
    SUCCEED();
}

TEST(TaskGroup, TheFirstQueuedTasksExceptionComesBackFromWait) {
    TaskGroup group;
    std::atomic<int> runs{0};
    group.run([&runs] { ++runs; });
    group.run([&runs] {
        ++runs;
        throw std::runtime_error("first");
    });
    group.run([&runs] {
        ++runs;
        throw std::logic_error("second");
    });
    try {
        group.wait();
        FAIL() << "no exception";
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), "first");
    }
    EXPECT_EQ(runs.load(), 3);  // the others ran all the same
    group.wait();               // and the group is empty again
}

// With every worker busy, the caller runs the tasks itself: a group waited
// for from inside a task cannot deadlock, however many are nested.
TEST(TaskGroup, TasksThatWaitForGroupsOfTheirOwnFinish) {
    std::atomic<int> leaves{0};
    TaskGroup outer;
    for (int i = 0; i < 2 * TaskGroup::workers() + 2; ++i) {
        outer.run([&leaves] {
            TaskGroup inner;
            for (int j = 0; j < 4; ++j) inner.run([&leaves] { ++leaves; });
            inner.wait();
        });
    }
    outer.wait();
    EXPECT_EQ(leaves.load(), 4 * (2 * TaskGroup::workers() + 2));
}

TEST(TaskGroup, TheCallerRunsWhatNoWorkerHasTaken) {
    // Occupy every worker until the caller has run the last task itself.
    std::atomic<bool> release{false};
    std::atomic<int> started{0};
    const std::thread::id caller = std::this_thread::get_id();
    std::thread::id ran_on;
    TaskGroup group;
    for (int i = 0; i < TaskGroup::workers(); ++i) {
        group.run([&release, &started] {
            ++started;
            while (!release.load()) std::this_thread::yield();
        });
    }
    while (started.load() < TaskGroup::workers()) std::this_thread::yield();
    group.run([&ran_on, &release] {
        ran_on = std::this_thread::get_id();
        release = true;
    });
    group.wait();
    EXPECT_EQ(ran_on, caller);
}

}  // namespace
}  // namespace probecycle
