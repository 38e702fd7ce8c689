// Recording outside the session engine (issue 54 point 2, record/mcap_recorder.h): an MCAP file of
// one device or several, fed through each device's tap and written by a thread of its own. The
// file is read back (format/mcap/mcap_repair.h reads every record and counts the messages); a
// queue that is full counts what it could not take; a tap may outlive its recorder (a session
// lets go of it later, in its own thread); a disk that fails stops the recording and says so once.
#include "record/mcap_recorder.h"
#include "record/recording.h"
#include "format/mcap/mcap_repair.h"
#include "../common/file_size_limit.h"
#include "../common/test_main.h"

#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>

#include <atomic>


using namespace imudesk;
using record::McapRecorder;

namespace {

capture::CaptureHeader headerOf(const std::string &serial)
{
    model::DeviceIdentity id;
    id.productName = "HI14R3";
    id.serial = serial;
    capture::CaptureHeader h;
    h.setIdentity(id);
    h.set(capture::CaptureHeader::kLinkKind, "HiPNUC serial");
    h.set(capture::CaptureHeader::kPort, "/dev/pts/9");
    return h;
}

// n samples of acceleration and angular rate, 1 ms apart from t0.
std::vector<model::Sample> batchOf(size_t n, int64_t t0Ns)
{
    std::vector<model::Sample> out(n);
    for (size_t i = 0; i < n; ++i) {
        model::Sample &s = out[i];
        s.fields = model::FieldAcc | model::FieldGyr;
        s.hostTimeNs = t0Ns + int64_t(i) * 1'000'000;
        s.commonTimeNs = s.hostTimeNs;
        s.acc = {0.0, 0.0, 1.0};
        s.gyr = {0.1 * double(i), 0.0, 0.0};
    }
    return out;
}

// Messages in a finished file, read back record by record (empty optional: not a whole file).
std::optional<uint64_t> messagesIn(const QString &path, const QString &scratch)
{
    const format::mcap::RepairResult r = format::mcap::repairMcap(path, scratch);
    if (!r.ok || !r.wasComplete || r.bytesLeftOut != 0)
        return std::nullopt;
    return r.messages;
}

} // namespace

