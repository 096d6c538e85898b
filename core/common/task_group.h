#pragma once

// Independent pieces of one computation run side by side: a TaskGroup hands
// its tasks to workers on the machine's other cores while the caller goes on,
// and wait() runs on the caller's own thread every task no worker has taken
// yet. The workers live as long as the program, so what a task keeps in
// thread_local caches (the motion cache) stays warm for the next group.
//
// The results do not depend on which thread runs what: each task writes only
// its own result, read after wait().

#include <exception>
#include <functional>
#include <memory>
#include <vector>

namespace probecycle {

class TaskGroup {
  public:
    TaskGroup() = default;
    TaskGroup(const TaskGroup&) = delete;
    TaskGroup& operator=(const TaskGroup&) = delete;
    // Waits for the tasks still running (their exceptions are dropped).
    ~TaskGroup();

    // Queues `task` for a worker (or for wait()).
    void run(std::function<void()> task);
    // Returns when every task has run; rethrows the first task's exception,
    // in the order the tasks were queued.
    void wait();

    // The workers beside the caller: the machine's cores less one, at least one.
    static int workers();

    struct Task;

  private:
    void finish_all() noexcept;
    std::vector<std::shared_ptr<Task>> tasks_;
};

}  // namespace probecycle
