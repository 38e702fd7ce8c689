// The cable pulled at the worst moments: in the middle of a frame, while a command waits
// for its reply, and while recording. The test plays the device on a pseudo-terminal and
// closes it (the slave side sees the hang-up an unplugged USB adapter gives). In every case:
// no crash, the owner thread's event loop keeps turning, the session says what happened, and
// every byte that arrived before the cable went is kept (samples in the store, bytes in the
// capture file).
#include "../common/raw_pty.h"
#include "../common/test_main.h"
#include "device/device_session.h"
#include "protocol/hipnuc/frame_decoder.h"
#include "capture/capture_reader.h"
#include "record/recording.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace imudesk;
using device::DeviceSession;
using device::SessionState;
using protocol::hipnuc::AsciiReply;
using test::hi91Frame;
using test::kSanitized;
using test::RawPty;
using test::StallWatch;

namespace {

// n whole frames, then the first `partial` bytes of one more.
std::vector<uint8_t> framesThenPart(uint32_t n, size_t partial)
{
    std::vector<uint8_t> out;
    for (uint32_t i = 0; i < n; ++i) {
        const auto f = hi91Frame(1000 + i);
        out.insert(out.end(), f.begin(), f.end());
    }
    const auto last = hi91Frame(1000 + n);
    out.insert(out.end(), last.begin(), last.begin() + qsizetype(std::min(partial, last.size())));
    return out;
}

// Bytes the session has received so far (its raw-byte log, device to host).
size_t bytesReceived(DeviceSession &session)
{
    size_t n = 0;
    for (const auto &c : session.rawLog().since(0))
        if (c.direction == device::RawByteLog::Direction::Rx)
            n += size_t(c.bytes.size());
    return n;
}

void checkStalls(const StallWatch &stalls, const char *what)
{
    qInfo("%s: worst stall of the owner thread %lld ms", what, stalls.worstMs());
    if (!kSanitized)
        QVERIFY2(stalls.worstMs() < 100, qPrintable(QString::number(stalls.worstMs())));
}

} // namespace

