// imudesk-cli update --can end to end over Qt's virtualcan bus: `imudesk-cli simulate --can ...
// --protocol canopen --flash-dump F` serves the simulated HiPNUC CANopen module (with its CAN
// bootloader) in one process, `imudesk-cli update --can ...` updates it from another. Happy path
// (the dump equals the image), a bad HEX refused before any frame reaches the bus, cancel (SIGINT)
// mid-download and a second run that finishes the update. This executable uses its own virtualcan
// TCP port; the simulator process owns the plugin's server.
#include "../common/cli_process.h"
#include "../common/cli_run.h"
#include "../common/firmware_files.h"
#include "../common/test_main.h"
#include "protocol/can/can_frame.h"
#include "protocol/ihex/firmware_image.h"
#include "protocol/ihex/intel_hex_writer.h"
#include "sim/kboot_bootloader.h"

#include <QCanBus>
#include <QCanBusDevice>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>
#include <memory>

using namespace imudesk;
using protocol::ihex::FirmwareImage;
using protocol::ihex::IntelHexWriter;

namespace {

constexpr int kPort = 24491;
constexpr uint32_t kAppStart = 0x8000;
constexpr uint32_t kFlashSize = 512 * 1024;

using imudesk::test::resultLine;
using imudesk::test::writeFile;

FirmwareImage image(const std::string &version, size_t size, uint64_t seed = 21)
{
    return imudesk::test::appImage(version, size, seed, kAppStart);
}

} // namespace

class TstCanFirmwareUpdate : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QProcess m_sim;
    QString m_bus;

    bool startSim(const QString &dump)
    {
        m_bus = QStringLiteral("virtualcan:tcp://127.0.0.1:%1/can0").arg(kPort);
        QStringList args{QStringLiteral("simulate"), QStringLiteral("--can"), m_bus, QStringLiteral("--protocol"),
                         QStringLiteral("canopen")};
        if (!dump.isEmpty())
            args << QStringLiteral("--flash-dump") << dump;
        return imudesk::test::startCliUntil(m_sim, args, "can: ");
    }
    void stopSim() { imudesk::test::stopCli(m_sim); }
    QStringList update(const QString &hex, const QStringList &extra = {}) const
    {
        return QStringList{QStringLiteral("update"), QStringLiteral("--can"), m_bus, QStringLiteral("--node"),
                           QStringLiteral("8"), hex} + extra;
    }

