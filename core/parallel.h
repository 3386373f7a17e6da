#pragma once
// Fork-join for the builds: a pool of worker threads, tasks in
// groups, and a wait that runs queued tasks (anyone's) until its group is done, so that
// a task may fork and wait in turn without tying a thread up. Workers take the oldest
// task (the largest, in a top-down build); a waiting thread the newest (its own).

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

namespace rt {

// The threads to use when asked for `requested` (0: every hardware thread).
inline int build_threads(int requested) {
    if (requested > 0) return requested;
    return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

class TaskPool {
  public:
    // Tasks waited for together.
    struct Group {
        std::atomic<int> pending{0};
    };

    explicit TaskPool(int threads) : threads_(std::max(1, threads)) {
        for (int i = 1; i < threads_; ++i)
            workers_.emplace_back([this](std::stop_token stop) { work(stop); });
    }
    ~TaskPool() {
        {
            std::lock_guard lock(mutex_);  // so that no worker is between its check and its wait
            for (auto& w : workers_) w.request_stop();
        }
        cv_.notify_all();
    }
    TaskPool(const TaskPool&) = delete;
    TaskPool& operator=(const TaskPool&) = delete;

    int threads() const { return threads_; }

    // A pool of `threads` kept for the life of the process (its workers sleep between
    // uses), so that a build pays no thread starts: one per thread count asked for.
    static TaskPool& shared(int threads) {
        static std::mutex mutex;
        static std::map<int, std::unique_ptr<TaskPool>> pools;
        std::lock_guard lock(mutex);
        auto& pool = pools[threads];
        if (!pool) pool = std::make_unique<TaskPool>(threads);
        return *pool;
    }

    void run(Group& group, std::function<void()> task) {
        group.pending.fetch_add(1);
        {
            std::lock_guard lock(mutex_);
            queue_.emplace_back(&group, std::move(task));
        }
        cv_.notify_one();
    }

    // Returns once every task of `group` has run, running queued tasks meanwhile.
    void wait(Group& group) {
        while (group.pending.load() > 0)
            if (!run_one(/*newest=*/true)) std::this_thread::yield();
    }

  private:
    using Task = std::pair<Group*, std::function<void()>>;

    bool run_one(bool newest) {
        Task task;
        {
            std::lock_guard lock(mutex_);
            if (queue_.empty()) return false;
            if (newest) {
                task = std::move(queue_.back());
                queue_.pop_back();
            } else {
                task = std::move(queue_.front());
                queue_.pop_front();
            }
        }
        task.second();
        task.first->pending.fetch_sub(1);
        return true;
    }

    void work(std::stop_token stop) {
        while (!stop.stop_requested()) {
            {
                std::unique_lock lock(mutex_);
                cv_.wait(lock, [&] { return stop.stop_requested() || !queue_.empty(); });
            }
            while (run_one(/*newest=*/false)) {
            }
        }
    }

    int threads_;
    std::mutex mutex_;
    std::condition_variable cv_;
    std::deque<Task> queue_;
    std::vector<std::jthread> workers_;  // last: stopped and joined first
};

// How many parts of at least `min_part` items [0, count) makes on up to `threads`
// threads (at least 1).
inline int part_count(std::size_t count, int threads, std::size_t min_part) {
    const std::size_t by_size = count / std::max<std::size_t>(1, min_part);
    return static_cast<int>(
        std::clamp<std::size_t>(by_size, 1, static_cast<std::size_t>(std::max(1, threads))));
}

// Calls body(part, begin, end) for `parts` contiguous ranges covering [begin, end), on
// the pool (the calling thread takes part 0; no pool: all here); returns when all have.
template <class Body>
void parallel_parts(TaskPool* pool, std::size_t begin, std::size_t end, int parts, Body&& body) {
    const std::size_t count = end - begin;
    const auto at = [&](int part) {
        return begin + count * static_cast<std::size_t>(part) / static_cast<std::size_t>(parts);
    };
    if (!pool || parts <= 1) {
        for (int part = 0; part < parts; ++part) body(part, at(part), at(part + 1));
        return;
    }
    TaskPool::Group group;
    for (int part = 1; part < parts; ++part)
        pool->run(group, [&body, part, b = at(part), e = at(part + 1)] { body(part, b, e); });
    body(0, at(0), at(1));
    pool->wait(group);
}

}  // namespace rt
