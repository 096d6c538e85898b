#include "core/common/task_group.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>
#include <utility>

namespace probecycle {

struct TaskGroup::Task {
    std::function<void()> body;
    std::atomic<bool> taken{false};
    std::exception_ptr error;
    std::mutex mutex;
    std::condition_variable done_changed;
    bool done{false};

    // Runs the body if no one has taken it yet; false if someone had.
    bool take_and_run() {
        if (taken.exchange(true)) return false;
        try {
            body();
        } catch (...) {
            error = std::current_exception();
        }
        {
            const std::lock_guard<std::mutex> lock(mutex);
            done = true;
        }
        done_changed.notify_all();
        return true;
    }

    void wait_done() {
        std::unique_lock<std::mutex> lock(mutex);
        done_changed.wait(lock, [this] { return done; });
    }
};

namespace {

// The workers and their queue, started on the first task, stopped and joined
// when the program ends.
class Pool {
  public:
    static Pool& instance() {
        static Pool pool;
        return pool;
    }

    void push(std::shared_ptr<TaskGroup::Task> task) {
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            queue_.push_back(std::move(task));
        }
        queue_changed_.notify_one();
    }

    int size() const { return static_cast<int>(threads_.size()); }

    Pool(const Pool&) = delete;
    Pool& operator=(const Pool&) = delete;

  private:
    Pool() {
        const unsigned cores = std::thread::hardware_concurrency();
        const unsigned count = std::max(1U, cores > 1 ? cores - 1 : 1U);
        threads_.reserve(count);
        for (unsigned i = 0; i < count; ++i) threads_.emplace_back([this] { work(); });
    }

    ~Pool() {
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            stopping_ = true;
        }
        queue_changed_.notify_all();
        for (std::thread& thread : threads_) thread.join();
    }

    void work() {
        for (;;) {
            std::shared_ptr<TaskGroup::Task> task;
            {
                std::unique_lock<std::mutex> lock(mutex_);
                queue_changed_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
                if (queue_.empty()) return;  // stopping
                task = std::move(queue_.front());
                queue_.pop_front();
            }
            task->take_and_run();  // the caller's wait() may have run it already
        }
    }

    std::mutex mutex_;
    std::condition_variable queue_changed_;
    std::deque<std::shared_ptr<TaskGroup::Task>> queue_;
    bool stopping_{false};
    std::vector<std::thread> threads_;
};

}  // namespace

TaskGroup::~TaskGroup() {
    finish_all();
}

int TaskGroup::workers() {
    return Pool::instance().size();
}

void TaskGroup::run(std::function<void()> task) {
    auto shared = std::make_shared<Task>();
    shared->body = std::move(task);
    tasks_.push_back(shared);
    Pool::instance().push(std::move(shared));
}

void TaskGroup::finish_all() noexcept {
    // What no worker has started runs here, on the caller's warm caches.
    for (const std::shared_ptr<Task>& task : tasks_) task->take_and_run();
    for (const std::shared_ptr<Task>& task : tasks_) task->wait_done();
}

void TaskGroup::wait() {
    finish_all();
    std::vector<std::shared_ptr<Task>> tasks;
    tasks.swap(tasks_);
    for (const std::shared_ptr<Task>& task : tasks) {
        if (task->error) std::rethrow_exception(task->error);
    }
}

}  // namespace probecycle