private Q_SLOTS:
    void initTestCase()
    {
        if (!QCanBus::instance()->plugins().contains(QStringLiteral("virtualcan")))
            QSKIP("Qt's virtualcan CAN bus plugin is not installed (package libqt6serialbus6-plugins)");
        QVERIFY(m_dir.isValid());
    }
    void cleanup() { stopSim(); }

    void happyPathFlashDump()
    {
        const QString dump = m_dir.filePath(QStringLiteral("can-flash.bin"));
        QVERIFY(startSim(dump));
        const auto img = image("1.7.2", 3000 + 5);
        const QString hex = writeFile(m_dir, QStringLiteral("can172.hex"), IntelHexWriter::write(img));
        const auto r = imudesk::test::runCli(update(hex, {QStringLiteral("--json"), QStringLiteral("--flash-layout"),
                                                          QStringLiteral("0:0x80000:0x8000")}),
                                             120000);
        QVERIFY2(r.code == 0, qPrintable(r.err + r.out));
        const QJsonObject res = resultLine(r.out);
        QCOMPARE(res.value(QStringLiteral("ok")).toBool(), true);
        QCOMPARE(res.value(QStringLiteral("verified")).toString(), QStringLiteral("bootloader CRC"));
        QCOMPARE(res.value(QStringLiteral("firmware_before")).toString(), QStringLiteral("1.7.1"));
        QCOMPARE(res.value(QStringLiteral("firmware_after")).toString(), QStringLiteral("1.7.2"));
        QVERIFY2(r.out.contains(QStringLiteral("\"event\":\"progress\"")), qPrintable(r.out));
        stopSim();
        QFile f(dump);
        QVERIFY2(f.open(QIODevice::ReadOnly), qPrintable(dump));
        const QByteArray area = f.readAll();
        QCOMPARE(qsizetype(area.size()), qsizetype(kFlashSize - kAppStart));
        QVERIFY(std::equal(img.data.begin(), img.data.end(), reinterpret_cast<const uint8_t *>(area.constData())));
        QVERIFY(std::all_of(area.begin() + qsizetype(img.size()), area.end(), [](char c) { return uint8_t(c) == 0xFF; }));
    }

    void badHexRefusedBeforeAnyFrame()
    {
        QVERIFY(startSim({}));
        // A listener on the same bus counts what is sent to the module's SDO server.
        QString err;
        std::unique_ptr<QCanBusDevice> ear(QCanBus::instance()->createDevice(
            QStringLiteral("virtualcan"), QStringLiteral("tcp://127.0.0.1:%1/can0").arg(kPort), &err));
        QVERIFY2(ear && ear->connectDevice(), qPrintable(err));
        QTRY_COMPARE_WITH_TIMEOUT(int(ear->state()), int(QCanBusDevice::ConnectedState), 5000);
        int requests = 0;
        QObject ctx;
        connect(ear.get(), &QCanBusDevice::framesReceived, &ctx, [&] {
            while (ear->framesAvailable())
                requests += ear->readFrame().frameId() == 0x608 ? 1 : 0;
        });
        std::string hex = IntelHexWriter::write(image("1.7.3", 512));
        const size_t line2 = hex.find('\n') + 1;
        hex[line2 + 9] = hex[line2 + 9] == 'A' ? 'B' : 'A';
        const auto r = imudesk::test::runCli(update(writeFile(m_dir, QStringLiteral("bad.hex"), hex)), 30000);
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("checksum")) && r.err.contains(QStringLiteral("nothing was sent")),
                 qPrintable(r.err));
        // Frames cross virtualcan within milliseconds: after 300 ms none has reached the module.
        QTest::qWait(300); // duration under test: no request reaches the module within 300 ms
        QCOMPARE(requests, 0);
        // The listener does hear an update's requests (the check above can fail).
        const auto good = imudesk::test::runCli(update(writeFile(m_dir, QStringLiteral("good.hex"),
                                                                 IntelHexWriter::write(image("1.7.3", 64)))),
                                                60000);
        QVERIFY2(good.code == 0, qPrintable(good.err));
        QTRY_VERIFY_WITH_TIMEOUT(requests > 0, 3000);
    }

    void cancelMidDownloadThenFinish()
    {
        QVERIFY(startSim({}));
        const auto img = image("1.7.4", 40 * 1024);
        const QString hex = writeFile(m_dir, QStringLiteral("can174.hex"), IntelHexWriter::write(img));
        QProcess p;
        p.start(QString::fromUtf8(IMUDESK_CLI_PATH), update(hex, {QStringLiteral("--json")}));
        QVERIFY(p.waitForStarted());
        bool downloading = false;
        QTRY_VERIFY_WITH_TIMEOUT(([&] {
                                     while (p.canReadLine()) {
                                         const auto o = QJsonDocument::fromJson(p.readLine()).object();
                                         if (o.value("event").toString() == QStringLiteral("progress")
                                             && o.value("done").toInteger() > 1024)
                                             downloading = true;
                                     }
                                     return downloading;
                                 }()),
                                 60000);
        ::kill(pid_t(p.processId()), SIGINT);
        QVERIFY(p.waitForFinished(20000));
        QCOMPARE(p.exitCode(), 130);
        const QString rest = QString::fromUtf8(p.readAllStandardOutput());
        const QJsonObject cancelled = resultLine(rest);
        QCOMPARE(cancelled.value(QStringLiteral("state")).toString(), QStringLiteral("cancelled"));
        QVERIFY2(cancelled.value(QStringLiteral("message")).toString().contains(QStringLiteral("run the update again")),
                 qPrintable(rest));
        const auto again = imudesk::test::runCli(update(hex, {QStringLiteral("--json")}), 120000);
        QVERIFY2(again.code == 0, qPrintable(again.err + again.out));
        const QJsonObject res = resultLine(again.out);
        QCOMPARE(res.value(QStringLiteral("resumed")).toBool(), true);
        QCOMPARE(res.value(QStringLiteral("firmware_after")).toString(), QStringLiteral("1.7.4"));
    }

    void usageErrors()
    {
        QCOMPARE(imudesk::test::runCli({QStringLiteral("update"), QStringLiteral("--can"), QStringLiteral("virtualcan"),
                                        QStringLiteral("x.hex")})
                     .code,
                 2);
        QCOMPARE(imudesk::test::runCli({QStringLiteral("update"), QStringLiteral("--can"), QStringLiteral("virtualcan:can0"),
                                        QStringLiteral("--node"), QStringLiteral("200"), QStringLiteral("x.hex")})
                     .code,
                 2);
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstCanFirmwareUpdate)
#include "tst_can_firmware_update.moc"
