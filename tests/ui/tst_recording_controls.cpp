// RecordingControls offscreen against the simulator on a pseudo-terminal: record and stop,
// elapsed/size/frames, the file name pattern, a missing folder, and a recording stopped by a
// file size limit (the reason is shown and recordingFailed emitted).
#include "device/device_session.h"
#include "record/capture_reader.h"
#include "recording/recording_controls.h"
#include "sim/pty_simulator.h"

#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>

#include <sys/resource.h>

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
        record::CaptureReader r;
        QString error;
        QVERIFY2(r.open(c.currentPath(), &error), qPrintable(error));
        record::CaptureReader::Chunk chunk;
        QCOMPARE(r.next(chunk), record::CaptureReader::Result::Chunk);
    }

    void missingFolderIsReported()
    {
        RecordingControls c;
        c.setSession(m_session.get());
        c.setFolder(m_dir.filePath(QStringLiteral("no/such")));
        QSignalSpy started(&c, &RecordingControls::recordingStarted);
        c.startRecording();
        QVERIFY(c.findChild<QLabel *>(QStringLiteral("message"))->text().contains(QStringLiteral("does not exist")));
        QTest::qWait(200);
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
        rlimit before{};
        getrlimit(RLIMIT_FSIZE, &before);
        const auto old = std::signal(SIGXFSZ, SIG_IGN);
        rlimit limited = before;
        limited.rlim_cur = 4096;
        setrlimit(RLIMIT_FSIZE, &limited);
        c.startRecording();
        const bool sawFailure = failed.wait(10000);
        setrlimit(RLIMIT_FSIZE, &before);
        std::signal(SIGXFSZ, old);
        QVERIFY(sawFailure);
        QVERIFY(failed.at(0).at(0).toString().contains(QStringLiteral("Recording stopped")));
        QCOMPARE(c.findChild<QLabel *>(QStringLiteral("message"))->text(), failed.at(0).at(0).toString());
        QCOMPARE(stopped.size(), 1);
        QVERIFY(!c.isRecording());
        QVERIFY(c.findChild<QPushButton *>(QStringLiteral("record"))->isEnabled());
    }

    void withoutSessionDisabled()
    {
        RecordingControls c;
        QVERIFY(!c.findChild<QPushButton *>(QStringLiteral("record"))->isEnabled());
        QVERIFY(!c.findChild<QPushButton *>(QStringLiteral("stop"))->isEnabled());
    }
};

QTEST_MAIN(TstRecordingControls)
#include "tst_recording_controls.moc"
