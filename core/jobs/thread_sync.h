#pragma once
// Hand-overs between threads that ThreadSanitizer cannot see, told to it.
//
// Debian's Qt is not built with ThreadSanitizer, and Qt 6 waits on futexes of its own (QMutex,
// QSemaphore, QThread::wait): a thread joined with QThread::wait() or a call made with
// Qt::BlockingQueuedConnection orders the two threads' memory, but TSan sees no such order and
// reports the accesses on both sides as a race. These helpers do the same waits and tell TSan
// about the order they make (__tsan_release on the side that hands over, __tsan_acquire on the
// side that takes over). In a build without TSan they are the plain Qt calls.
//
// What stays invisible to TSan is the queue of a queued signal; tests/tsan.supp suppresses those
// reports by the Qt frames that carry the value, and says why.
#include <QMetaObject>
#include <QThread>

#include <utility>

#if defined(__SANITIZE_THREAD__)
#define IMUDESK_THREAD_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define IMUDESK_THREAD_SANITIZER 1
#endif
#endif

#ifdef IMUDESK_THREAD_SANITIZER
extern "C" void __tsan_acquire(void *addr);
extern "C" void __tsan_release(void *addr);
#endif

namespace imudesk::jobs {

// What this thread wrote so far is seen by a thread that calls takeOver(token) afterwards.
inline void handOver([[maybe_unused]] const void *token)
{
#ifdef IMUDESK_THREAD_SANITIZER
    __tsan_release(const_cast<void *>(token));
#endif
}
inline void takeOver([[maybe_unused]] const void *token)
{
#ifdef IMUDESK_THREAD_SANITIZER
    __tsan_acquire(const_cast<void *>(token));
#endif
}

// Runs fn in context's thread and returns when it has run (Qt::BlockingQueuedConnection): what
// the caller wrote before is seen by fn, what fn wrote is seen by the caller after.
template <typename Fn>
void callAndWait(QObject *context, Fn &&fn)
{
    char token = 0;
    handOver(&token);
    QMetaObject::invokeMethod(
        context,
        [&token, &fn] {
            takeOver(&token);
            std::forward<Fn>(fn)();
            handOver(&token);
        },
        Qt::BlockingQueuedConnection);
    takeOver(&token);
}

// Runs fn later in context's thread (Qt::QueuedConnection): what the caller wrote before, e.g.
// a request's payload it allocated, is seen by fn. (The copy of fn itself is made inside Qt,
// after this hand-over; tests/tsan.supp covers that copy.)
template <typename Fn>
void postTo(QObject *context, Fn &&fn)
{
    handOver(context);
    QMetaObject::invokeMethod(
        context,
        [context, f = std::forward<Fn>(fn)]() mutable {
            takeOver(context);
            f();
        },
        Qt::QueuedConnection);
}

// Call once when the thread is made, before start(): its last act hands over what it wrote, for
// joinThread() to take over.
inline void announceJoin(QThread &thread)
{
    // Direct: QThread::finished is emitted by the finishing thread itself, and the QThread
    // object lives in the thread that made it (an automatic connection would queue it there).
    QObject::connect(&thread, &QThread::finished, &thread, [t = &thread] { handOver(t); }, Qt::DirectConnection);
}
// wait() for a thread that ends by itself (QThread::create); afterwards everything the thread
// wrote is the caller's.
inline void waitForThread(QThread &thread)
{
    thread.wait();
    takeOver(&thread);
}
// quit() its event loop and waitForThread().
inline void joinThread(QThread &thread)
{
    thread.quit();
    waitForThread(thread);
}

} // namespace imudesk::jobs
