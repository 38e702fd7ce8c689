// RecordingControls offscreen against the simulator on a pseudo-terminal: record and stop,
// elapsed/size/frames, the file name pattern, a missing folder, and a recording stopped by a
// file size limit (the reason is shown and recordingFailed emitted).
#include "../common/capture_bytes.h"
#include "../common/raw_pty.h"
#include "../common/file_size_limit.h"
#include "../common/test_main.h"
#include "device/device_session.h"
#include "record/capture_exporter.h"
#include "capture/capture_reader.h"
#include "recording/recording_controls.h"
#include "sim/pty_simulator.h"

#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QFile>
#include <QSpinBox>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QTest>

#include <functional>


using namespace imudesk;
using ui::RecordingControls;

class TstRecordingControls : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    std::unique_ptr<sim::PtySimulator> m_sim;
    std::unique_ptr<device::DeviceSession> m_session;
    model::DeviceIdentity m_identity;

private Q_SLOTS:
    void initTestCase()
    {
        sim::SimOptions o;
        o.baud = 921600;
        m_sim = std::make_unique<sim::PtySimulator>(o);
        QString error;
        QVERIFY2(m_sim->start(&error), qPrintable(error));
        m_session = std::make_unique<device::DeviceSession>();
        QSignalSpy identity(m_session.get(), &device::DeviceSession::identityChanged);
        m_session->open(m_sim->devicePath(), 921600);
        QVERIFY(identity.wait(10000));
        m_identity = identity.at(0).at(0).value<model::DeviceIdentity>();
    }
    void cleanupTestCase()
    {
        m_session.reset();
        m_sim.reset();
    }

    void patternExpands_data()
    {
        QTest::addColumn<QString>("pattern");
        QTest::addColumn<QString>("expected");
        QTest::newRow("product") << "{product}.imucap" << "device.imucap";
        QTest::newRow("suffix added") << "run" << "run.imucap";
        QTest::newRow("no path escape, no hidden file") << "../x/y" << "_._x_y.imucap";
        QTest::newRow("date") << "{date}" << QDate::currentDate().toString(QStringLiteral("yyyyMMdd")) + ".imucap";
        QTest::newRow("MCAP kept") << "{product}.mcap" << "device.mcap";
    }
    void patternExpands()
    {
        QFETCH(QString, pattern);
        QFETCH(QString, expected);
        RecordingControls c;
        QCOMPARE(c.expandPattern(pattern), expected);
    }

    void recordAndStop()
    {
        RecordingControls c;
        c.setSession(m_session.get());
        c.setFolder(m_dir.path());
        c.setPattern(QStringLiteral("{product}-{serial}"));
        // The session was identified before the controls were attached.
        c.setIdentity(QString::fromStdString(m_identity.productName), QString::fromStdString(m_identity.serial));
        auto *record = c.findChild<QPushButton *>(QStringLiteral("record"));
        auto *stop = c.findChild<QPushButton *>(QStringLiteral("stop"));
        QVERIFY(record->isEnabled());
        QVERIFY(!stop->isEnabled());
        QSignalSpy started(&c, &RecordingControls::recordingStarted);
        QSignalSpy stopped(&c, &RecordingControls::recordingStopped);
        QTest::mouseClick(record, Qt::LeftButton);
        QVERIFY(started.wait(5000));
        QCOMPARE(started.at(0).at(0).toString(),
                 m_dir.filePath(QStringLiteral("HI14R3-%1.imucap").arg(QString::fromStdString(m_identity.serial))));
        QVERIFY(c.isRecording());
        QVERIFY(!record->isEnabled() && stop->isEnabled());
        QTRY_VERIFY_WITH_TIMEOUT(c.findChild<QLabel *>(QStringLiteral("frames"))->text().startsWith(QLatin1String("1")),
                                 3000);
        QTRY_COMPARE_WITH_TIMEOUT(c.findChild<QLabel *>(QStringLiteral("elapsed"))->text(), QStringLiteral("00:00:01"),
                                  3000);
        QTest::mouseClick(stop, Qt::LeftButton);
        QVERIFY(stopped.wait(5000));
        QVERIFY(!c.isRecording());
        capture::CaptureReader r;
        QString error;
        QVERIFY2(r.open(c.currentPath(), &error), qPrintable(error));
        capture::CaptureReader::Chunk chunk;
        QCOMPARE(r.next(chunk), capture::CaptureReader::Result::Chunk);
    }

    // "Stop after": the recording ends by itself after the seconds set, says so, and the field
    // is remembered for the next panel (0: until Stop).
    void stopsAfterTheDurationSet()
    {
        RecordingControls c;
        c.setSession(m_session.get());
        c.setFolder(m_dir.path());
        c.setPattern(QStringLiteral("{product}-timed"));
        auto *duration = c.findChild<QSpinBox *>(QStringLiteral("duration"));
        QVERIFY(duration);
        duration->setValue(2);
        QCOMPARE(RecordingControls().durationS(), 2); // remembered
        QSignalSpy started(&c, &RecordingControls::recordingStarted);
        QSignalSpy stopped(&c, &RecordingControls::recordingStopped);
        QElapsedTimer t;
        t.start();
        c.startRecording();
        QVERIFY(started.wait(5000));
        QVERIFY(!duration->isEnabled());
        QVERIFY(stopped.wait(10000)); // nobody pressed Stop
        const qint64 ms = t.elapsed();
        QVERIFY2(ms >= 1900, qPrintable(QString::number(ms)));
        QVERIFY(!c.isRecording());
        QVERIFY(duration->isEnabled());
        const QString message = c.findChild<QLabel *>(QStringLiteral("message"))->text();
        QVERIFY2(message.contains(QStringLiteral("stopped after 2 s")), qPrintable(message));
        QVERIFY(QFileInfo(c.currentPath()).size() > 0);
        c.setDurationS(0);
        QCOMPARE(RecordingControls().durationS(), 0);
    }

    // A pattern ending in .mcap records MCAP from the window: the file opens in the official
    // reader's format (magic first), the controls count its samples.
    void recordMcapFromTheWindow()
    {
        RecordingControls c;
        c.setSession(m_session.get());
        c.setFolder(m_dir.path());
        c.setPattern(QStringLiteral("{product}-live.mcap"));
        c.setIdentity(QString::fromStdString(m_identity.productName), QString::fromStdString(m_identity.serial));
        QSignalSpy started(&c, &RecordingControls::recordingStarted);
        QSignalSpy stopped(&c, &RecordingControls::recordingStopped);
        c.startRecording();
        QVERIFY(started.wait(5000));
        QCOMPARE(started.at(0).at(0).toString(), m_dir.filePath(QStringLiteral("HI14R3-live.mcap")));
        QTRY_VERIFY_WITH_TIMEOUT(c.findChild<QLabel *>(QStringLiteral("frames"))->text().startsWith(QLatin1String("1")), 3000);
        c.stopRecording();
        QVERIFY(stopped.wait(5000));
        QFile f(c.currentPath());
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray all = f.readAll();
        QVERIFY(all.startsWith(QByteArray("\x89MCAP0\r\n", 8)));
        QVERIFY(all.endsWith(QByteArray("\x89MCAP0\r\n", 8))); // closed: summary and footer written
    }

    void missingFolderIsReported()
    {
        RecordingControls c;
        c.setSession(m_session.get());
        c.setFolder(m_dir.filePath(QStringLiteral("no/such")));
        QSignalSpy started(&c, &RecordingControls::recordingStarted);
        c.startRecording();
        QVERIFY(c.findChild<QLabel *>(QStringLiteral("message"))->text().contains(QStringLiteral("does not exist")));
        QTest::qWait(200); // duration under test: no recording starts later either
        QCOMPARE(started.size(), 0);
    }

    void fullDiskStopsWithMessage()
    {
        RecordingControls c;
        c.setSession(m_session.get());
        c.setFolder(m_dir.path());
        c.setPattern(QStringLiteral("limited"));
        QSignalSpy failed(&c, &RecordingControls::recordingFailed);
        QSignalSpy stopped(&c, &RecordingControls::recordingStopped);
        imudesk::test::FileSizeLimit disk(4096);
        QVERIFY(disk.ok());
        c.startRecording();
        const bool sawFailure = failed.wait(10000);
        disk.lift();
        QVERIFY(sawFailure);
        QVERIFY2(failed.at(0).at(0).toString().contains(QStringLiteral("Recording stopped")), qPrintable(failed.at(0).at(0).toString()));
        QCOMPARE(c.findChild<QLabel *>(QStringLiteral("message"))->text(), failed.at(0).at(0).toString());
        QCOMPARE(stopped.size(), 1);
        QVERIFY(!c.isRecording());
        QVERIFY(c.findChild<QPushButton *>(QStringLiteral("record"))->isEnabled());
    }

    // A frame that began before Record was pressed: the session decodes it, but the file holds
    // only its tail. The frames the panel counts are the frames the file holds, the ones an
    // export writes (it counted one more: 2092 recorded, 2091 exported).
    void countsTheFramesTheFileHolds()
    {
        test::RawPty pty;
        QVERIFY(pty.ok());
        device::DeviceSession session;
        QVERIFY(test::openOnPty(session, pty));
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        RecordingControls c;
        c.setSession(&session);
        c.setFolder(dir.path());
        const auto received = [&session] {
            size_t n = 0;
            for (const auto &chunk : session.rawLog().since(0))
                if (chunk.direction == device::RawByteLog::Direction::Rx)
                    n += size_t(chunk.bytes.size());
            return n;
        };
        // The session drops a frame's first bytes after HipnucSerialFamily::kLineIdleMs (120 ms)
        // of silence, so the rest must follow sooner: qWaitFor polls every 10 ms, within a bound, and
        // tries again when a loaded machine took too long (the session then did not decode the
        // straddling frame either, and the counts would agree for another reason).
        uint32_t ms = 1000;
        size_t sent = 0;
        for (int attempt = 0; attempt < 5; ++attempt) {
            // 20 frames, then the first 30 bytes of the 21st, read by the session before Record.
            std::vector<uint8_t> before;
            for (int i = 0; i < 20; ++i) {
                const auto f = test::hi91Frame(ms++);
                before.insert(before.end(), f.begin(), f.end());
            }
            const auto straddling = test::hi91Frame(ms++);
            before.insert(before.end(), straddling.begin(), straddling.begin() + 30);
            QTRY_COMPARE_WITH_TIMEOUT(received(), sent, 5000); // the previous attempt's bytes all read
            const uint64_t samplesBefore = session.store().totalAppended();
            pty.write(before);
            sent += before.size();
            QVERIFY(imudesk::test::waitFor([&] { return received() == sent; }, 5000));
            QSignalSpy started(&session, &device::Session::recordingStarted);
            QSignalSpy progress(&session, &device::Session::recordingProgress);
            c.setPattern(QStringLiteral("straddle-%1").arg(attempt));
            c.startRecording();
            QVERIFY(started.wait(5000));
            // The rest of the 21st frame, then 10 whole ones.
            std::vector<uint8_t> after(straddling.begin() + 30, straddling.end());
            for (int i = 0; i < 10; ++i) {
                const auto f = test::hi91Frame(ms++);
                after.insert(after.end(), f.begin(), f.end());
            }
            pty.write(after);
            sent += after.size();
            QTRY_COMPARE_WITH_TIMEOUT(received(), sent, 5000);
            QTRY_VERIFY_WITH_TIMEOUT(session.store().totalAppended() >= samplesBefore + 30, 5000);
            c.stopRecording();
            QTRY_VERIFY_WITH_TIMEOUT(!c.isRecording(), 5000);
            if (session.store().totalAppended() != samplesBefore + 31) {
                qInfo("attempt %d: the straddling frame's first bytes were dropped as idle; again", attempt);
                continue;
            }
            // 31 frames decoded by the session, 11 of them after Record was pressed.
            QVERIFY(!progress.isEmpty());
            const quint64 recorded = progress.last().at(1).toULongLong();

            // The file, byte for byte, and what an export writes from it: 10 whole frames.
            const QString path = dir.filePath(QStringLiteral("straddle-%1.imucap").arg(attempt));
            const QByteArray bytes = test::receivedBytes(path);
            QCOMPARE(size_t(bytes.size()), after.size());
            protocol::hipnuc::FrameDecoder decoder;
            QCOMPARE(decoder.feed(reinterpret_cast<const uint8_t *>(bytes.constData()), size_t(bytes.size())).size(),
                     size_t(10));
            record::CaptureExporter::Options o;
            o.format = record::CaptureExporter::Format::JsonLines;
            o.output = dir.filePath(QStringLiteral("straddle.jsonl"));
            const auto exported = record::CaptureExporter::run(path, o);
            QVERIFY2(exported.ok, qPrintable(exported.error));
            QCOMPARE(exported.frames, uint64_t(10));
            QCOMPARE(recorded, quint64(10));
            const QString shown = c.findChild<QLabel *>(QStringLiteral("frames"))->text();
            QVERIFY2(shown.startsWith(QStringLiteral("10 ")), qPrintable(shown));
            return;
        }
        QFAIL("the straddling frame was never decoded whole by the session");
    }

    void withoutSessionDisabled()
    {
        RecordingControls c;
        QVERIFY(!c.findChild<QPushButton *>(QStringLiteral("record"))->isEnabled());
        QVERIFY(!c.findChild<QPushButton *>(QStringLiteral("stop"))->isEnabled());
    }
};

IMUDESK_TEST_MAIN(TstRecordingControls)
#include "tst_recording_controls.moc"
