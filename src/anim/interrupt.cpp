#include "anim/interrupt.h"

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <thread>

namespace frameray::anim {

namespace {

std::atomic<bool> gStop{false};
std::mutex gMutex;
std::condition_variable gCv;
bool gAcknowledged = false;
std::function<void()> gEmergency;
int gPipe[2] = {-1, -1};

// Async-signal-safe: only raises the flag and wakes the watcher. Whatever
// thread the signal lands on (libraries may start threads before main).
void onSignal(int) {
    gStop = true;
    const char byte = 1;
    [[maybe_unused]] const auto n = write(gPipe[1], &byte, 1);
}

}  // namespace

void installInterruptWatcher(std::chrono::milliseconds grace) {
    if (pipe(gPipe) != 0) return;
    struct sigaction sa = {};
    sa.sa_handler = onSignal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART;
    sigaction(SIGINT, &sa, nullptr);
    sigaction(SIGTERM, &sa, nullptr);
    std::thread([grace] {
        char byte = 0;
        while (read(gPipe[0], &byte, 1) < 0) {
        }
        gStop = true;
        std::unique_lock lock(gMutex);
        if (gCv.wait_for(lock, grace, [] { return gAcknowledged; })) return;
        std::function<void()> action = gEmergency;
        lock.unlock();
        if (action) action();
        std::fflush(nullptr);
        _exit(2);
    }).detach();
}

bool stopRequested() { return gStop.load(); }

void acknowledgeStop() {
    {
        std::lock_guard lock(gMutex);
        gAcknowledged = true;
    }
    gCv.notify_all();
}

void setEmergencyStop(std::function<void()> action) {
    std::lock_guard lock(gMutex);
    gEmergency = std::move(action);
}

}  // namespace frameray::anim
