// Faults injected on the way into a DeviceSession. Through a pseudo-terminal (the real serial
// path: the test plays the device, or sim::PtySimulator): random byte corruption, an overload
// (a frame every 100 µs for 10 s), a frame split by a pause and a reader that stalls. With the
// simulated module in this process (sim::SimulatedTransport): a storm of ERR replies, a device
// that reboots by itself and a baud rate switched under the tool's feet. In every case: no
// crash, every intact frame is decoded, the session stays in a clear state, and the thread
// that owns the session (the GUI thread in the app) never waits on the link: its event loop
// keeps turning.
#include "../common/raw_pty.h"
#include "../common/session_probes.h"
#include "../common/session_send.h"
#include "../common/sim_session.h"
#include "../common/test_main.h"
#include "device/device_session.h"
#include "protocol/hipnuc/frame_decoder.h"
#include "protocol/hipnuc/payloads.h"
#include "sim/pty_simulator.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>
#include <QTimer>

#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <cstdlib>
#include <random>

using namespace imudesk;
using device::DeviceSession;
using device::SessionState;
using protocol::hipnuc::AsciiReply;
using test::hi91Frame;
using test::kSanitized;
using test::RawPty;
using test::StallWatch;
using test::StatsProbe;

namespace {

bool waitState(DeviceSession &s, SessionState want, int timeoutMs = 15000)
{
    return imudesk::test::waitFor([&s, want] { return s.state() == want; }, timeoutMs);
}

AsciiReply send(DeviceSession &s, const QString &cmd, int timeoutMs = 1000)
{
    return test::sendAndWait(s, cmd, timeoutMs);
}

sim::SimOptions simOptions(int baud = 115200)
{
    sim::SimOptions o;
    o.model = "HI14R3";
    o.firmware = "1.7.1";
    o.baud = baud;
    o.motion = sim::Motion::Spin;
    o.seed = 7;
    return o;
}

} // namespace

