#include "graph/points/WorkerPool.hpp"

#include <algorithm>

namespace arcomp {

WorkerPool::WorkerPool(std::size_t workers) {
    for (std::size_t w = 1; w < std::max<std::size_t>(1, workers); ++w) threads_.emplace_back([this, w] { loop(w); });
}

WorkerPool::~WorkerPool() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : threads_) t.join();
}

void WorkerPool::runErased(void* job, Call call) {
    {
        std::lock_guard lock(mutex_);
        job_ = job;
        call_ = call;
        running_ = threads_.size();
        ++generation_;
    }
    wake_.notify_all();
    call(job, 0);
    std::unique_lock lock(mutex_);
    done_.wait(lock, [this] { return running_ == 0; });
}

void WorkerPool::loop(std::size_t worker) {
    std::uint64_t seen = 0;
    for (;;) {
        void* job = nullptr;
        Call call = nullptr;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
            if (stop_) return;
            seen = generation_;
            job = job_;
            call = call_;
        }
        call(job, worker);
        std::lock_guard lock(mutex_);
        if (--running_ == 0) done_.notify_one();
    }
}

}  // namespace arcomp
