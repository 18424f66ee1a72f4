#pragma once
// One thread for the life of its owner, running one job at a time: the
// station's front (capture and matte of the next frame) runs on it while
// the frame's GL stages run on the caller's thread.
//
// Why not std::async: that starts a new thread for every job. Libraries
// keep per-thread data that outlives the thread (OpenCV 4.6's TLS slots,
// which cv::parallel_for_ takes, stay allocated after the thread exits,
// still referenced, so no leak checker reports them): a thread a frame grew
// a station by about 0.9 KB a frame. A thread that stays makes that data once.
//
//   WorkerThread worker;
//   worker.start([&] { next = captureAndMatte(); });
//   drawThisFrame();          // on the caller's thread, meanwhile
//   worker.finish();          // waits; rethrows what the job threw

#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace arcomp {

class WorkerThread {
public:
    WorkerThread();
    // Waits for the job in hand (what it threw is dropped), then ends the thread.
    ~WorkerThread();
    WorkerThread(const WorkerThread&) = delete;
    WorkerThread& operator=(const WorkerThread&) = delete;

    // Hands `job` to the thread. One job at a time: throws std::logic_error
    // while a started job has not been finish()ed.
    void start(std::function<void()> job);
    // Whether a job was started and not yet finish()ed (it may have run already).
    bool busy() const { return busy_; }
    // Waits for the job in hand and rethrows what it threw; returns at once
    // when there is none.
    void finish();
    // Waits for the job in hand without rethrowing (for scope guards); the
    // job stays busy() until finish() takes its outcome.
    void wait() noexcept;

private:
    void run();

    std::mutex mutex_;
    std::condition_variable wake_, done_;
    std::function<void()> job_;  // set: handed and not yet run
    bool running_ = false;       // the job is on the thread now
    bool stop_ = false;
    std::exception_ptr thrown_;
    bool busy_ = false;   // the owner's side: started, not finished
    std::thread thread_;  // last: starts once the rest is ready
};

}  // namespace arcomp
