#include "runtime/station/WorkerThread.hpp"

#include <stdexcept>
#include <utility>

namespace arcomp {

WorkerThread::WorkerThread() : thread_([this] { run(); }) {}

WorkerThread::~WorkerThread() {
    wait();
    {
        const std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_one();
    thread_.join();
}

void WorkerThread::start(std::function<void()> job) {
    if (busy_) throw std::logic_error("WorkerThread::start: the previous job has not been finished");
    {
        const std::lock_guard lock(mutex_);
        job_ = std::move(job);
        thrown_ = nullptr;
    }
    busy_ = true;
    wake_.notify_one();
}

void WorkerThread::wait() noexcept {
    std::unique_lock lock(mutex_);
    done_.wait(lock, [this] { return !job_ && !running_; });
}

void WorkerThread::finish() {
    if (!busy_) return;
    wait();
    busy_ = false;
    std::exception_ptr thrown;
    {
        const std::lock_guard lock(mutex_);
        thrown = std::exchange(thrown_, nullptr);
    }
    if (thrown) std::rethrow_exception(thrown);
}

void WorkerThread::run() {
    std::unique_lock lock(mutex_);
    for (;;) {
        wake_.wait(lock, [this] { return stop_ || job_; });
        if (!job_) return;  // stop_, with nothing left to run
        std::function<void()> job = std::move(job_);
        job_ = nullptr;
        running_ = true;
        lock.unlock();
        std::exception_ptr thrown;
        try {
            job();
        } catch (...) {
            thrown = std::current_exception();
        }
        job = nullptr;  // the job's captures go on this thread, before the owner is told
        lock.lock();
        thrown_ = thrown;
        running_ = false;
        done_.notify_all();
    }
}

}  // namespace arcomp
