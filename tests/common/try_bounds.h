#pragma once
// How long a test waits for a condition before it calls the condition failed (issue 33:
// steady under load). A QTRY_* bound is not a duration under test: the wait ends as soon as
// the condition holds, so a passing test takes as long as before. The bound only says when to
// give up, and on a machine where other processes take the cores (CI beside a build, `ctest
// -j2` beside two busy loops) a simulated device's answer can come several times later than
// on an idle one. Every QTRY_* of the tests therefore gives up after kTryStretch times the
// bound it names (IMUDESK_TEST_TRY_STRETCH in the environment overrides the factor; 1 restores
// Qt's). Durations that are themselves under test are measured with QElapsedTimer or the
// device's clock and compared explicitly, never through a QTRY bound.
//
// Included by the tests' precompiled headers (cmake/pch/test_pch.h), so it applies to every
// test file, after <QTest> defined the macro it replaces.
#include <QElapsedTimer>
#include <QTest>

#include <cstdlib>

namespace imudesk::test {

inline constexpr int kTryStretch = 3;

inline int tryBound(int timeoutMs)
{
    static const int stretch = [] {
        const char *text = std::getenv("IMUDESK_TEST_TRY_STRETCH");
        const int value = text ? std::atoi(text) : kTryStretch;
        return value >= 1 ? value : kTryStretch;
    }();
    return timeoutMs * stretch;
}

// QTest::qWaitFor with the same stretch as the QTRY_* macros below: runs the event loop until
// pred holds, giving up after tryBound(timeoutMs). The tests call this instead of qWaitFor; a
// wait that needed more than the bound it names says so (QINFO), as a QTRY_* does.
template <typename Predicate>
bool waitFor(Predicate pred, int timeoutMs)
{
    QElapsedTimer clock;
    clock.start();
    const bool held = QTest::qWaitFor(pred, tryBound(timeoutMs));
    if (held && clock.elapsed() > timeoutMs)
        qInfo("a condition held after about %lld ms, beyond its bound of %d ms (stretched for a busy machine)",
              static_cast<long long>(clock.elapsed()), timeoutMs);
    return held;
}

} // namespace imudesk::test

// Qt 6.4's QTRY_IMPL (qtestcase.h) with the bound stretched. Qt's second wait (twice the bound
// again, to tell how much longer it would have taken) is replaced by the stretch itself; a wait
// that needed more than the bound it names says so in the test's output (QINFO), so a slowdown
// stays visible while the test passes.
#ifndef QTRY_IMPL
#error "QTRY_IMPL is not defined: <QTest> changed; see tests/common/try_bounds.h"
#endif
#undef QTRY_IMPL
#define QTRY_IMPL(expr, timeout)                                                                                 \
    const int qt_test_timeoutValue = ::imudesk::test::tryBound(timeout);                                         \
    const int qt_test_step = (timeout) < 350 ? (timeout) / 7 + 1 : 50;                                           \
    {                                                                                                            \
        QTRY_LOOP_IMPL(expr, qt_test_timeoutValue, qt_test_step)                                                 \
        if (qt_test_i > (timeout) && (expr))                                                                     \
            qInfo("%s held after about %d ms, beyond its bound of %d ms (stretched for a busy machine)",       \
                  #expr, qt_test_i, int(timeout));                                                               \
    }