class TstMcapRecorder : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void twoDevicesThroughTheirTaps()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("two.mcap"));
        McapRecorder rec;
        QString error;
        QVERIFY2(rec.start(path, {{headerOf("A1"), {}}, {headerOf("B2"), {}}}, &error), qPrintable(error));
        auto a = rec.tap(0), b = rec.tap(1);
        QVERIFY(a->begin(headerOf("ignored"), &error));
        QVERIFY(b->begin(headerOf("ignored"), &error));
        for (int k = 0; k < 10; ++k) {
            a->samples(batchOf(50, k * 50'000'000));
            b->samples(batchOf(30, k * 50'000'000));
        }
        QCOMPARE(rec.stop(), QString());
        QCOMPARE(rec.samples(), (std::vector<uint64_t>{500, 300}));
        QCOMPARE(rec.missed(), uint64_t(0));
        QCOMPARE(a->progress().frames, uint64_t(500));
        QCOMPARE(b->progress().frames, uint64_t(300));
        QVERIFY(a->progress().bytesWritten > 0);
        const auto messages = messagesIn(path, dir.filePath(QStringLiteral("read.mcap")));
        QVERIFY(messages);
        // Each sample of acceleration and rate is one Imu message at least.
        QVERIFY2(*messages >= 800, qPrintable(QString::number(*messages)));
        // Twice the samples again: the count of messages follows them, so none was dropped.
        QTemporaryDir dir2;
        const QString path2 = dir2.filePath(QStringLiteral("two.mcap"));
        McapRecorder rec2;
        QVERIFY(rec2.start(path2, {{headerOf("A1"), {}}, {headerOf("B2"), {}}}, &error));
        for (int k = 0; k < 20; ++k) {
            rec2.append(0, batchOf(50, k * 50'000'000));
            rec2.append(1, batchOf(30, k * 50'000'000));
        }
        QCOMPARE(rec2.stop(), QString());
        const auto messages2 = messagesIn(path2, dir2.filePath(QStringLiteral("read.mcap")));
        QVERIFY(messages2);
        QCOMPARE(*messages2, 2 * *messages);
    }

    void aFullQueueCountsWhatItCouldNotTake()
    {
        QTemporaryDir dir;
        McapRecorder rec;
        QString error;
        QVERIFY(rec.start(dir.filePath(QStringLiteral("full.mcap")), {{headerOf("A1"), {}}}, &error));
        rec.append(0, batchOf(McapRecorder::kQueueSamples + 7, 0)); // one hand-over: the queue takes what fits
        QCOMPARE(rec.missed(), uint64_t(7));
        QCOMPARE(rec.stop(), QString());
        QCOMPARE(rec.samples(), std::vector<uint64_t>{McapRecorder::kQueueSamples});
    }

    void anEndedTapTakesNothingAndATapOutlivesItsRecorder()
    {
        QTemporaryDir dir;
        std::shared_ptr<device::StreamTap> tap;
        QString error;
        {
            McapRecorder rec;
            QVERIFY(rec.start(dir.filePath(QStringLiteral("one.mcap")), {{headerOf("A1"), {}}}, &error));
            tap = rec.tap(0);
            QVERIFY(tap->begin(headerOf("A1"), &error));
            tap->samples(batchOf(20, 0));
            QCOMPARE(tap->end(), QString());
            tap->samples(batchOf(20, 100'000'000)); // after end(): not recorded
            QCOMPARE(rec.stop(), QString());
            QCOMPARE(rec.samples(), std::vector<uint64_t>{20});
        }
        // The recorder is gone; its session may still hand the tap samples and end it.
        QVERIFY(tap->begin(headerOf("A1"), &error));
        tap->samples(batchOf(20, 200'000'000));
        QCOMPARE(tap->progress().frames, uint64_t(20));
        QCOMPARE(tap->end(), QString());
    }

    void oneDeviceByItsFileName()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("single.mcap"));
        const auto tap = record::recordingFor(path);
        QVERIFY(dynamic_cast<record::McapTap *>(tap.get()));
        QVERIFY(dynamic_cast<record::CaptureTap *>(record::recordingFor(dir.filePath(QStringLiteral("x.imucap"))).get()));
        QString error;
        QVERIFY2(tap->begin(headerOf("A1"), &error), qPrintable(error));
        tap->samples(batchOf(250, 0));
        QCOMPARE(tap->end(), QString());
        QCOMPARE(tap->progress().frames, uint64_t(250));
        const auto messages = messagesIn(path, dir.filePath(QStringLiteral("read.mcap")));
        QVERIFY(messages);
        QVERIFY2(*messages >= 250, qPrintable(QString::number(*messages)));
    }

    void aFullDiskStopsTheRecordingAndSaysSoOnce()
    {
        // A real file on a "disk" of 64 KiB: RLIMIT_FSIZE makes write() fail with EFBIG once the
        // file's start and its first chunks are written. (/dev/full refuses the start at once:
        // begin() says "No space left on device".)
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("limited.mcap"));
        imudesk::test::FileSizeLimit disk(64 * 1024);
        QVERIFY(disk.ok());
        std::atomic<int> told{0};
        QString reason, error;
        bool started = false;
        {
            record::McapTap tap(path);
            tap.setStoppedHandler([&](const QString &why) {
                reason = why;
                ++told;
            });
            started = tap.begin(headerOf("A1"), &error);
            for (int k = 0; started && k < 100 && told.load() == 0; ++k) {
                tap.samples(batchOf(1000, int64_t(k) * 1'000'000'000));
                // Written, or the disk refused it: the next batch meets an empty queue.
                const uint64_t fed = uint64_t(k + 1) * 1000;
                QTRY_VERIFY_WITH_TIMEOUT(told.load() > 0 || tap.progress().frames >= fed, 5000);
            }
            imudesk::test::waitFor([&] { return told.load() > 0; }, 5000);
            tap.samples(batchOf(10, 0)); // after the failure: dropped
            if (started)
                error = tap.end();
        }
        disk.lift();
        QVERIFY2(started, qPrintable(error));
        QCOMPARE(told.load(), 1);
        QVERIFY2(reason.contains(path) && reason.contains(QLatin1String("disk space")), qPrintable(reason));
        QCOMPARE(error, reason); // end() says the same
        // What was written before the disk filled is there: the file is cut, not lost.
        QVERIFY(QFileInfo(path).size() > 0);
    }
};

IMUDESK_TEST_MAIN(TstMcapRecorder)
#include "tst_mcap_recorder.moc"