class TstCablePulled : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void midFrame_data()
    {
        QTest::addColumn<int>("partial");
        QTest::newRow("after the sync bytes") << 2;
        QTest::newRow("inside the header") << 5;
        QTest::newRow("inside the payload") << 40;
        QTest::newRow("one byte short") << int(protocol::hipnuc::Hi91::kSize) + 5;
    }
    void midFrame()
    {
        QFETCH(int, partial);
        RawPty pty;
        QVERIFY(pty.ok());
        DeviceSession session;
        QSignalSpy errors(&session, &DeviceSession::errorOccurred);
        QVERIFY(test::openOnPty(session, pty));
        StallWatch stalls;
        pty.write(framesThenPart(300, size_t(partial)));
        QTRY_COMPARE_WITH_TIMEOUT(session.store().totalAppended(), uint64_t(300), 5000);
        pty.pull();
        QTRY_COMPARE_WITH_TIMEOUT(session.state(), SessionState::Disconnected, 5000);
        // Said, with what to do; every whole frame kept, the cut one not made into a sample.
        QVERIFY(!errors.isEmpty());
        QVERIFY2(errors.last().at(0).toString().contains(QLatin1String("lost"), Qt::CaseInsensitive),
                 qPrintable(errors.last().at(0).toString()));
        QTest::qWait(200); // duration under test: nothing more turns up after the hang-up
        QCOMPARE(session.store().totalAppended(), uint64_t(300));
        QCOMPARE(session.store().latest()->deviceTimeMs, 1000.0 + 299);
        checkStalls(stalls, "mid-frame");
    }

    void midCommand()
    {
        RawPty pty;
        QVERIFY(pty.ok());
        DeviceSession session;
        QVERIFY(test::openOnPty(session, pty));
        const auto frames = framesThenPart(50, 0);
        pty.write(frames);
        QTRY_COMPARE_WITH_TIMEOUT(session.store().totalAppended(), uint64_t(50), 5000);
        StallWatch stalls;
        QSignalSpy finished(&session, &DeviceSession::commandFinished);
        const quint64 id = session.sendText(QStringLiteral("LOG VERSION"), 5000);
        // The command reaches the "device", which starts to answer, then the cable goes.
        std::string sent;
        QTRY_VERIFY_WITH_TIMEOUT((sent += pty.readAvailable()).find("LOG VERSION") != std::string::npos, 3000);
        const std::string half = "LOG VERSION\r\nMODEL=HI14R3\r\nVERS";
        pty.write(std::vector<uint8_t>(half.begin(), half.end()));
        QTRY_COMPARE_WITH_TIMEOUT(bytesReceived(session), frames.size() + half.size(), 3000); // the half reply is in
        QElapsedTimer clock;
        clock.start();
        pty.pull();
        // The command ends at once (not after its 5 s timeout) and says the link is gone.
        QTRY_VERIFY_WITH_TIMEOUT(!finished.isEmpty(), 3000);
        QVERIFY2(clock.elapsed() < 3000, qPrintable(QString::number(clock.elapsed())));
        QCOMPARE(finished.first().at(0).toULongLong(), id);
        const auto reply = finished.first().at(1).value<AsciiReply>();
        QCOMPARE(reply.status, AsciiReply::Status::NotSent);
        QVERIFY(!reply.errorLine.empty());
        QTRY_COMPARE_WITH_TIMEOUT(session.state(), SessionState::Disconnected, 5000);
        QCOMPARE(session.store().totalAppended(), uint64_t(50));
        // A command sent now is refused at once, not queued for a device that is not there.
        QSignalSpy later(&session, &DeviceSession::commandFinished);
        session.sendText(QStringLiteral("LOG VERSION"), 5000);
        QTRY_VERIFY_WITH_TIMEOUT(!later.isEmpty(), 1000);
        QCOMPARE(later.first().at(1).value<AsciiReply>().status, AsciiReply::Status::NotSent);
        checkStalls(stalls, "mid-command");
    }

    void midRecording()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("pulled.imucap"));
        RawPty pty;
        QVERIFY(pty.ok());
        DeviceSession session;
        QVERIFY(test::openOnPty(session, pty));
        QSignalSpy started(&session, &DeviceSession::recordingStarted);
        QSignalSpy stopped(&session, &DeviceSession::recordingStopped);
        record::startRecording(session, path);
        QTRY_VERIFY_WITH_TIMEOUT(!started.isEmpty(), 3000);
        StallWatch stalls;
        // 2000 frames in bursts, then half a frame, then the cable goes.
        std::vector<uint8_t> all;
        for (uint32_t burst = 0; burst < 10; ++burst) {
            std::vector<uint8_t> b;
            for (uint32_t i = 0; i < 200; ++i) {
                const auto f = hi91Frame(1000 + burst * 200 + i);
                b.insert(b.end(), f.begin(), f.end());
            }
            pty.write(b);
            all.insert(all.end(), b.begin(), b.end());
            QTest::qWait(5); // duration under test: a 5 ms gap between bursts (separate reads and chunks)
        }
        const auto cut = hi91Frame(3000);
        const std::vector<uint8_t> part(cut.begin(), cut.begin() + 30);
        pty.write(part);
        all.insert(all.end(), part.begin(), part.end());
        QTRY_COMPARE_WITH_TIMEOUT(session.store().totalAppended(), uint64_t(2000), 5000);
        QTRY_COMPARE_WITH_TIMEOUT(bytesReceived(session), all.size(), 5000); // the cut frame's bytes too
        pty.pull();
        QTRY_COMPARE_WITH_TIMEOUT(session.state(), SessionState::Disconnected, 5000);
        session.stopRecording();
        QTRY_VERIFY_WITH_TIMEOUT(!stopped.isEmpty(), 5000);
        checkStalls(stalls, "mid-recording");

        // The file is whole: its received chunks are, byte for byte, what the device sent.
        capture::CaptureReader reader;
        QString error;
        QVERIFY2(reader.open(path, &error), qPrintable(error));
        std::vector<uint8_t> received;
        capture::CaptureReader::Chunk c;
        capture::CaptureReader::Result r;
        while ((r = reader.next(c)) == capture::CaptureReader::Result::Chunk)
            if (c.kind == capture::ChunkReceived)
                received.insert(received.end(), c.data, c.data + c.size);
        QCOMPARE(int(r), int(capture::CaptureReader::Result::End));
        QCOMPARE(reader.damagedChunks(), uint64_t(0));
        QCOMPARE(received.size(), all.size());
        QVERIFY(received == all);
        // And it decodes to the 2000 frames (the cut one is not a frame).
        protocol::hipnuc::FrameDecoder decoder;
        QCOMPARE(decoder.feed(received.data(), received.size()).size(), size_t(2000));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstCablePulled)
#include "tst_cable_pulled.moc"