class TstFaultInjection : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void tenPercentCorruption()
    {
        RawPty pty;
        QVERIFY(pty.ok());
        DeviceSession session;
        StatsProbe stats(session);
        QVERIFY(test::openOnPty(session, pty));
        StallWatch stalls;

        // 4000 frames; one in ten hit by a burst of 1 to 8 random bytes somewhere in it
        // (header, length, CRC or payload). Frames that survived must all be decoded;
        // damaged ones must not turn into samples.
        std::mt19937 rng(1234);
        std::uniform_int_distribution<int> byte(0, 255), percent(0, 99), burst(1, 8);
        uint64_t intact = 0, written = 0;
        for (uint32_t i = 0; i < 4000; ++i) {
            std::vector<uint8_t> frame = hi91Frame(1000 + i);
            bool damaged = false;
            if (percent(rng) < 10) {
                std::uniform_int_distribution<size_t> where(0, frame.size() - 1);
                const size_t at = where(rng);
                for (int k = burst(rng); k > 0 && at + size_t(k) - 1 < frame.size(); --k) {
                    const uint8_t v = uint8_t(byte(rng));
                    damaged |= v != frame[at + size_t(k) - 1];
                    frame[at + size_t(k) - 1] = v;
                }
            }
            intact += damaged ? 0 : 1;
            pty.write(frame);
            written += frame.size();
            if (i % 200 == 0) {
                pty.drain();
                QCoreApplication::processEvents();
            }
        }
        QTRY_VERIFY_WITH_TIMEOUT(stats.last.frames >= intact, 10000);
        // Every byte written has been through the decoder: nothing more can come.
        QTRY_COMPARE_WITH_TIMEOUT(stats.last.bytesIn, written, 5000);
        QVERIFY(intact > 3500 && intact < 3700);
        // A damaged frame passing its CRC by chance is 1 in 65536: none here.
        QCOMPARE(stats.last.frames, intact);
        QCOMPARE(session.store().totalAppended(), intact);
        QVERIFY(stats.last.crcErrors + stats.last.bytesSkipped > 0);
        QCOMPARE(session.state(), SessionState::Connected);
        qInfo("corruption: %llu intact frames decoded of 4000, %llu CRC errors, %llu bytes skipped, worst stall %lld ms",
              (unsigned long long)intact, (unsigned long long)stats.last.crcErrors,
              (unsigned long long)stats.last.bytesSkipped, stalls.worstMs());
        if (!kSanitized)
            QVERIFY2(stalls.worstMs() < 100, qPrintable(QString::number(stalls.worstMs())));
    }

    void overloadFrameEvery100us()
    {
        RawPty pty;
        QVERIFY(pty.ok());
        DeviceSession session;
        StatsProbe stats(session);
        QVERIFY(test::openOnPty(session, pty));
        StallWatch stalls;
        // 10 s of a frame every 100 µs (10 kHz, ten times what any module sends), written
        // in 1 ms slices of ten frames.
        const int seconds = qEnvironmentVariableIntValue("IMUDESK_OVERLOAD_SECONDS") > 0
                                ? qEnvironmentVariableIntValue("IMUDESK_OVERLOAD_SECONDS")
                                : 10;
        const uint32_t total = uint32_t(seconds) * 10000;
        QElapsedTimer clock;
        clock.start();
        uint32_t sent = 0;
        while (sent < total) {
            const uint32_t due = std::min<uint32_t>(total, uint32_t(clock.nsecsElapsed() / 100'000) + 10);
            std::vector<uint8_t> slice;
            for (; sent < due; ++sent) {
                const auto f = hi91Frame(sent); // device clock: one ms per frame (10 frames per real ms)
                slice.insert(slice.end(), f.begin(), f.end());
            }
            pty.write(slice);
            pty.drain();
            QTest::qWait(1); // duration under test: the writer paces the 10 kHz stream in 1 ms slices
        }
        QTRY_VERIFY_WITH_TIMEOUT(stats.last.frames >= total, 30000);
        QCOMPARE(stats.last.crcErrors, uint64_t(0));
        QCOMPARE(session.state(), SessionState::Connected);
        // The store is bounded: it keeps its capacity, not the 100 000 samples.
        QVERIFY(session.store().size() <= session.store().capacity());
        QCOMPARE(session.store().totalAppended(), uint64_t(total));
        qInfo("overload: %u frames in %.1f s, worst stall %lld ms", total, clock.elapsed() / 1000.0, stalls.worstMs());
        if (!kSanitized)
            QVERIFY2(stalls.worstMs() < 100, qPrintable(QString::number(stalls.worstMs())));
    }

    void errStormKeepsStreaming()
    {
        test::SimSession sim(simOptions(921600));
        DeviceSession &session = sim.session;
        session.setAutoReconnect(false);
        StatsProbe stats(session);
        sim.open(921600);
        QVERIFY(waitState(session, SessionState::Connected));
        QTRY_VERIFY(session.store().totalAppended() > 50);
        const uint64_t before = session.store().totalAppended();
        // 200 commands the device refuses with ERR, as fast as the session takes them.
        QSignalSpy finished(&session, &DeviceSession::commandFinished);
        for (int i = 0; i < 200; ++i)
            session.sendText(QStringLiteral("CONFIG ATT MODE 7"), 1000);
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 200, 60000);
        int errors = 0;
        for (const auto &args : finished)
            errors += args.at(1).value<AsciiReply>().status == AsciiReply::Status::Refused;
        QCOMPARE(errors, 200);
        // The stream went on meanwhile and the next command still works.
        QTRY_VERIFY(session.store().totalAppended() > before + 50);
        QCOMPARE(send(session, QStringLiteral("LOG VERSION")).status, AsciiReply::Status::Ok);
        QCOMPARE(session.state(), SessionState::Connected);
        QCOMPARE(stats.last.crcErrors, uint64_t(0));
    }

    void deviceRebootsByItself()
    {
        test::SimSession sim(simOptions());
        DeviceSession &session = sim.session;
        session.setAutoReconnect(false);
        StatsProbe stats(session);
        sim.open(115200);
        QVERIFY(waitState(session, SessionState::Connected));
        QTRY_VERIFY(session.store().totalAppended() > 100);
        sim.withDevice([](sim::HipnucSimulator &d) { d.powerCycle(); });
        QTRY_VERIFY_WITH_TIMEOUT(stats.last.deviceResets >= 1, 5000);
        const uint64_t after = session.store().totalAppended();
        QTRY_VERIFY(session.store().totalAppended() > after + 50); // streaming again
        QCOMPARE(session.state(), SessionState::Connected);
        // A reset is not a loss: the gap across it is not counted as frames lost.
        QCOMPARE(stats.last.framesLost, uint64_t(0));
    }

    void baudSwitchedUnderTheToolsFeet()
    {
        test::SimSession sim(simOptions());
        DeviceSession &session = sim.session;
        session.setAutoReconnect(false);
        StatsProbe stats(session);
        QSignalSpy errors(&session, &DeviceSession::errorOccurred);
        QSignalSpy warnings(&session, &DeviceSession::streamWarning);
        sim.open(115200);
        QVERIFY(waitState(session, SessionState::Connected));
        QTRY_VERIFY(session.store().totalAppended() > 50);
        stats.next(3000);
        const uint64_t damageBefore = stats.last.bytesSkipped + stats.last.crcErrors;
        // Someone else tells the module to run at 460800 (another tool on the same port).
        sim.withDevice([](sim::HipnucSimulator &d) { d.receive("SERIALCONFIG 460800\r\n"); });
        QCOMPARE(sim.deviceBaud(), 460800);
        // Garbage arrives now: what the module sent at the old rate is in.
        QTRY_VERIFY_WITH_TIMEOUT(stats.last.bytesSkipped + stats.last.crcErrors > damageBefore, 5000);
        const uint64_t frozen = session.store().totalAppended();
        QTest::qWait(800); // duration under test: 800 ms of garbage and no new sample
        // Garbage only: no new samples, the damage is counted, the session stays open and
        // tells the user what is wrong and what to do.
        QVERIFY(session.store().totalAppended() <= frozen + 1);
        QVERIFY(stats.last.bytesSkipped > 0 || stats.last.crcErrors > 0);
        QCOMPARE(session.state(), SessionState::Connected);
        // Said as a warning that lasts while the garbage does (the window shows it in the tab, not
        // as a modal), never as an error.
        QTRY_VERIFY_WITH_TIMEOUT(!warnings.isEmpty(), 5000);
        QVERIFY2(warnings.last().at(0).toString().contains(QLatin1String("baud"), Qt::CaseInsensitive),
                 qPrintable(warnings.last().at(0).toString()));
        QVERIFY(errors.isEmpty());
        // Following the device to its new rate brings the samples back, and withdraws the warning.
        session.setHostBaud(460800);
        QTRY_VERIFY_WITH_TIMEOUT(session.store().totalAppended() > frozen + 50, 5000);
        QTRY_COMPARE_WITH_TIMEOUT(warnings.last().at(0).toString(), QString(), 5000);
        QCOMPARE(warnings.size(), 2);
    }

    // A frame delivered in two pieces with a pause between them (a USB adapter's latency
    // timer, a loaded host): the session waits for the rest instead of giving the frame up.
    void frameSplitByAPause_data()
    {
        QTest::addColumn<int>("pauseMs");
        QTest::newRow("16 ms (FTDI latency timer)") << 16;
        QTest::newRow("60 ms (loaded host)") << 60;
    }
    void frameSplitByAPause()
    {
        QFETCH(int, pauseMs);
        RawPty pty;
        QVERIFY(pty.ok());
        DeviceSession session;
        StatsProbe stats(session);
        QVERIFY(test::openOnPty(session, pty));
        pty.drain();
        uint64_t written = 0;
        for (uint32_t i = 0; i < 20; ++i) {
            const auto f = hi91Frame(5000 + i);
            const size_t cut = 10 + 3 * i;
            pty.write(std::vector<uint8_t>(f.begin(), f.begin() + qsizetype(cut)));
            QTest::qWait(pauseMs); // duration under test: the pause inside the frame
            pty.write(std::vector<uint8_t>(f.begin() + qsizetype(cut), f.end()));
            written += f.size();
        }
        QTRY_COMPARE_WITH_TIMEOUT(session.store().totalAppended(), uint64_t(20), 5000);
        // Every byte written has been through the decoder: nothing more can come.
        QTRY_COMPARE_WITH_TIMEOUT(stats.last.bytesIn, written, 5000);
        QCOMPARE(session.store().totalAppended(), uint64_t(20));
        QCOMPARE(stats.last.crcErrors, uint64_t(0));
    }

    void stalledReaderLosesNothingAlreadyReceived()
    {
        sim::PtySimulator simulator(simOptions(921600));
        QVERIFY(simulator.start(nullptr));
        DeviceSession session;
        session.setAutoReconnect(false);
        StatsProbe stats(session);
        session.open(simulator.devicePath(), 921600);
        QVERIFY(waitState(session, SessionState::Connected));
        QTRY_VERIFY(session.store().totalAppended() > 100);
        // The owner's thread stops for 1.5 s (a modal dialog, a slow disk): the worker keeps
        // reading, so nothing is dropped at the pty and every frame is in the store after.
        QThread::msleep(1500);
        QCoreApplication::processEvents(); // what was queued during the stall
        stats.next(3000);                  // and stats made after it
        uint64_t dropped = 0;
        simulator.withDevice([&dropped](sim::HipnucSimulator &d) { dropped = d.droppedFrames(); });
        QCOMPARE(simulator.stats().chunksDropped, uint64_t(0));
        QCOMPARE(stats.last.framesLost, dropped);
        QCOMPARE(stats.last.crcErrors, uint64_t(0));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstFaultInjection)
#include "tst_fault_injection.moc"
