#pragma once
// A fixed set of threads that runs one parallel job at a time and lives as
// long as its owner, so that a frame's parallel region costs a wake-up
// rather than starting and joining threads every frame.
//
//   WorkerPool pool(2);                                      // the caller is worker 0
//   pool.run([&](std::size_t worker) { drawBand(worker); });  // returns once every worker is done
//
// Jobs must not throw: an exception on a pool thread ends the program, as
// it would on a plain std::thread. One caller at a time.

#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace arcomp {

class WorkerPool {
public:
    // `workers` counts the caller: 1 runs every job on the calling thread.
    explicit WorkerPool(std::size_t workers);
    ~WorkerPool();
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    std::size_t size() const { return threads_.size() + 1; }
    // `job(worker)` on every worker at once, worker 0 on this thread. The
    // job is called through a pointer, not copied into a std::function, so
    // a frame allocates nothing.
    template <class Job>
    void run(Job& job) {
        runErased(&job, [](void* j, std::size_t worker) { (*static_cast<Job*>(j))(worker); });
    }

private:
    using Call = void (*)(void* job, std::size_t worker);
    void runErased(void* job, Call call);
    void loop(std::size_t worker);

    std::vector<std::thread> threads_;
    std::mutex mutex_;
    std::condition_variable wake_, done_;
    void* job_ = nullptr;
    Call call_ = nullptr;
    std::uint64_t generation_ = 0;  // one per run(), so a worker never runs a job twice
    std::size_t running_ = 0;
    bool stop_ = false;
};

}  // namespace arcomp
